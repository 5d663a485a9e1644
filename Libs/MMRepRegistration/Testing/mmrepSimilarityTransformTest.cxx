// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Paired-point similarity and rigid alignment against known transforms.
#include "mmrepSimilarityTransform.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace
{
using mmrep::SimilarityTransform;

SimilarityTransform Known(double scale)
{
  SimilarityTransform t;
  t.rotation = Eigen::Quaterniond(0.3, -0.5, 0.7, 0.2).normalized().toRotationMatrix();
  t.scale = scale;
  t.translation = Eigen::Vector3d(12.5, -40.0, 7.25);
  return t;
}

std::vector<Eigen::Vector3d> Cloud(int n)
{
  std::mt19937 rng(7);
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < n; ++i)
    pts.emplace_back(double(rng() % 2000) / 10 - 100, double(rng() % 2000) / 10 - 100, double(rng() % 2000) / 10 - 100);
  return pts;
}
} // namespace

TEST(RegistrationSimilarity, UmeyamaRecoversKnownSimilarityExactly)
{
  const SimilarityTransform truth = Known(1.7);
  const auto src = Cloud(25);
  std::vector<Eigen::Vector3d> dst;
  for (const auto& p : src)
    dst.push_back(truth.Apply(p));
  const SimilarityTransform est = mmrep::EstimateSimilarity(src, dst);
  EXPECT_NEAR(est.scale, 1.7, 1e-9);
  EXPECT_LT((est.rotation - truth.rotation).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((est.translation - truth.translation).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(est.rotation.determinant(), 1.0, 1e-12);
  for (const auto& p : src)
    EXPECT_LT((est.Apply(p) - truth.Apply(p)).norm(), 1e-9);
}

TEST(RegistrationSimilarity, RigidVariantKeepsUnitScale)
{
  const SimilarityTransform truth = Known(1.0);
  const auto src = Cloud(10);
  std::vector<Eigen::Vector3d> dst, scaled;
  for (const auto& p : src)
  {
    dst.push_back(truth.Apply(p));
    scaled.push_back(2.0 * truth.Apply(p));
  }
  const SimilarityTransform est = mmrep::EstimateRigid(src, dst);
  EXPECT_EQ(est.scale, 1.0);
  EXPECT_LT((est.rotation - truth.rotation).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((est.translation - truth.translation).cwiseAbs().maxCoeff(), 1e-9);
  // On scaled targets the rigid fit cannot match, the similarity fit does.
  EXPECT_EQ(mmrep::EstimateRigid(src, scaled).scale, 1.0);
  EXPECT_NEAR(mmrep::EstimateSimilarity(src, scaled).scale, 2.0, 1e-9);
}

TEST(RegistrationSimilarity, InverseComposeAndMatrixAgree)
{
  const SimilarityTransform a = Known(0.8);
  SimilarityTransform b;
  b.rotation = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  b.scale = 1.3;
  b.translation = Eigen::Vector3d(-3, 4, 5);
  const Eigen::Vector3d p(10, -20, 30);
  EXPECT_LT((a.Inverse().Apply(a.Apply(p)) - p).norm(), 1e-12);
  EXPECT_LT((a.Compose(b).Apply(p) - a.Apply(b.Apply(p))).norm(), 1e-12);
  const Eigen::Vector4d h = a.Matrix() * p.homogeneous();
  EXPECT_LT((h.head<3>() - a.Apply(p)).norm(), 1e-12);
  EXPECT_NEAR(b.RotationAngle(), 0.4, 1e-12);
}

TEST(RegistrationSimilarity, BadInputThrows)
{
  const auto src = Cloud(5);
  auto dst = src;
  EXPECT_THROW(mmrep::EstimateSimilarity({src[0], src[1]}, {dst[0], dst[1]}), std::invalid_argument);
  EXPECT_THROW(mmrep::EstimateSimilarity(src, {dst[0], dst[1], dst[2]}), std::invalid_argument);
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 6; ++i)
    line.emplace_back(1.0 * i, 2.0 * i, -1.0 * i);
  EXPECT_THROW(mmrep::EstimateSimilarity(line, line), std::invalid_argument);
  EXPECT_THROW(mmrep::EstimateRigid(line, line), std::invalid_argument);
  std::vector<Eigen::Vector3d> same(4, Eigen::Vector3d(1, 1, 1));
  EXPECT_THROW(mmrep::EstimateRigid(same, same), std::invalid_argument);
  dst[2].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(mmrep::EstimateRigid(src, dst), std::invalid_argument);
  // Coincident targets: zero scale.
  EXPECT_THROW(mmrep::EstimateSimilarity(src, std::vector<Eigen::Vector3d>(5, Eigen::Vector3d::Zero())),
               std::invalid_argument);
}
