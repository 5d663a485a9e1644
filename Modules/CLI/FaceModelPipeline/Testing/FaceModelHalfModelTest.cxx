// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The half-face model of the speaker model of the bundled CT (FaceModelPipeline --halfModel): the
// cut against the full model, and issue 14's half-face simulation: the symmetric smile (both
// zygomatici majores) on the full model against the left one on the half, landmark by landmark.
#include "mmrepFEMeshIO.h"
#include "mmrepJaw.h"
#include "mmrepModuleRunner.h"
#include "mmrepPlane.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

namespace
{
using namespace mmrep;
using namespace mmrep::testing;
namespace fs = std::filesystem;

const std::string kCT = std::string(MMREP_SOURCE_DIR) + "/Resources/SampleData/cthead.nrrd";
const std::string kPoints = std::string(MMREP_SOURCE_DIR) + "/Resources/SampleData/cthead.ControlPoints.mrk.json";

// Landmark displacements: the deformed model's landmarks (moved by the module) minus the rest ones.
std::map<std::string, Point3> LandmarkMotion(const FEMesh& rest, const std::string& deformedPath)
{
  const FEMesh moved = ReadFEMesh(deformedPath);
  std::map<std::string, Point3> out;
  for (std::size_t k = 0; k < rest.landmarks.size() && k < moved.landmarks.size(); ++k)
    out[rest.landmarks[k].name] = moved.landmarks[k].position - rest.landmarks[k].position;
  return out;
}

// Every landmark of the half model moves like the full model's: within 5 % of its motion (of a
// tenth of the largest motion for landmarks that barely move).
void ExpectHalfMatchesFull(const FEMesh& full, const std::string& fullOut, const FEMesh& half,
                           const std::string& halfOut)
{
  const auto fullMotion = LandmarkMotion(full, fullOut), halfMotion = LandmarkMotion(half, halfOut);
  ASSERT_EQ(halfMotion.size(), half.landmarks.size());
  double largest = 0;
  for (const auto& [name, u] : fullMotion)
    largest = std::max(largest, u.norm());
  for (const auto& [name, uh] : halfMotion)
  {
    ASSERT_EQ(fullMotion.count(name), 1u) << name;
    const Point3& uf = fullMotion.at(name);
    const double diff = (uh - uf).norm();
    std::printf("  %-20s full (%7.3f %7.3f %7.3f)  half (%7.3f %7.3f %7.3f)  difference %.4f mm = %.2f %%\n",
                name.c_str(), uf.x(), uf.y(), uf.z(), uh.x(), uh.y(), uh.z(), diff,
                100 * diff / std::max(uf.norm(), 1e-12));
    EXPECT_LE(diff, 0.05 * std::max(uf.norm(), 0.1 * largest)) << name;
  }
}

fs::path SpeakerWithHalfModel(const ScratchDirectory& dir)
{
  const fs::path out = dir.path() / "speaker";
  const ModuleRun pipeline = RunModuleExecutable(
    "FaceModelPipeline", {kCT, kPoints, "--outputDirectory", out.string(), "--noPictures", "--halfModel"});
  EXPECT_EQ(pipeline.exitCode, 0) << pipeline.err;
  return out;
}
} // namespace

TEST(FaceModelPipelineModule, HalfModelOfTheSpeakerSimulatesTheSymmetricSmileLikeTheFullModel)
{
  ScratchDirectory dir("halfmodel");
  const fs::path out = SpeakerWithHalfModel(dir);
  for (const char* f : {"half-model.vtu", "half-model.inp", "half-model.feb", "half-model.msh"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const FEMesh full = ReadFEMesh((out / "model.vtu").string());
  const FEMesh half = ReadFEMesh((out / "half-model.vtu").string());

  // The cut, against the full model: half of the solids (the model is symmetric), the nodes of the
  // solids whose centroid is on the left plus the left tracks' nodes, all on the left or the plane.
  const Plane plane = FitPlaneToNodeSet(full, "midsagittal");
  std::set<std::int32_t> leftNodes;
  std::size_t leftSolids = 0;
  for (const auto& e : full.elements)
  {
    if (e.type == ElementType::Cable)
      continue;
    Point3 c = Point3::Zero();
    for (int k = 0; k < NodeCount(e.type); ++k)
      c += full.nodes[static_cast<std::size_t>(e.nodes[k])] / NodeCount(e.type);
    if (plane.SignedDistance(c) > 0)
    {
      ++leftSolids;
      leftNodes.insert(e.nodes.begin(), e.nodes.begin() + NodeCount(e.type));
    }
  }
  std::size_t leftCables = 0;
  for (const auto& [name, track] : full.muscles)
    if (name.compare(name.size() - 2, 2, "_L") == 0)
    {
      leftNodes.insert(track.nodes.begin(), track.nodes.end());
      leftCables += track.cables.size();
    }
  // The left condyle of the jaw axis (a node of no element) is kept too.
  for (auto n : full.nodeSets.at("jawAxis"))
    if (plane.SignedDistance(full.nodes[static_cast<std::size_t>(n)]) > 0)
      leftNodes.insert(n);
  EXPECT_EQ(2 * leftSolids, full.SolidElementCount());
  EXPECT_EQ(half.SolidElementCount(), leftSolids);
  EXPECT_EQ(half.elements.size() - half.SolidElementCount(), leftCables);
  EXPECT_EQ(half.nodes.size(), leftNodes.size());
  for (const auto& p : half.nodes)
    EXPECT_GE(plane.SignedDistance(p), -1e-6);
  EXPECT_EQ(half.nodeSets.at("symmetryBoundary").size(), half.nodeSets.at("midsagittal").size());
  EXPECT_EQ(half.nodeSets.at("skin").size(), [&] {
    std::size_t n = 0;
    for (auto id : full.nodeSets.at("skin"))
      n += leftNodes.count(id);
    return n;
  }());
  EXPECT_NE(Slurp(out / "half-model.inp").find("*TRANSFORM, NSET=symmetryBoundary, TYPE=R"), std::string::npos);
  EXPECT_NE(Slurp(out / "half-model.feb").find("<constraint type=\"symmetry plane\""), std::string::npos);

  // The symmetric smile.
  const std::string fullOut = dir / "full-smile.vtu", halfOut = dir / "half-smile.vtu";
  const std::string fullRet = dir / "full.txt", halfRet = dir / "half.txt";
  const ModuleRun f =
    RunModuleExecutable("SimulateMuscleActivation",
                        {(out / "model.vtu").string(), fullOut, "--muscles", "ZygomaticusMajor_L,ZygomaticusMajor_R",
                         "--elementType", "C3D8", "--returnparameterfile", fullRet},
                        true);
  ASSERT_EQ(f.exitCode, 0) << f.err;
  const ModuleRun h =
    RunModuleExecutable("SimulateMuscleActivation",
                        {(out / "half-model.vtu").string(), halfOut, "--muscles", "ZygomaticusMajor_L", "--elementType",
                         "C3D8", "--returnparameterfile", halfRet},
                        true);
  ASSERT_EQ(h.exitCode, 0) << h.err;
  EXPECT_NE(h.out.find("symmetry-plane nodes"), std::string::npos);
  const auto fv = ReadReturnParameters(fullRet), hv = ReadReturnParameters(halfRet);
  std::printf("speaker model smile: ccx full %s s, half %s s (ratio %.2f)\n", fv.at("ccxSeconds").c_str(),
              hv.at("ccxSeconds").c_str(), std::stod(hv.at("ccxSeconds")) / std::stod(fv.at("ccxSeconds")));

  ExpectHalfMatchesFull(full, fullOut, half, halfOut);
  const auto corner = ReturnVector(hv, "leftLipCornerDisplacement");
  ASSERT_EQ(corner.size(), 3u);
  EXPECT_GT(corner[0], 0.05); // the left corner moves laterally and up, as on the full model
  EXPECT_GT(corner[2], 0.05);

  // A right-side muscle on the half model: one clear line, no output.
  const std::string bad = dir / "bad.vtu";
  const ModuleRun r = RunModuleExecutable("SimulateMuscleActivation",
                                          {(out / "half-model.vtu").string(), bad, "--muscles", "ZygomaticusMajor_R"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.ErrLines().size(), 1u) << r.err;
  EXPECT_NE(r.err.find("right side"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(bad));
}

// Issue 14: the jaw opens on the half model too (its axis: the plane normal through the left
// condyle) and the lips part as on the full model.
TEST(FaceModelPipelineModule, HalfModelOfTheSpeakerOpensTheJawLikeTheFullModel)
{
  ScratchDirectory dir("halfmodel-jaw");
  const fs::path out = SpeakerWithHalfModel(dir);
  const FEMesh full = ReadFEMesh((out / "model.vtu").string());
  const FEMesh half = ReadFEMesh((out / "half-model.vtu").string());
  ASSERT_EQ(half.nodeSets.at("jawAxis").size(), 1u);
  const std::string fullOut = dir / "full-open.vtu", halfOut = dir / "half-open.vtu";
  const std::string fullRet = dir / "full.txt", halfRet = dir / "half.txt";
  for (const auto& [model, vtu, ret] :
       {std::tuple{out / "model.vtu", fullOut, fullRet}, std::tuple{out / "half-model.vtu", halfOut, halfRet}})
  {
    const ModuleRun run = RunModuleExecutable(
      "SimulateMuscleActivation", {model.string(), vtu, "--gesture", "open", "--returnparameterfile", ret}, true);
    ASSERT_EQ(run.exitCode, 0) << run.err;
  }
  const auto fv = ReadReturnParameters(fullRet), hv = ReadReturnParameters(halfRet);
  std::printf("speaker model jaw opening 10 deg: ccx full %s s, half %s s (ratio %.2f)\n", fv.at("ccxSeconds").c_str(),
              hv.at("ccxSeconds").c_str(), std::stod(hv.at("ccxSeconds")) / std::stod(fv.at("ccxSeconds")));
  ExpectHalfMatchesFull(full, fullOut, half, halfOut);
  // The mouth opening measured on each model (the half's width doubles its left half).
  const double fullAperture = std::stod(fv.at("apertureHeight")), halfAperture = std::stod(hv.at("apertureHeight"));
  std::printf("aperture height: full %.3f mm, half %.3f mm\n", fullAperture, halfAperture);
  EXPECT_GE(fullAperture, 5.0);
  EXPECT_NEAR(halfAperture, fullAperture, 0.05 * fullAperture);
  // The half model's mandible rotates about its own axis exactly as the full model's does.
  const FEMesh halfOpen = ReadFEMesh(halfOut);
  const Eigen::Isometry3d jaw = JawRotation(full, 10.0), halfJaw = JawRotation(half, 10.0);
  const Point3 condyle = half.nodes[static_cast<std::size_t>(half.nodeSets.at("jawAxis")[0])];
  EXPECT_LT((jaw * condyle - halfJaw * condyle).norm(), 1e-6);
  for (auto n : half.nodeSets.at("mandible"))
  {
    const Point3 rest = half.nodes[static_cast<std::size_t>(n)];
    EXPECT_LT((halfOpen.nodes[static_cast<std::size_t>(n)] - halfJaw * rest).norm(), 1e-3);
    EXPECT_LT((halfJaw * rest - jaw * rest).norm(), 0.05); // the same rotation as the full model's
  }
}
