// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Synthetic warp: inverse consistency, Jacobian bound (against finite differences), and the
// resampling direction end to end (the synthetic CT's skin mapped back lies on the source skin).
#include "mmrepRegistrationTestData.h"
#include "mmrepSyntheticSubject.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <gtest/gtest.h>
#include <vtkGenericCell.h>
#include <vtkStaticCellLocator.h>

#include <cmath>
#include <iostream>
#include <random>
#include <stdexcept>

namespace
{
mmrep::SyntheticWarpParameters Strong()
{
  mmrep::SyntheticWarpParameters p;
  p.rollDegrees = -15;
  p.pitchDegrees = 10;
  p.yawDegrees = 15;
  p.translation = {5, -8, 3};
  p.centre = {10, -20, 30};
  p.bumps = 6;
  p.width = 30;
  // At the admissible limit: bumps * amplitude * e^-1/2 / width = 0.2.
  p.amplitude = mmrep::SyntheticWarp::kMaximumGradient * p.width / std::exp(-0.5) / p.bumps;
  p.regionMin = {-60, -80, -50};
  p.regionMax = {80, 40, 110};
  p.seed = 99;
  return p;
}

// Mean and max distance from points to the triangles of a surface.
std::pair<double, double> DistanceToSurface(vtkPolyData* surface, const std::vector<Eigen::Vector3d>& points)
{
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  double sum = 0, worst = 0;
  for (const auto& p : points)
  {
    double closest[3], d2;
    vtkIdType id;
    int sub;
    locator->FindClosestPoint(p.data(), closest, cell, id, sub, d2);
    sum += std::sqrt(d2);
    worst = std::max(worst, std::sqrt(d2));
  }
  return {sum / points.size(), worst};
}
} // namespace

TEST(SyntheticSubjectWarp, ForwardInvertsInverse)
{
  const mmrep::SyntheticWarp warp(Strong());
  std::mt19937 rng(3);
  double worst = 0;
  for (int i = 0; i < 5000; ++i)
  {
    const Eigen::Vector3d y(double(rng() % 3000) / 10 - 130, double(rng() % 3000) / 10 - 170,
                            double(rng() % 3000) / 10 - 120);
    worst = std::max(worst, (warp.Forward(warp.Inverse(y)) - y).norm());
    worst = std::max(worst, (warp.Inverse(warp.Forward(y)) - y).norm());
  }
  std::cout << "max |F(G(y)) - y|, |G(F(x)) - x| = " << worst << " mm\n";
  EXPECT_LT(worst, 1e-6);
  // The warp is not a rigid motion only: the bumps move points by millimetres.
  double maxU = 0;
  for (int i = 0; i < 2000; ++i)
  {
    const Eigen::Vector3d z(double(rng() % 1400) / 10 - 60, double(rng() % 1200) / 10 - 80,
                            double(rng() % 1600) / 10 - 50);
    maxU = std::max(maxU, warp.Displacement(z).norm());
  }
  EXPECT_GT(maxU, 1.0);
}

TEST(SyntheticSubjectWarp, JacobianDeterminantAboveHalfEverywhere)
{
  const mmrep::SyntheticWarp warp(Strong());
  EXPECT_NEAR(warp.GradientBound(), 0.2, 1e-12);
  double minDetG = 1e9, minDetF = 1e9, maxGrad = 0, worstFd = 0;
  const double h = 1e-4;
  for (double x = -100; x <= 120; x += 7)
    for (double y = -120; y <= 80; y += 7)
      for (double z = -90; z <= 150; z += 7)
      {
        const Eigen::Vector3d p(x, y, z);
        const Eigen::Matrix3d jg = warp.InverseJacobian(p);
        minDetG = std::min(minDetG, jg.determinant());
        minDetF = std::min(minDetF, warp.ForwardJacobian(p).determinant());
        const Eigen::Matrix3d du = warp.DisplacementGradient(p);
        maxGrad = std::max(maxGrad, du.jacobiSvd().singularValues()(0));
        // Independent check of the analytic Jacobian: central differences of G.
        Eigen::Matrix3d fd;
        for (int d = 0; d < 3; ++d)
        {
          const Eigen::Vector3d e = Eigen::Vector3d::Unit(d) * h;
          fd.col(d) = (warp.Inverse(p + e) - warp.Inverse(p - e)) / (2 * h);
        }
        worstFd = std::max(worstFd, (fd - jg).cwiseAbs().maxCoeff());
      }
  std::cout << "min det dG = " << minDetG << ", min det dF = " << minDetF << ", max |grad u| = " << maxGrad
            << " (bound " << warp.GradientBound() << "), finite-difference mismatch " << worstFd << "\n";
  EXPECT_LT(worstFd, 1e-6);
  EXPECT_LE(maxGrad, warp.GradientBound());
  EXPECT_GT(minDetG, 0.5);
  EXPECT_GT(minDetF, 0.5);
  EXPECT_LT(minDetG, 0.95); // the sampling does reach strongly deformed places
}

TEST(SyntheticSubjectWarp, RejectsOutOfRangeParameters)
{
  auto p = Strong();
  p.rollDegrees = 15.5;
  EXPECT_THROW(mmrep::SyntheticWarp{p}, std::invalid_argument);
  p = Strong();
  p.yawDegrees = -20;
  EXPECT_THROW(mmrep::SyntheticWarp{p}, std::invalid_argument);
  p = Strong();
  p.amplitude *= 1.01; // gradient bound above 0.2
  EXPECT_THROW(mmrep::SyntheticWarp{p}, std::invalid_argument);
  p = Strong();
  p.width = 0;
  EXPECT_THROW(mmrep::SyntheticWarp{p}, std::invalid_argument);
}

TEST(SyntheticSubjectWarp, SameSeedSameWarpOtherSeedOtherWarp)
{
  const Eigen::Vector3d q(3, -4, 20);
  const mmrep::SyntheticWarp a(Strong()), b(Strong());
  EXPECT_EQ(a.Forward(q), b.Forward(q));
  auto p = Strong();
  p.seed = 100;
  EXPECT_GT((mmrep::SyntheticWarp(p).Inverse(q) - a.Inverse(q)).norm(), 1e-3);
}

TEST(SyntheticSubjectWarp, FieldsHoldTheMaps)
{
  const auto& src = mmrep::testing::BundledSkin("headsq.nrrd");
  mmrep::SyntheticWarpParameters p;
  mmrep::FitWarpToImage(p, src.ct);
  const mmrep::SyntheticWarp warp(p);
  const auto fwd = mmrep::ForwardDisplacementField(src.ct, warp);
  const auto inv = mmrep::InverseDisplacementField(src.ct, warp);
  for (const itk::Index<3>& idx : {itk::Index<3>{{0, 0, 0}}, itk::Index<3>{{31, 20, 50}}, itk::Index<3>{{63, 63, 92}}})
  {
    itk::Point<double, 3> pt;
    src.ct->TransformIndexToPhysicalPoint(idx, pt);
    const Eigen::Vector3d x(pt[0], pt[1], pt[2]);
    const auto d = fwd->GetPixel(idx);
    const auto e = inv->GetPixel(idx);
    const Eigen::Vector3d f = warp.Forward(x), g = warp.Inverse(x);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_NEAR(x(k) + d[k], f(k), 1e-3);
      EXPECT_NEAR(x(k) + e[k], g(k), 1e-3);
    }
  }
}

TEST(SyntheticSubjectWarp, SubjectSkinMapsBackOntoSourceSkin)
{
  const auto& src = mmrep::testing::BundledSkin("cthead.nrrd");
  mmrep::SyntheticWarpParameters p; // defaults: 8 deg roll, 5 deg yaw, bumps
  mmrep::FitWarpToImage(p, src.ct);
  const mmrep::SyntheticWarp warp(p);
  const auto subjectCT = mmrep::ResampleSyntheticSubject(src.ct, warp);
  const auto subjectSkin = mmrep::testing::SkinOf(subjectCT, src.thresholds, 30000);
  std::vector<Eigen::Vector3d> back, wrong, unmoved;
  for (vtkIdType i = 0; i < subjectSkin->GetNumberOfPoints(); ++i)
  {
    double q[3];
    subjectSkin->GetPoint(i, q);
    const Eigen::Vector3d y(q[0], q[1], q[2]);
    back.push_back(warp.Inverse(y));
    wrong.push_back(warp.Forward(y)); // the other direction: must not fit
    unmoved.push_back(y);
  }
  const auto [mean, worst] = DistanceToSurface(src.skin, back);
  const auto wrongMean = DistanceToSurface(src.skin, wrong).first;
  const auto unmovedMean = DistanceToSurface(src.skin, unmoved).first;
  std::cout << "subject skin mapped back by G: mean " << mean << " mm, max " << worst << " mm; by F: mean " << wrongMean
            << " mm; not mapped: " << unmovedMean << " mm\n";
  EXPECT_LT(mean, 1.0); // about one voxel (1 x 1 x 2 mm)
  EXPECT_GT(wrongMean, 3.0 * mean + 2.0);
  EXPECT_GT(unmovedMean, 2.0 * mean + 1.0);
}
