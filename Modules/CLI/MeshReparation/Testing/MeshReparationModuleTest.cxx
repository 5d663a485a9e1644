// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// MeshReparation module: runs the executable on generated tangled shells (under xvfb-run when
// there is no display) and checks its files against recomputations from the meshes it wrote.
#include "mmrepFEMeshIO.h"
#include "mmrepCertifiedJacobian.h"
#include "mmrepMeshQuality.h"
#include "mmrepModuleRunner.h"
#include "mmrepSurfaceIO.h"
#include "mmrepTangledMeshGenerator.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkTriangle.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

namespace
{
using namespace mmrep;
using mmrep::testing::ModuleRun;
using mmrep::testing::ReadReturnParameters;
using mmrep::testing::RunModuleExecutable;
using mmrep::testing::ScratchDirectory;
using mmrep::testing::Slurp;

const mmrep::testing::ShellAtlas& Atlas()
{
  static const auto atlas = mmrep::testing::MakeShellAtlas();
  return atlas;
}

// Largest distance of the set's nodes to the surface, by brute force over every triangle.
double MaxDistanceBruteForce(const FEMesh& mesh, const std::string& set, vtkPolyData* surface)
{
  double worst = 0;
  for (const auto id : mesh.nodeSets.at(set))
  {
    double best = std::numeric_limits<double>::infinity();
    for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
    {
      double closest[3], pcoords[3], weights[3], d2 = 0;
      int subId = 0;
      surface->GetCell(c)->EvaluatePosition(mesh.nodes[id].data(), closest, subId, pcoords, d2, weights);
      best = std::min(best, d2);
    }
    worst = std::max(worst, std::sqrt(best));
  }
  return worst;
}

struct Inputs
{
  std::string mesh, skin, skull;
};

Inputs WriteInputs(const ScratchDirectory& dir, const FEMesh& mesh)
{
  Inputs in{dir / "input.vtu", dir / "skin.vtp", dir / "skull.vtp"};
  WriteFEMesh(mesh, in.mesh);
  WriteSurface(Atlas().skin, in.skin);
  WriteSurface(Atlas().skull, in.skull);
  return in;
}

nlohmann::json ReadJSON(const std::string& path)
{
  return nlohmann::json::parse(Slurp(path));
}
} // namespace

TEST(RepairModule, RepairsTangledMeshWithReportAndHistogram)
{
  ScratchDirectory dir("repair-module");
  mmrep::testing::TangleOptions tangle;
  tangle.seed = 11, tangle.symmetric = true, tangle.noise = 0.15, tangle.folds = 3, tangle.warp = 1;
  const FEMesh input = mmrep::testing::Tangle(Atlas(), tangle);
  const Inputs in = WriteInputs(dir, input);
  const ModuleRun run = RunModuleExecutable(
    "MeshReparation",
    {in.mesh, dir / "out.inp", "--skinSurface", in.skin, "--skullSurface", in.skull, "--report", dir / "report.json",
     "--histogram", dir / "histogram.png", "--symmetryPlane", "0,0,0,1,0,0", "--returnparameterfile", dir / "rp.txt"},
    true);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  ASSERT_TRUE(std::filesystem::exists(dir / "out.inp"));
  EXPECT_NE(Slurp(dir / "out.inp").find("*NODE"), std::string::npos);
  // Same run to .vtu to read the result back (deterministic: same nodes as the .inp).
  const ModuleRun vtu =
    RunModuleExecutable("MeshReparation", {in.mesh, dir / "out.vtu", "--skinSurface", in.skin, "--skullSurface",
                                           in.skull, "--symmetryPlane", "0,0,0,1,0,0"});
  ASSERT_EQ(vtu.exitCode, 0) << vtu.err;
  const FEMesh output = ReadFEMesh(dir / "out.vtu");

  const double threshold = 0.3;
  const quality::QualitySummary before = quality::SummarizeScaledJacobian(input, threshold);
  const quality::QualitySummary after = quality::SummarizeScaledJacobian(output, threshold);
  ASSERT_GT(before.inverted, 0u);
  EXPECT_EQ(after.inverted, 0u);
  EXPECT_EQ(after.belowThreshold, 0u);
  EXPECT_GE(after.min, threshold);

  const nlohmann::json report = ReadJSON(dir / "report.json");
  EXPECT_TRUE(report["success"].get<bool>());
  EXPECT_EQ(report["quality"]["before"]["minScaledJacobian"].get<double>(), before.min);
  EXPECT_EQ(report["quality"]["before"]["inverted"].get<std::size_t>(), before.inverted);
  EXPECT_EQ(report["quality"]["before"]["belowThreshold"].get<std::size_t>(), before.belowThreshold);
  EXPECT_EQ(report["quality"]["after"]["minScaledJacobian"].get<double>(), after.min);
  EXPECT_EQ(report["quality"]["after"]["meanScaledJacobian"].get<double>(), after.mean);
  EXPECT_EQ(report["quality"]["after"]["belowThreshold"].get<std::size_t>(), after.belowThreshold);
  EXPECT_EQ(report["quality"]["after"]["inverted"].get<std::size_t>(), after.inverted);
  EXPECT_TRUE(report["failedElements"].empty());
  // Surface accuracy against a brute-force recomputation on the output mesh.
  for (const auto& [set, surface] :
       {std::pair<std::string, vtkPolyData*>{"skin", Atlas().skin}, {"skull", Atlas().skull}, {"lips", Atlas().skin}})
  {
    EXPECT_NEAR(report["surfaceAccuracy"][set]["after"]["maxDistance"].get<double>(),
                MaxDistanceBruteForce(output, set, surface), 1e-9)
      << set;
    EXPECT_NEAR(report["surfaceAccuracy"][set]["before"]["maxDistance"].get<double>(),
                MaxDistanceBruteForce(input, set, surface), 1e-9)
      << set;
  }
  std::size_t moved = 0;
  for (std::size_t i = 0; i < input.nodes.size(); ++i)
    moved += input.nodes[i] != output.nodes[i] ? 1 : 0;
  EXPECT_EQ(report["movedNodes"].get<std::size_t>(), moved);

  const auto rp = ReadReturnParameters(dir / "rp.txt");
  EXPECT_EQ(rp.at("success"), "true");
  EXPECT_EQ(std::stoul(rp.at("invertedBefore")), before.inverted);
  EXPECT_EQ(std::stoul(rp.at("invertedAfter")), 0u);
  EXPECT_EQ(std::stoul(rp.at("belowThresholdAfter")), 0u);
  EXPECT_EQ(std::stoul(rp.at("movedNodes")), moved);
  EXPECT_NEAR(std::stod(rp.at("minScaledJacobianAfter")), after.min, 1e-9);
  EXPECT_NEAR(std::stod(rp.at("minScaledJacobianBefore")), before.min, 1e-9);
  // Validity inside: the certificate of the mesh as read back, and of the input, exactly.
  const auto certifiedIn = mmrep::quality::CertifyMesh(input), certifiedOut = mmrep::quality::CertifyMesh(output);
  EXPECT_EQ(std::stoul(rp.at("notCertifiedBefore")), certifiedIn.NotValid());
  EXPECT_EQ(std::stoul(rp.at("notCertifiedAfter")), certifiedOut.NotValid());
  EXPECT_GE(certifiedIn.NotValid(), before.inverted); // an element inverted at a corner is never certified
  EXPECT_NEAR(std::stod(rp.at("certifiedMinimumAfter")), certifiedOut.minimumLower, 1e-6);
  EXPECT_EQ(report["quality"]["after"]["notCertifiedInside"].get<std::size_t>(), certifiedOut.NotValid());

  // The histogram: two panels side by side with red (below threshold) bars before, blue after.
  vtkNew<vtkPNGReader> png;
  png->SetFileName((dir / "histogram.png").c_str());
  png->Update();
  int dims[3];
  png->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 1120);
  EXPECT_EQ(dims[1], 420);
  auto count = [&](int x0, int x1, int r, int g, int b) {
    int n = 0;
    for (int y = 0; y < dims[1]; ++y)
      for (int x = x0; x < x1; ++x)
      {
        const auto* p = static_cast<unsigned char*>(png->GetOutput()->GetScalarPointer(x, y, 0));
        n += (p[0] == r && p[1] == g && p[2] == b) ? 1 : 0;
      }
    return n;
  };
  EXPECT_GT(count(0, 560, 215, 60, 50), 50);   // red bars before
  EXPECT_EQ(count(560, 1120, 215, 60, 50), 0); // none after
  EXPECT_GT(count(560, 1120, 60, 110, 200), 500);
}

TEST(RepairModule, HopelessMeshFailsWritesReportButNoMesh)
{
  ScratchDirectory dir("repair-module");
  FEMesh mesh = Atlas().mesh;
  // An epidermis element in the middle of the face, all 8 nodes collapsed onto one skin node and
  // all of them bound to the skin: at best it can become flat on the skin, never valid.
  const std::size_t collapsed = 250;
  const Point3 onSkin = mesh.nodes[mesh.elements[collapsed].nodes[0]];
  auto& skin = mesh.nodeSets["skin"];
  for (int k = 0; k < 8; ++k)
  {
    mesh.nodes[mesh.elements[collapsed].nodes[k]] = onSkin;
    skin.push_back(mesh.elements[collapsed].nodes[k]);
  }
  std::sort(skin.begin(), skin.end());
  skin.erase(std::unique(skin.begin(), skin.end()), skin.end());
  const Inputs in = WriteInputs(dir, mesh);
  const ModuleRun run =
    RunModuleExecutable("MeshReparation",
                        {in.mesh, dir / "out.vtu", "--skinSurface", in.skin, "--skullSurface", in.skull, "--report",
                         dir / "report.json", "--histogram", dir / "histogram.png"},
                        true);
  EXPECT_EQ(run.exitCode, 1);
  ASSERT_EQ(run.ErrLines().size(), 1u) << run.err;
  EXPECT_NE(run.err.find("elements stay below the scaled Jacobian threshold"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("(worst: element "), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.vtu"));
  EXPECT_TRUE(std::filesystem::exists(dir / "histogram.png"));
  const nlohmann::json report = ReadJSON(dir / "report.json");
  EXPECT_FALSE(report["success"].get<bool>());
  EXPECT_TRUE(report["output"].is_null());
  bool listed = false;
  for (const auto& f : report["failedElements"])
    listed = listed || f["element"].get<std::size_t>() == collapsed;
  EXPECT_TRUE(listed);
  EXPECT_EQ(report["quality"]["after"]["belowThreshold"].get<std::size_t>(), report["failedElements"].size());
  for (const auto& name : dir.Entries())
    EXPECT_EQ(name.find("mmrep-tmp"), std::string::npos) << name;
}

TEST(RepairModule, ValidMeshWrittenUnchanged)
{
  ScratchDirectory dir("repair-module");
  const Inputs in = WriteInputs(dir, Atlas().mesh);
  const ModuleRun run =
    RunModuleExecutable("MeshReparation", {in.mesh, dir / "out.vtu", "--returnparameterfile", dir / "rp.txt"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const FEMesh output = ReadFEMesh(dir / "out.vtu");
  ASSERT_EQ(output.nodes.size(), Atlas().mesh.nodes.size());
  for (std::size_t i = 0; i < output.nodes.size(); ++i)
    ASSERT_EQ(std::memcmp(output.nodes[i].data(), Atlas().mesh.nodes[i].data(), 3 * sizeof(double)), 0) << i;
  EXPECT_EQ(ReadReturnParameters(dir / "rp.txt").at("movedNodes"), "0");
}

TEST(RepairModule, BadInputsFailWithOneLineAndNoOutput)
{
  ScratchDirectory dir("repair-module");
  // Missing input file.
  ModuleRun run = RunModuleExecutable("MeshReparation", {dir / "missing.vtu", dir / "out.vtu"});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_EQ(run.ErrLines().size(), 1u) << run.err;
  EXPECT_NE(run.err.find("missing.vtu"), std::string::npos) << run.err;
  // An empty mesh.
  {
    vtkNew<vtkUnstructuredGrid> empty;
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetInputData(empty);
    writer->SetFileName((dir / "empty.vtu").c_str());
    ASSERT_EQ(writer->Write(), 1);
  }
  run = RunModuleExecutable("MeshReparation", {dir / "empty.vtu", dir / "out.vtu"});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_EQ(run.ErrLines().size(), 1u) << run.err;
  // A missing surface, and a wrong symmetry plane.
  const Inputs in = WriteInputs(dir, Atlas().mesh);
  run = RunModuleExecutable("MeshReparation", {in.mesh, dir / "out.vtu", "--skinSurface", dir / "nosuch.vtp"});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_EQ(run.ErrLines().size(), 1u) << run.err;
  EXPECT_NE(run.err.find("nosuch.vtp"), std::string::npos) << run.err;
  run = RunModuleExecutable("MeshReparation", {in.mesh, dir / "out.vtu", "--symmetryPlane", "0,0,0,1"});
  EXPECT_NE(run.exitCode, 0);
  EXPECT_EQ(run.ErrLines().size(), 1u) << run.err;
  EXPECT_NE(run.err.find("symmetryPlane"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.vtu"));
}
