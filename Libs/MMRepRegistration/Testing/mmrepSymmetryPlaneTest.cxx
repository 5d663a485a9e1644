// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Symmetry plane: exact recovery on an exactly symmetric shape, and equivariance under known head
// tilts on the real skins of the bundled CTs (the plane of the moved head must be the moved plane).
#include "mmrepRegistrationTestData.h"
#include "mmrepSymmetryPlane.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <vtkCellArray.h>

#include <cmath>
#include <iostream>
#include <stdexcept>

namespace
{
constexpr double kDeg = 3.14159265358979323846 / 180;

Eigen::Matrix3d Tilt(double rollDeg, double yawDeg, double pitchDeg = 0)
{
  return (Eigen::AngleAxisd(yawDeg * kDeg, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rollDeg * kDeg, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(pitchDeg * kDeg, Eigen::Vector3d::UnitX()))
    .toRotationMatrix();
}

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::atan2(a.cross(b).norm(), std::abs(a.dot(b))) / kDeg;
}

// Copy of `s` moved by x -> R (x - c) + c + t.
vtkSmartPointer<vtkPolyData> Moved(vtkPolyData* s, const Eigen::Matrix3d& r, const Eigen::Vector3d& c,
                                   const Eigen::Vector3d& t)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(s);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    const Eigen::Vector3d q = r * (Eigen::Vector3d(p[0], p[1], p[2]) - c) + c + t;
    out->GetPoints()->SetPoint(i, q.data());
  }
  return out;
}

Eigen::Vector3d BoundsCentre(vtkPolyData* s)
{
  double b[6];
  s->GetBounds(b);
  return {0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])};
}
} // namespace

TEST(SymmetryPlane, ExactlySymmetricShapeGivesItsPlane)
{
  struct Case
  {
    double roll, yaw, pitch;
    Eigen::Vector3d t;
  };
  for (const Case& c : {Case{0, 0, 0, {0, 0, 0}}, Case{12, -9, 5, {10, -20, 30}}, Case{-15, 15, -8, {-5, 3, 40}}})
  {
    const Eigen::Matrix3d r = Tilt(c.roll, c.yaw, c.pitch);
    const auto head = mmrep::testing::SymmetricHead(r, c.t);
    const auto est = mmrep::EstimateSymmetryPlane(head);
    const Eigen::Vector3d trueNormal = r * Eigen::Vector3d::UnitX();
    const double angle = AngleDeg(est.plane.normal, trueNormal);
    const double offset = std::abs(est.plane.SignedDistance(c.t)); // at the head's centre
    std::cout << "symmetric shape roll " << c.roll << " yaw " << c.yaw << " pitch " << c.pitch << ": normal error "
              << angle << " deg, offset " << offset << " mm, rms " << est.rmsResidual << " mm, " << est.iterations
              << " iterations\n";
    EXPECT_LT(angle, 0.1);
    EXPECT_LT(offset, 0.1);
    EXPECT_NEAR(est.plane.normal.norm(), 1.0, 1e-12);
    EXPECT_GT(est.plane.normal.x(), 0);
    EXPECT_LT(est.rmsResidual, 0.2);
    // The reported point is on the plane near the centre.
    EXPECT_LT((est.plane.point - c.t).norm(), 20.0);
  }
}

class SymmetryPlaneTilted : public ::testing::TestWithParam<const char*>
{
};

TEST_P(SymmetryPlaneTilted, BundledHeadGivesTheTiltedPlane)
{
  struct Tilted
  {
    double roll, yaw, pitch;
  };
  // The extremes of the ±15° range about each axis, alone and combined (with pitch).
  const Tilted tilts[] = {{15, 0, 0}, {0, -15, 0}, {-15, 15, 10}, {12, -15, -10}};
  for (const char* name : {GetParam()})
  {
    vtkPolyData* skin = mmrep::testing::BundledSkin(name).skin;
    ASSERT_GT(skin->GetNumberOfPoints(), 10000) << name;
    const auto base = mmrep::EstimateSymmetryPlane(skin);
    std::cout << name << ": plane normal " << base.plane.normal.transpose() << ", point "
              << base.plane.point.transpose() << ", rms " << base.rmsResidual << " mm, " << base.iterations
              << " iterations\n";
    // Sanity against the anatomy: the head's plane is near-sagittal.
    EXPECT_LT(AngleDeg(base.plane.normal, Eigen::Vector3d::UnitX()), 10.0) << name;
    const Eigen::Vector3d centre = BoundsCentre(skin);
    const Eigen::Vector3d shift(7, -12, 5);
    double worstAngle = 0, worstOffset = 0;
    for (const Tilted& t : tilts)
    {
      const Eigen::Matrix3d r = Tilt(t.roll, t.yaw, t.pitch);
      const auto est = mmrep::EstimateSymmetryPlane(Moved(skin, r, centre, shift));
      mmrep::Plane expected;
      expected.normal = r * base.plane.normal;
      expected.point = r * (base.plane.point - centre) + centre + shift;
      const Eigen::Vector3d movedCentre = centre + shift;
      const double angle = AngleDeg(est.plane.normal, expected.normal);
      const double offset = std::abs(est.plane.SignedDistance(expected.Project(movedCentre)));
      std::cout << name << " roll " << t.roll << " yaw " << t.yaw << " pitch " << t.pitch << ": normal error " << angle
                << " deg, offset at centre " << offset << " mm, rms " << est.rmsResidual << " mm, " << est.iterations
                << " iterations\n";
      EXPECT_LT(angle, 1.0) << name << " roll " << t.roll << " yaw " << t.yaw;
      EXPECT_LT(offset, 1.0) << name << " roll " << t.roll << " yaw " << t.yaw;
      worstAngle = std::max(worstAngle, angle);
      worstOffset = std::max(worstOffset, offset);
    }
    std::cout << name << ": worst normal error " << worstAngle << " deg, worst offset " << worstOffset << " mm\n";
  }
}

INSTANTIATE_TEST_SUITE_P(BundledCTs, SymmetryPlaneTilted, ::testing::Values("cthead.nrrd", "headsq.nrrd"),
                         [](const auto& info) {
                           return std::string(info.param).substr(0, std::string(info.param).find('.'));
                         });

TEST(SymmetryPlane, EmptyOrTrianglelessSurfaceThrows)
{
  vtkNew<vtkPolyData> empty;
  EXPECT_THROW(mmrep::EstimateSymmetryPlane(empty), std::runtime_error);
  EXPECT_THROW(mmrep::EstimateSymmetryPlane(nullptr), std::runtime_error);
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(mmrep::testing::SymmetricHead(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero())->GetPoints());
  EXPECT_THROW(mmrep::EstimateSymmetryPlane(cloud), std::runtime_error);
  mmrep::SymmetryPlaneOptions bad;
  bad.trimFraction = 0.95;
  EXPECT_THROW(mmrep::EstimateSymmetryPlane(mmrep::testing::SymmetricHead(Eigen::Matrix3d::Identity(), {0, 0, 0}), bad),
               std::invalid_argument);
}

TEST(SymmetryPlane, DeterministicResult)
{
  vtkPolyData* skin = mmrep::testing::BundledSkin("headsq.nrrd").skin;
  const auto a = mmrep::EstimateSymmetryPlane(skin);
  const auto b = mmrep::EstimateSymmetryPlane(skin);
  EXPECT_EQ(a.plane.normal, b.plane.normal);
  EXPECT_EQ(a.plane.point, b.plane.point);
  EXPECT_EQ(a.rmsResidual, b.rmsResidual);
}
