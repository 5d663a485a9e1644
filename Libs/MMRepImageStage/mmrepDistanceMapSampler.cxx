// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepDistanceMapSampler.h"

#include <Eigen/LU>
#include <itkImageRegionConstIterator.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mmrep
{

DistanceMapSampler::DistanceMapSampler(const FloatImage* map)
{
  if (map == nullptr)
    throw std::invalid_argument("distance map sampler: no map");
  const auto region = map->GetLargestPossibleRegion();
  for (int a = 0; a < 3; ++a)
  {
    size_[a] = static_cast<int>(region.GetSize()[a]);
    origin_[a] = map->GetOrigin()[a];
  }
  if (size_.minCoeff() < 2)
    throw std::invalid_argument("distance map sampler: the map needs at least 2 voxels along each axis");
  Eigen::Matrix3d direction, spacing = Eigen::Matrix3d::Zero();
  for (int r = 0; r < 3; ++r)
  {
    spacing(r, r) = map->GetSpacing()[r];
    for (int c = 0; c < 3; ++c)
      direction(r, c) = map->GetDirection()(r, c);
  }
  fromIndex_ = direction * spacing;
  toIndex_ = fromIndex_.inverse();
  data_.reserve(region.GetNumberOfPixels());
  itk::ImageRegionConstIterator<FloatImage> it(map, region); // x fastest, as indexed below
  for (; !it.IsAtEnd(); ++it)
    data_.push_back(it.Get());
}

double DistanceMapSampler::Value(const Eigen::Vector3d& x, Eigen::Vector3d* gradient) const
{
  const Eigen::Vector3d c = toIndex_ * (x - origin_);
  Eigen::Vector3d cc;
  for (int a = 0; a < 3; ++a)
    cc[a] = std::clamp(c[a], 0.0, static_cast<double>(size_[a] - 1));
  int i0[3];
  double t[3];
  for (int a = 0; a < 3; ++a)
  {
    i0[a] = std::min(static_cast<int>(std::floor(cc[a])), size_[a] - 2);
    t[a] = cc[a] - i0[a];
  }
  const std::size_t sx = 1, sy = static_cast<std::size_t>(size_[0]), sz = sy * static_cast<std::size_t>(size_[1]);
  const std::size_t base = i0[0] * sx + i0[1] * sy + i0[2] * sz;
  double v[2][2][2];
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx)
        v[dz][dy][dx] = data_[base + dx * sx + dy * sy + dz * sz];
  // Trilinear value and its derivatives in index space.
  const double c00 = v[0][0][0] * (1 - t[0]) + v[0][0][1] * t[0];
  const double c01 = v[0][1][0] * (1 - t[0]) + v[0][1][1] * t[0];
  const double c10 = v[1][0][0] * (1 - t[0]) + v[1][0][1] * t[0];
  const double c11 = v[1][1][0] * (1 - t[0]) + v[1][1][1] * t[0];
  const double c0 = c00 * (1 - t[1]) + c01 * t[1];
  const double c1 = c10 * (1 - t[1]) + c11 * t[1];
  double value = c0 * (1 - t[2]) + c1 * t[2];
  Eigen::Vector3d gIndex = Eigen::Vector3d::Zero();
  if (gradient)
  {
    const double dx00 = v[0][0][1] - v[0][0][0], dx01 = v[0][1][1] - v[0][1][0];
    const double dx10 = v[1][0][1] - v[1][0][0], dx11 = v[1][1][1] - v[1][1][0];
    gIndex[0] = ((dx00 * (1 - t[1]) + dx01 * t[1]) * (1 - t[2]) + (dx10 * (1 - t[1]) + dx11 * t[1]) * t[2]);
    gIndex[1] = (c01 - c00) * (1 - t[2]) + (c11 - c10) * t[2];
    gIndex[2] = c1 - c0;
    // ∂d/∂x = (∂c/∂x)ᵀ ∂d/∂c
    *gradient = toIndex_.transpose() * gIndex;
  }
  if (cc != c)
  {
    // Outside: add the distance to the nearest box point; gradient along the outward offset.
    const Eigen::Vector3d offset = x - (origin_ + fromIndex_ * cc);
    const double dist = offset.norm();
    value += dist;
    if (gradient && dist > 0)
      *gradient = offset / dist;
  }
  return value;
}

} // namespace mmrep
