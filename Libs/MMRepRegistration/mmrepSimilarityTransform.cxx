// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Paired-point alignment: input checks here, the closed-form solution is Eigen's umeyama().
#include "mmrepSimilarityTransform.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mmrep
{

SimilarityTransform SimilarityTransform::Inverse() const
{
  SimilarityTransform inv;
  inv.rotation = rotation.transpose();
  inv.scale = 1.0 / scale;
  inv.translation = -(inv.scale * (inv.rotation * translation));
  return inv;
}

Eigen::Matrix4d SimilarityTransform::Matrix() const
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = Linear();
  m.topRightCorner<3, 1>() = translation;
  return m;
}

SimilarityTransform SimilarityTransform::Compose(const SimilarityTransform& first) const
{
  SimilarityTransform c;
  c.rotation = rotation * first.rotation;
  c.scale = scale * first.scale;
  c.translation = scale * (rotation * first.translation) + translation;
  return c;
}

double SimilarityTransform::RotationAngle() const
{
  return Eigen::AngleAxisd(rotation).angle();
}

namespace
{

SimilarityTransform Estimate(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                             bool withScale)
{
  if (source.size() != target.size())
    throw std::invalid_argument("paired-point alignment: " + std::to_string(source.size()) + " source points but " +
                                std::to_string(target.size()) + " target points");
  if (source.size() < 3)
    throw std::invalid_argument("paired-point alignment: needs at least 3 point pairs, got " +
                                std::to_string(source.size()));
  const Eigen::Index n = static_cast<Eigen::Index>(source.size());
  Eigen::Matrix3Xd src(3, n), dst(3, n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    src.col(i) = source[static_cast<std::size_t>(i)];
    dst.col(i) = target[static_cast<std::size_t>(i)];
  }
  if (!src.allFinite() || !dst.allFinite())
    throw std::invalid_argument("paired-point alignment: a point coordinate is not finite");

  // Collinear (or coincident) source points leave a rotation about their line free.
  // Singular values of the centred points from their 3 x 3 scatter matrix (a fixed-size SVD; the 3 x n
  // one instantiates Eigen's dynamic QR preconditioners, slow to compile). The square roots are good to
  // about 1e-8 of the largest, hence the 1e-6 ratio.
  const Eigen::Matrix3Xd centred = src.colwise() - src.rowwise().mean();
  const Eigen::Matrix3d scatter = centred * centred.transpose();
  const Eigen::Vector3d sv = Eigen::JacobiSVD<Eigen::Matrix3d>(scatter).singularValues().cwiseSqrt();
  if (!(sv(1) > 1e-6 * std::max(sv(0), 1e-300)) || sv(0) <= 0)
    throw std::invalid_argument("paired-point alignment: source points are collinear or coincident");

  const Eigen::Matrix4d m = Eigen::umeyama(src, dst, withScale);
  SimilarityTransform t;
  const Eigen::Matrix3d linear = m.topLeftCorner<3, 3>();
  t.scale = withScale ? std::cbrt(linear.determinant()) : 1.0;
  if (!(t.scale > 0) || !std::isfinite(t.scale))
    throw std::invalid_argument("paired-point alignment: target points are coincident (zero scale)");
  t.rotation = linear / t.scale;
  t.translation = m.topRightCorner<3, 1>();
  return t;
}

} // namespace

SimilarityTransform EstimateSimilarity(const std::vector<Eigen::Vector3d>& source,
                                       const std::vector<Eigen::Vector3d>& target)
{
  return Estimate(source, target, true);
}

SimilarityTransform EstimateRigid(const std::vector<Eigen::Vector3d>& source,
                                  const std::vector<Eigen::Vector3d>& target)
{
  return Estimate(source, target, false);
}

} // namespace mmrep
