// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// SymmetryPlane module: return values and plane markup against the library on the same file, and
// failures (missing file, empty surface, surface without triangles) without output.
#include "mmrepModuleRunner.h"
#include "mmrepRegistrationTestData.h"
#include "mmrepSurfaceIO.h"
#include "mmrepSymmetryPlane.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace
{
using mmrep::testing::RunModuleExecutable;
using mmrep::testing::ScratchDirectory;

std::vector<double> Parse(const std::string& text)
{
  std::vector<double> v;
  std::stringstream s(text);
  for (std::string item; std::getline(s, item, ',');)
    v.push_back(std::stod(item));
  return v;
}
} // namespace

TEST(SymmetryPlaneModule, ReturnsTheLibraryPlaneAndWritesAMarkup)
{
  ScratchDirectory dir("SymmetryPlaneModule");
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()).toRotationMatrix() *
                            Eigen::AngleAxisd(-0.1, Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d t(3, -40, 12);
  mmrep::WriteSurface(mmrep::testing::SymmetricHead(r, t), dir / "head.vtp");
  const auto expected = mmrep::EstimateSymmetryPlane(mmrep::ReadSurface(dir / "head.vtp"));

  const auto run = RunModuleExecutable("SymmetryPlane", {dir / "head.vtp", "--outputPlane", dir / "plane.mrk.json",
                                                         "--returnparameterfile", dir / "ret.txt"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("<filter-start>"), std::string::npos);
  EXPECT_NE(run.out.find("<filter-end>"), std::string::npos);
  const auto values = mmrep::testing::ReadReturnParameters(dir / "ret.txt");
  const auto point = Parse(values.at("planePoint"));
  const auto normal = Parse(values.at("planeNormal"));
  ASSERT_EQ(point.size(), 3u);
  ASSERT_EQ(normal.size(), 3u);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(point[i], expected.plane.point(i), 1e-9);
    EXPECT_NEAR(normal[i], expected.plane.normal(i), 1e-12);
  }
  // And the plane is the shape's true plane.
  EXPECT_GT(std::abs(Eigen::Vector3d(normal[0], normal[1], normal[2]).dot(r * Eigen::Vector3d::UnitX())), 1 - 1e-6);
  EXPECT_NEAR(std::stod(values.at("rmsResidual")), expected.rmsResidual, 1e-9);
  EXPECT_EQ(std::stoi(values.at("iterations")), expected.iterations);

  std::ifstream f(dir / "plane.mrk.json");
  const auto doc = nlohmann::json::parse(f);
  ASSERT_TRUE(doc.contains("@schema"));
  const auto& m = doc.at("markups").at(0);
  EXPECT_EQ(m.at("type"), "Plane");
  EXPECT_EQ(m.at("coordinateSystem"), "LPS");
  EXPECT_EQ(m.at("planeType"), "pointNormal");
  const auto origin = m.at("controlPoints").at(0).at("position").get<std::vector<double>>();
  const auto n = m.at("normal").get<std::vector<double>>();
  const auto o2b = m.at("objectToBase").get<std::vector<double>>();
  ASSERT_EQ(o2b.size(), 16u);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(origin[i], expected.plane.point(i), 1e-9);
    EXPECT_NEAR(n[i], expected.plane.normal(i), 1e-12);
    EXPECT_NEAR(o2b[4 * i + 2], expected.plane.normal(i), 1e-12); // third column: the normal
  }
  // objectToBase's rotation is orthonormal and right-handed.
  Eigen::Matrix3d rot;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      rot(i, j) = o2b[4 * i + j];
  EXPECT_LT((rot.transpose() * rot - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_NEAR(rot.determinant(), 1.0, 1e-12);
}

TEST(SymmetryPlaneModule, BadInputFailsWithOneLineAndNoOutput)
{
  ScratchDirectory dir("SymmetryPlaneModuleBad");
  // A point cloud without triangles.
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(mmrep::testing::SymmetricHead(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero())->GetPoints());
  mmrep::WriteSurface(cloud, dir / "cloud.vtp");
  std::ofstream(dir / "empty.vtk") << "# vtk DataFile Version 3.0\nempty\nASCII\nDATASET POLYDATA\nPOINTS 0 float\n";
  for (const std::string& input : {dir / "missing.vtp", dir / "empty.vtk", dir / "cloud.vtp"})
  {
    const auto run = RunModuleExecutable(
      "SymmetryPlane", {input, "--outputPlane", dir / "plane.mrk.json", "--returnparameterfile", dir / "ret.txt"});
    EXPECT_NE(run.exitCode, 0) << input;
    ASSERT_EQ(run.ErrLines().size(), 1u) << run.err;
    EXPECT_NE(run.err.find("SymmetryPlane"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "plane.mrk.json")) << input;
    EXPECT_FALSE(std::filesystem::exists(dir / "ret.txt")) << input;
  }
  EXPECT_EQ(dir.Entries().size(), 2u); // only the two inputs written above
}
