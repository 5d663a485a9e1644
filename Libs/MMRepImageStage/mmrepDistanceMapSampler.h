// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Trilinear value and gradient of a distance map at any LPS point, as the registration energy
// needs them. Outside the map's box the value continues as (distance to the box) + (value at the
// nearest box point), with the gradient pointing away from the box, so descent leads back in.
#pragma once

#include "mmrepImageIO.h"

#include <Eigen/Core>

#include <vector>

namespace mmrep
{

class DistanceMapSampler
{
public:
  DistanceMapSampler() = default;
  explicit DistanceMapSampler(const FloatImage* map); // throws std::invalid_argument for an empty map
  bool Empty() const { return data_.empty(); }
  double Value(const Eigen::Vector3d& x, Eigen::Vector3d* gradient = nullptr) const;

private:
  std::vector<float> data_;
  Eigen::Vector3i size_ = Eigen::Vector3i::Zero();
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d toIndex_ = Eigen::Matrix3d::Identity();   // continuous index = toIndex (x − origin)
  Eigen::Matrix3d fromIndex_ = Eigen::Matrix3d::Identity(); // inverse
};

} // namespace mmrep
