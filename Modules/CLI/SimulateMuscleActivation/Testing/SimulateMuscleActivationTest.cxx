// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// SimulateMuscleActivation on the shipped atlas (a speaker model of the bundled CT): two CalculiX
// solves (zygomaticus major left; orbicularis oris peripheralis) and the user-facing errors.
#include "mmrepFEMeshIO.h"
#include "mmrepModuleRunner.h"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>

namespace
{
using namespace mmrep;
using namespace mmrep::testing;
namespace fs = std::filesystem;

const std::string kAtlas = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu";

// Displacement of the skin node nearest to a landmark, read from the written .vtu: a check of the
// module's landmark interpolation that does not use it.
Point3 NearestSkinNodeDisplacement(const std::string& vtu, const FEMesh& rest, const std::string& landmark)
{
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(vtu.c_str());
  reader->Update();
  vtkDataArray* u = reader->GetOutput()->GetPointData()->GetArray("Displacement");
  if (u == nullptr)
    throw std::runtime_error("no Displacement array in " + vtu);
  Point3 p = Point3::Zero();
  for (const auto& l : rest.landmarks)
    if (l.name == landmark)
      p = l.position;
  std::int32_t best = -1;
  for (auto n : rest.nodeSets.at("skin"))
    if (best < 0 ||
        (rest.nodes[static_cast<std::size_t>(n)] - p).norm() < (rest.nodes[static_cast<std::size_t>(best)] - p).norm())
      best = n;
  double t[3];
  u->GetTuple(best, t);
  return Point3(t[0], t[1], t[2]);
}

TEST(SimulateMuscleActivationModule, ZygomaticusMajorLeftRaisesLeftMouthCornerLaterally)
{
  ScratchDirectory dir("zyg");
  const std::string out = dir / "zyg.vtu", png = dir / "zyg.png", lips = dir / "zyg_lips.png", ret = dir / "ret.txt";
  const ModuleRun run = RunModuleExecutable(
    "SimulateMuscleActivation",
    // C3D8 and 30 % of the cited forces (few Newton iterations) for the module's plumbing and
    // directions; the default's figures are asserted on the speaker model (FaceModelPipelineModule).
    {kAtlas, out, "--muscles", "ZygomaticusMajor_L", "--elementType", "C3D8", "--forceScale", "0.3", "--picture", png,
     "--lipsPicture", lips, "--returnparameterfile", ret},
    true);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::printf("%s", run.out.substr(run.out.find("CalculiX:")).c_str());
  EXPECT_NE(run.out.find("CalculiX: converged"), std::string::npos);
  const auto values = ReadReturnParameters(ret);
  const std::vector<double> corner = ReturnVector(values, "leftLipCornerDisplacement");
  ASSERT_EQ(corner.size(), 3u);
  std::printf("LeftLipCorner: lateral (+x) %.3f mm, superior (+z) %.3f mm, |u| %.3f mm; ccx %s s, %s increments\n",
              corner[0], corner[2], std::sqrt(corner[0] * corner[0] + corner[1] * corner[1] + corner[2] * corner[2]),
              values.at("ccxSeconds").c_str(), values.at("increments").c_str());
  EXPECT_GT(corner[0], 0.05); // +x = patient left = lateral for the left corner
  EXPECT_GT(corner[2], 0.05); // upward
  EXPECT_GE(std::stoi(values.at("increments")), 1);
  // 0.3 × the atlas's cited maximum force (3.25 N) on the Hill curve's ascending limb: below it.
  const double force = std::stod(values.at("meanMuscleForce"));
  EXPECT_GT(force, 0.6 * 0.3 * 3.247);
  EXPECT_LT(force, 0.3 * 3.247);

  // The written model: same topology, nodes moved by the Displacement array, corner region moves the same way.
  const FEMesh rest = ReadFEMesh(kAtlas);
  const FEMesh moved = ReadFEMesh(out);
  ASSERT_EQ(moved.nodes.size(), rest.nodes.size());
  ASSERT_EQ(moved.muscles.size(), rest.muscles.size());
  const Point3 near = NearestSkinNodeDisplacement(out, rest, "LeftLipCorner");
  EXPECT_GT(near.x(), 0);
  EXPECT_GT(near.z(), 0);
  double largest = 0;
  for (std::size_t i = 0; i < rest.nodes.size(); ++i)
    largest = std::max(largest, (moved.nodes[i] - rest.nodes[i]).norm());
  EXPECT_NEAR(largest, std::stod(values.at("maxDisplacement")), 1e-6);
  // The bone attachment holds (maxilla and, with the jaw at rest, mandible); the skull nodes over the
  // teeth are in neither and may move.
  for (const char* set : {"maxilla", "mandible"})
    for (auto n : rest.nodeSets.at(set))
      EXPECT_EQ(moved.nodes[static_cast<std::size_t>(n)], rest.nodes[static_cast<std::size_t>(n)]);
  EXPECT_TRUE(IsPNG(png));
  EXPECT_TRUE(IsPNG(lips));
}

TEST(SimulateMuscleActivationModule, OrbicularisOrisPeripheralisProtrudesAndClosesLips)
{
  ScratchDirectory dir("oop");
  const std::string out = dir / "oop.vtu", ret = dir / "ret.txt";
  const ModuleRun run = RunModuleExecutable(
    "SimulateMuscleActivation",
    {kAtlas, out, "--muscles",
     "OrbicularisOrisPeripheralisUpper_L,OrbicularisOrisPeripheralisUpper_R,OrbicularisOrisPeripheralisLower_L,"
     "OrbicularisOrisPeripheralisLower_R",
     "--elementType", "C3D8", "--returnparameterfile", ret});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::printf("%s", run.out.substr(run.out.find("CalculiX:")).c_str());
  const auto values = ReadReturnParameters(ret);
  const std::vector<double> upper = ReturnVector(values, "upperLipCenterDisplacement");
  const std::vector<double> lower = ReturnVector(values, "lowerLipCenterDisplacement");
  std::printf(
    "UpperLipCenter: anterior (-y) %.3f mm, superior %.3f mm; LowerLipCenter: anterior %.3f mm, superior %.3f mm; "
    "lip gap change %.3f mm\n",
    -upper[1], upper[2], -lower[1], lower[2], upper[2] - lower[2]);
  EXPECT_LT(upper[1], -0.15);            // forward (anterior is -y in LPS); measured 0.233 mm
  EXPECT_LT(lower[1], -0.02);            // measured 0.039 mm with the cited 0.43 N per track
  EXPECT_LT(upper[2] - lower[2], -0.05); // the centres move toward each other (the gap closes)
  EXPECT_LT(upper[2], 0);                // the upper lip moves down
}

TEST(SimulateMuscleActivationModule, UnknownMuscleListsTheValidNames)
{
  ScratchDirectory dir("unknown");
  const ModuleRun run =
    RunModuleExecutable("SimulateMuscleActivation", {kAtlas, dir / "o.vtu", "--muscles", "zygomaticusMajor_L"});
  EXPECT_EQ(run.exitCode, 1);
  ASSERT_EQ(run.ErrLines().size(), 1u) << run.err;
  EXPECT_NE(run.err.find("unknown muscle 'zygomaticusMajor_L'"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("ZygomaticusMajor_L"), std::string::npos);
  EXPECT_NE(run.err.find("OrbicularisOrisPeripheralisUpper_R"), std::string::npos);
  EXPECT_TRUE(dir.Entries().empty());
}

TEST(SimulateMuscleActivationModule, ModelWithoutMusclesIsRefused)
{
  ScratchDirectory dir("nomuscle");
  FEMesh mesh = ReadFEMesh(kAtlas);
  mesh.muscles.clear();
  std::vector<Element> solids;
  for (const auto& e : mesh.elements)
    if (e.type != ElementType::Cable)
      solids.push_back(e);
  mesh.elements = solids;
  std::vector<std::string> muscleSets;
  for (auto it = mesh.elementSets.begin(); it != mesh.elementSets.end();)
    it = (it->first == "epidermis" || it->first == "dermis" || it->first == "hypodermis") ? std::next(it)
                                                                                          : mesh.elementSets.erase(it);
  mesh.nodes.resize(mesh.nodes.size()); // muscle nodes stay as unused nodes
  WriteFEMesh(mesh, dir / "plain.vtu");
  const ModuleRun run = RunModuleExecutable("SimulateMuscleActivation",
                                            {dir / "plain.vtu", dir / "o.vtu", "--muscles", "ZygomaticusMajor_L"});
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("has no muscles"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir / "o.vtu"));
}

TEST(SimulateMuscleActivationModule, MissingCalculiXIsReported)
{
  ScratchDirectory dir("noccx");
  const ModuleRun run = RunModuleExecutable(
    "SimulateMuscleActivation", {kAtlas, dir / "o.vtu", "--muscles", "ZygomaticusMajor_L", "--ccx", "ccx-missing"});
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("not found on PATH: install the Debian package calculix-ccx"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir / "o.vtu"));
}

} // namespace
