// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// LocalRefinement as a user runs it on a registered synthetic atlas.
#include "mmrepAtlasRegistration.h"
#include "mmrepElasticTestData.h"
#include "mmrepFEMeshIO.h"
#include "mmrepModuleRunner.h"
#include "mmrepSurfaceIO.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

using namespace mmrep::elastictest;
using mmrep::testing::ReadReturnParameters;
using mmrep::testing::RunModuleExecutable;
using mmrep::testing::ScratchDirectory;

TEST(ElasticLocalRefinementModule, RefinesTheLipsAndLeavesTheRestBitIdentical)
{
  ScratchDirectory dir("localref");
  const auto atlas = MakeAtlas();
  const Truth truth;
  mmrep::SubjectData subject;
  subject.skin = MakeSurface(SkinRadii(), truth);
  subject.skull = MakeSurface(SkullRadii(), truth);
  subject.controlPoints = SubjectControlPoints(atlas.mesh, truth);
  subject.plane = truth.SubjectPlane();
  // A coarse R (level 1 only) leaves the lips for Q to fit.
  mmrep::AtlasRegistrationOptions coarse;
  coarse.finestLevel = 1;
  const auto registered = mmrep::RegisterAtlas(atlas.mesh, atlas.plane, subject, coarse).mesh;
  mmrep::WriteFEMesh(registered, dir / "registered.vtu");
  mmrep::WriteSurface(subject.skin, dir / "skin.vtp");
  const auto run =
    RunModuleExecutable("LocalRefinement", {dir / "registered.vtu", dir / "skin.vtp", dir / "out.vtu", "--report",
                                            dir / "report.json", "--returnparameterfile", dir / "values.txt"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto values = ReadReturnParameters(dir / "values.txt");
  const double before = std::stod(values.at("lipsMeanBefore")), after = std::stod(values.at("lipsMeanAfter"));
  EXPECT_LT(after, before);
  EXPECT_LE(after, 0.05);
  EXPECT_LE(std::stod(values.at("lipsMaxAfter")), 0.15);
  // Nodes far from the lips (the skull layer behind the forehead and all nodes above the eyes)
  // are read back exactly as written.
  const auto in = mmrep::ReadFEMesh(dir / "registered.vtu");
  const auto out = mmrep::ReadFEMesh(dir / "out.vtu");
  ASSERT_EQ(in.nodes.size(), out.nodes.size());
  std::size_t same = 0, moved = 0;
  for (std::size_t i = 0; i < in.nodes.size(); ++i)
    (in.nodes[i] == out.nodes[i] ? same : moved)++;
  EXPECT_GT(same, in.nodes.size() / 2);
  EXPECT_GT(moved, 50u);
  const auto json = nlohmann::json::parse(mmrep::testing::Slurp(dir / "report.json"));
  EXPECT_DOUBLE_EQ(json["after"]["region"]["mean"].get<double>(), after);
  // Same run with a Markdown report: the Q∘R row holds the region's errors.
  const auto md = RunModuleExecutable(
    "LocalRefinement", {dir / "registered.vtu", dir / "skin.vtp", dir / "out2.vtu", "--report", dir / "report.md"});
  ASSERT_EQ(md.exitCode, 0) << md.err;
  const auto text = mmrep::testing::Slurp(dir / "report.md");
  char cells[64];
  std::snprintf(cells, sizeof(cells), "| %.3f | %.3f |", after, std::stod(values.at("lipsMaxAfter")));
  const auto row = text.find("| Q∘R |");
  ASSERT_NE(row, std::string::npos) << text;
  EXPECT_NE(text.substr(row, text.find('\n', row) - row).find(cells), std::string::npos) << text;
}

TEST(ElasticLocalRefinementModule, BadInputGivesOneLineAndNoOutput)
{
  ScratchDirectory dir("localbad");
  const auto atlas = MakeAtlas();
  mmrep::WriteFEMesh(atlas.mesh, dir / "mesh.vtu");
  mmrep::WriteSurface(MakeSurface(SkinRadii(), Truth{}, 5.0), dir / "skin.vtp");
  auto run =
    RunModuleExecutable("LocalRefinement", {dir / "mesh.vtu", dir / "skin.vtp", dir / "out.vtu", "--nodeSet", "nose"});
  EXPECT_EQ(run.exitCode, 1);
  ASSERT_EQ(run.ErrLines().size(), 1u) << run.err;
  EXPECT_NE(run.err.find("'nose'"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.vtu"));
  run = RunModuleExecutable("LocalRefinement", {dir / "mesh.vtu", dir / "missing.vtp", dir / "out.vtu"});
  EXPECT_EQ(run.exitCode, 1);
  ASSERT_EQ(run.ErrLines().size(), 1u) << run.err;
  EXPECT_NE(run.err.find("missing.vtp"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.vtu"));
}
