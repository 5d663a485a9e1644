// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The elementary step: C1 bump, exact gradient bound, non-folding, bucketed replay, Jacobian.
#include "mmrepElasticTransform.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <random>

using namespace mmrep;

TEST(ElasticBump, IsC1AcrossTheSupportBoundary)
{
  // Node value 1, flat there; value and slope vanish at |t| = 1 from inside and outside.
  EXPECT_DOUBLE_EQ(ElasticBump(0.0), 1.0);
  EXPECT_DOUBLE_EQ(ElasticBumpDerivative(0.0), 0.0);
  for (double s : {-1.0, 1.0})
  {
    EXPECT_EQ(ElasticBump(s), 0.0);
    EXPECT_LT(std::abs(ElasticBump(s * (1 - 1e-4))), 1e-7);
    EXPECT_LT(std::abs(ElasticBumpDerivative(s * (1 - 1e-4))), 1e-3);
    EXPECT_EQ(ElasticBumpDerivative(s * (1 + 1e-4)), 0.0);
  }
  // The derivative is the derivative (central differences), and it is continuous (no jumps).
  const double eps = 1e-6;
  double previous = ElasticBumpDerivative(-1.2);
  for (double t = -1.2; t <= 1.2; t += 1e-3)
  {
    const double fd = (ElasticBump(t + eps) - ElasticBump(t - eps)) / (2 * eps);
    EXPECT_NEAR(ElasticBumpDerivative(t), fd, 1e-5) << t;                // FD truncation: 3ε²/2ε at |t| = 1
    EXPECT_LT(std::abs(ElasticBumpDerivative(t) - previous), 1e-2) << t; // |b''| ≤ 6: steps of 1e-3 move b' ≤ 6e-3
    previous = ElasticBumpDerivative(t);
  }
  // φ and ∇φ across a face of the support: finite differences of the 3D bump agree everywhere.
  const Eigen::Vector3d node(1, 2, 3), h(2, 3, 4);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.1, 1.1);
  for (int k = 0; k < 2000; ++k)
  {
    const Eigen::Vector3d p = node + Eigen::Vector3d(u(rng) * h.x(), u(rng) * h.y(), u(rng) * h.z());
    Eigen::Vector3d g;
    ElasticTransform::Bump(p, node, h, &g);
    for (int a = 0; a < 3; ++a)
    {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[a] = 1e-6;
      const double fd = (ElasticTransform::Bump(p + e, node, h) - ElasticTransform::Bump(p - e, node, h)) / 2e-6;
      EXPECT_NEAR(g[a], fd, 1e-6);
    }
  }
}

TEST(ElasticBump, GradientBoundIsExactAndStepsAtTheBoundDoNotFold)
{
  for (const Eigen::Vector3d h : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(3.2, 4.7, 5.1), Eigen::Vector3d(1, 10, 10)})
  {
    const double L = MaximumBumpGradient(h);
    // Dense sampling never exceeds L and comes within 0.1% of it.
    double sampled = 0;
    const int n = 60;
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        for (int k = -n; k <= n; ++k)
        {
          Eigen::Vector3d g;
          ElasticTransform::Bump(Eigen::Vector3d(i * h.x() / n, j * h.y() / n, k * h.z() / n), Eigen::Vector3d::Zero(),
                                 h, &g);
          sampled = std::max(sampled, g.norm());
        }
    EXPECT_LE(sampled, L * (1 + 1e-12));
    EXPECT_GT(sampled, 0.999 * L);
    EXPECT_GE(L, 1.5 / h.maxCoeff() - 1e-12); // at least the single-axis maximum of |b'|/h

    // Single steps at the largest allowed |δ| = 0.4/L, in many directions: det J ≥ 0.6 > 0.
    std::mt19937 rng(3);
    std::normal_distribution<double> nd;
    std::uniform_real_distribution<double> ud(-1, 1);
    double minDet = 1e9, minDetTooBig = 1e9;
    for (int k = 0; k < 20000; ++k)
    {
      const Eigen::Vector3d dir = Eigen::Vector3d(nd(rng), nd(rng), nd(rng)).normalized();
      const Eigen::Vector3d p(ud(rng) * h.x(), ud(rng) * h.y(), ud(rng) * h.z());
      ElasticStep s;
      s.delta = 0.4 / L * dir;
      Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
      ElasticTransform::ApplyStep(s, h, p, &j);
      minDet = std::min(minDet, j.determinant());
      // Past the bound (|δ| = 1.5/L) some step folds: the bound is not vacuous.
      s.delta = 1.5 / L * dir;
      j.setIdentity();
      ElasticTransform::ApplyStep(s, h, p, &j);
      minDetTooBig = std::min(minDetTooBig, j.determinant());
    }
    EXPECT_GE(minDet, 0.6 - 1e-12);
    EXPECT_LT(minDetTooBig, 0.0);
  }
}

namespace
{
ElasticTransform RandomTransform(bool symmetric, unsigned seed)
{
  ElasticTransform t;
  t.preLinear = 1.1 * Eigen::AngleAxisd(0.2, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  t.preTranslation = Eigen::Vector3d(3, -2, 1);
  t.frameRotation = Eigen::AngleAxisd(0.3, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  t.frameOrigin = Eigen::Vector3d(1, 2, 3);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int l = 1; l <= 4; ++l)
  {
    ElasticLevel level;
    level.level = l;
    level.cells = 1 << l;
    level.boxMin = Eigen::Vector3d(-50, -40, -30);
    level.h = Eigen::Vector3d(100, 80, 60) / level.cells;
    const double maxStep = 0.4 / MaximumBumpGradient(level.h);
    for (int s = 0; s < 300; ++s)
    {
      std::uniform_int_distribution<int> node(0, level.cells);
      ElasticStep step;
      const int ix = node(rng);
      step.node =
        Eigen::Vector3d(symmetric ? (ix - level.cells / 2) * level.h.x() : level.boxMin.x() + ix * level.h.x(),
                        level.boxMin.y() + node(rng) * level.h.y(), level.boxMin.z() + node(rng) * level.h.z());
      step.delta = 0.5 * maxStep * Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
      step.mirrored = symmetric && step.node.x() != 0;
      if (symmetric && !step.mirrored)
        step.delta.x() = 0;
      level.steps.push_back(step);
    }
    t.levels.push_back(level);
  }
  return t;
}
} // namespace

TEST(ElasticTransform, BucketedReplayEqualsBruteForceBitForBit)
{
  ElasticTransform brute = RandomTransform(true, 11);
  ElasticTransform indexed = brute;
  indexed.BuildIndex();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-70, 70);
  int moved = 0;
  for (int k = 0; k < 5000; ++k)
  {
    const Eigen::Vector3d x(u(rng), u(rng), u(rng));
    const Eigen::Vector3d a = brute.Apply(x), b = indexed.Apply(x);
    ASSERT_EQ(a, b) << x.transpose();
    moved += (a - indexed.PreApply(x)).norm() > 1e-6 ? 1 : 0;
  }
  EXPECT_GT(moved, 1000); // the steps do act on the sample
}

TEST(ElasticTransform, JacobianMatchesFiniteDifferencesAndStaysPositive)
{
  ElasticTransform t = RandomTransform(false, 13);
  t.BuildIndex();
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-45, 45);
  double worst = 0;
  for (int k = 0; k < 500; ++k)
  {
    const Eigen::Vector3d x(u(rng), u(rng), u(rng));
    const Eigen::Matrix3d j = t.Jacobian(x);
    Eigen::Matrix3d fd;
    for (int a = 0; a < 3; ++a)
    {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[a] = 1e-5;
      fd.col(a) = (t.Apply(x + e) - t.Apply(x - e)) / 2e-5;
    }
    worst = std::max(worst, (j - fd).cwiseAbs().maxCoeff());
    EXPECT_GT(j.determinant(), 0.0);
  }
  EXPECT_LT(worst, 1e-5);
}

TEST(ElasticTransform, MirroredStepsCommuteWithTheMirrorExactly)
{
  ElasticTransform t = RandomTransform(true, 17);
  t.BuildIndex();
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-60, 60);
  for (int k = 0; k < 3000; ++k)
  {
    const Eigen::Vector3d f(u(rng), u(rng), u(rng));
    const Eigen::Vector3d mf(-f.x(), f.y(), f.z());
    const Eigen::Vector3d a = t.ApplyInFrame(f), b = t.ApplyInFrame(mf);
    ASSERT_EQ(b, Eigen::Vector3d(-a.x(), a.y(), a.z())) << f.transpose();
  }
}
