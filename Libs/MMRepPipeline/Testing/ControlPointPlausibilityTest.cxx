// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The control points' plausibility against known configurations: the atlas's own landmarks moved by
// a known similarity (accepted, the known scale and turn found), a face turned sideways or upside
// down, a point moved off its feature, points off the skin.
#include "mmrepControlPointPlausibility.h"
#include "mmrepFEMeshIO.h"
#include "mmrepSurfaceIO.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace
{
const std::string kAtlas = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/";

std::vector<mmrep::Point3> Moved(const mmrep::FEMesh& atlas, double scale, const Eigen::Matrix3d& r,
                                 const Eigen::Vector3d& t)
{
  std::vector<mmrep::Point3> p;
  for (const auto& l : atlas.landmarks)
    p.push_back(scale * (r * l.position) + t);
  return p;
}

std::vector<std::string> Names(const mmrep::FEMesh& atlas)
{
  std::vector<std::string> n;
  for (const auto& l : atlas.landmarks)
    n.push_back(l.name);
  return n;
}

std::string Refusal(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch (const std::invalid_argument& e)
  {
    return e.what();
  }
  return {};
}

TEST(ControlPointPlausibility, KnownSimilarityIsAcceptedWithItsScaleAndTurn)
{
  const auto atlas = mmrep::ReadFEMesh(kAtlas + "FaceAtlas.vtu");
  // Turned 20 degrees about the atlas face's own up (its face is pitched a little in its CT).
  Eigen::Vector3d anterior, superior;
  ASSERT_TRUE(mmrep::AtlasFaceFrame(atlas, anterior, superior));
  EXPECT_NEAR(anterior.dot(superior), 0.0, 1e-12);
  const Eigen::Matrix3d yaw20 = Eigen::AngleAxisd(20.0 * EIGEN_PI / 180.0, superior).toRotationMatrix();
  const auto points = Moved(atlas, 0.9, yaw20, {5, -7, 12});
  const auto c = mmrep::AssessControlPoints(atlas, points);
  EXPECT_NEAR(c.scale, 0.9, 1e-9);
  EXPECT_NEAR(c.turn, 20.0, 1e-6); // the face's front turns with the yaw
  EXPECT_NEAR(c.tilt, 0.0, 1e-6);  // its up does not
  for (double r : c.leaveOneOut)
    EXPECT_LT(r, 1e-6);
  EXPECT_EQ(Refusal([&] { mmrep::CheckControlPointConfiguration(atlas, Names(atlas), points); }), "");
  EXPECT_EQ(mmrep::DirectionInWords(c.anterior), "the front");
}

TEST(ControlPointPlausibility, TurnedUpsideDownMovedAndScaledFacesAreRefusedNamingWhy)
{
  const auto atlas = mmrep::ReadFEMesh(kAtlas + "FaceAtlas.vtu");
  const auto names = Names(atlas);
  const Eigen::Matrix3d yaw90 = Eigen::AngleAxisd(EIGEN_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d roll180 = Eigen::AngleAxisd(EIGEN_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d id = Eigen::Matrix3d::Identity();
  const std::string turned = Refusal([&] {
    mmrep::CheckControlPointConfiguration(atlas, names, Moved(atlas, 1, yaw90, {0, 0, 0}));
  });
  EXPECT_NE(turned.find("orientation header looks wrong: the control points have the face looking to the patient's "
                        "left and its top pointing to the top (superior)"),
            std::string::npos)
    << turned;
  const std::string upsideDown = Refusal([&] {
    mmrep::CheckControlPointConfiguration(atlas, names, Moved(atlas, 1, roll180, {0, 0, 0}));
  });
  EXPECT_NE(upsideDown.find("looking to the back and its top pointing to the feet"), std::string::npos) << upsideDown;
  EXPECT_NE(Refusal([&] {
              mmrep::CheckControlPointConfiguration(atlas, names, Moved(atlas, 2.5, id, {0, 0, 0}));
            }).find("span 2.5 times"),
            std::string::npos);
  // The lower lip 25 mm up (on the nose): named, the others accepted.
  auto onTheNose = Moved(atlas, 1, id, {0, 0, 0});
  std::size_t lower = 0;
  while (names[lower] != "LowerLipCenter")
    ++lower;
  onTheNose[lower].z() += 25.0;
  const std::string moved = Refusal([&] { mmrep::CheckControlPointConfiguration(atlas, names, onTheNose); });
  EXPECT_NE(moved.find("'LowerLipCenter' lies "), std::string::npos) << moved;
  // 12 mm is within the variation between real faces: accepted.
  onTheNose[lower].z() -= 13.0;
  EXPECT_EQ(Refusal([&] { mmrep::CheckControlPointConfiguration(atlas, names, onTheNose); }), "");
}

TEST(ControlPointPlausibility, PointsOffTheSkinAreRefusedWithTheirDistance)
{
  const auto atlas = mmrep::ReadFEMesh(kAtlas + "FaceAtlas.vtu");
  const auto skin = mmrep::ReadSurface(kAtlas + "FaceAtlasSkin.vtp");
  const auto names = Names(atlas);
  auto points = Moved(atlas, 1, Eigen::Matrix3d::Identity(), {0, 0, 0});
  EXPECT_EQ(Refusal([&] { mmrep::CheckControlPointsOnSkin(skin, names, points); }), "");
  points[1].y() -= 12.0; // 12 mm in front of the face (LPS -y), in the air
  const std::string off = Refusal([&] { mmrep::CheckControlPointsOnSkin(skin, names, points); });
  EXPECT_NE(off.find("'" + names[1] + "' lies "), std::string::npos) << off;
  EXPECT_NE(off.find(" mm from the skin (at most 5.0)"), std::string::npos) << off;
}

} // namespace
