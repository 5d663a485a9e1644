// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Test and benchmark helper: the smallest det ∇ of an elastic transform's elastic part, sampled on
// n³ cell centres of a box given in the transform's frame coordinates (each sample is mapped back to
// input space through the transform's similarity, whose determinant is divided out).
#pragma once

#include "mmrepElasticTransform.h"

#include <Eigen/LU>

#include <algorithm>
#include <limits>

namespace mmrep::testing
{

inline double MinimumJacobianDeterminant(const ElasticTransform& t, const Eigen::Vector3d& frameLo,
                                         const Eigen::Vector3d& frameHi, int n)
{
  const Eigen::Matrix3d preInverse = t.preLinear.inverse();
  const double preDet = t.preLinear.determinant();
  double minDet = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
      {
        const Eigen::Vector3d u((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n);
        const Eigen::Vector3d x =
          preInverse * (t.ToWorld(frameLo + (frameHi - frameLo).cwiseProduct(u)) - t.preTranslation);
        minDet = std::min(minDet, t.Jacobian(x).determinant() / preDet);
      }
  return minDet;
}

// Over the box of the transform's finest grid level.
inline double MinimumJacobianDeterminantOverGrid(const ElasticTransform& t, int n)
{
  const auto& level = t.levels.back();
  return MinimumJacobianDeterminant(t, level.boxMin, level.boxMin + level.h * level.cells, n);
}

} // namespace mmrep::testing
