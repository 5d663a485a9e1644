// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Least-squares similarity (rotation, isotropic scale, translation) and rigid transforms from
// paired points (Umeyama 1991, through Eigen::umeyama).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace mmrep
{

// x -> scale * rotation * x + translation (rotation proper: det = +1).
struct SimilarityTransform
{
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double scale = 1.0;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d Apply(const Eigen::Vector3d& p) const { return scale * (rotation * p) + translation; }
  Eigen::Matrix3d Linear() const { return scale * rotation; }
  SimilarityTransform Inverse() const;
  Eigen::Matrix4d Matrix() const; // homogeneous 4x4
  // (this ∘ first)(x) = this->Apply(first.Apply(x))
  SimilarityTransform Compose(const SimilarityTransform& first) const;
  double RotationAngle() const; // radians, angle of `rotation`
};

// Transform T minimising Σ |T(source_i) - target_i|². Throws std::invalid_argument when the
// lists differ in size, hold fewer than 3 points, a coordinate is not finite, or the source
// points are (nearly) collinear, so that the rotation is undetermined.
SimilarityTransform EstimateSimilarity(const std::vector<Eigen::Vector3d>& source,
                                       const std::vector<Eigen::Vector3d>& target);
// Same with scale fixed to 1.
SimilarityTransform EstimateRigid(const std::vector<Eigen::Vector3d>& source,
                                  const std::vector<Eigen::Vector3d>& target);

} // namespace mmrep
