// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Runs build/bin/MeshConvert as a user would and checks its files, stdout and stderr.
#include "mmrepFEMeshIO.h"
#include "mmrepHalfModel.h"
#include "mmrepFETestMesh.h"
#include "mmrepFETestUtilities.h"

#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <gtest/gtest.h>

#include <set>

namespace fs = std::filesystem;
using mmrep::testing::ReadText;
using mmrep::testing::Run;

namespace
{

std::string Quote(const fs::path& p)
{
  return "'" + p.string() + "'";
}

mmrep::testing::CommandResult Convert(const fs::path& in, const fs::path& out, const fs::path& dir)
{
  return Run(std::string("'") + MESHCONVERT_EXECUTABLE + "' " + Quote(in) + " " + Quote(out), dir);
}

std::set<std::string> Listing(const fs::path& dir)
{
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().rfind("command.", 0) != 0)
      names.insert(entry.path().filename().string());
  return names;
}

std::size_t LineCount(const std::string& text)
{
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

} // namespace

TEST(MeshConvert, ConvertsToEveryFormat)
{
  const auto dir = mmrep::testing::ScratchDir("MeshConvert");
  const mmrep::FEMesh mesh = mmrep::testing::MakeTestMesh();
  const auto input = dir / "face.vtu";
  mmrep::WriteFEMesh(mesh, input.string());
  for (const std::string ext : {".vtu", ".vtk", ".inp", ".feb", ".msh"})
  {
    const auto output = dir / ("converted" + ext);
    const auto result = Convert(input, output, dir);
    ASSERT_EQ(result.status, 0) << ext << ": " << result.err;
    EXPECT_TRUE(result.err.empty()) << result.err;
    EXPECT_NE(result.out.find("<filter-start>"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("<filter-progress>"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("<filter-end>"), std::string::npos) << result.out;
    // Same bytes as the library writes directly; VTK formats also read back exactly.
    const auto reference = dir / ("reference" + ext);
    mmrep::WriteFEMesh(mesh, reference.string());
    EXPECT_EQ(ReadText(output), ReadText(reference)) << ext;
    if (ext == ".vtu" || ext == ".vtk")
      mmrep::testing::ExpectSameMesh(mesh, mmrep::ReadFEMesh(output.string()));
  }
  // A legacy .vtk input works as well.
  const auto legacy = dir / "converted.vtk";
  const auto back = dir / "back.vtu";
  ASSERT_EQ(Convert(legacy, back, dir).status, 0);
  mmrep::testing::ExpectSameMesh(mesh, mmrep::ReadFEMesh(back.string()));
}

TEST(MeshConvert, FailuresPrintOneLineAndLeaveNoOutput)
{
  const auto dir = mmrep::testing::ScratchDir("MeshConvert");
  const mmrep::FEMesh mesh = mmrep::testing::MakeTestMesh();
  const auto good = dir / "face.vtu";
  mmrep::WriteFEMesh(mesh, good.string());
  const std::string bytes = ReadText(good);
  const auto truncated = dir / "truncated.vtu";
  std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() * 2 / 3);
  const auto truncatedVtk = dir / "truncated.vtk";
  mmrep::WriteFEMesh(mesh, (dir / "full.vtk").string());
  const std::string vtkBytes = ReadText(dir / "full.vtk");
  std::ofstream(truncatedVtk, std::ios::binary) << vtkBytes.substr(0, vtkBytes.size() * 2 / 3);
  const auto empty = dir / "empty.vtu";
  {
    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkPoints> points;
    grid->SetPoints(points);
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetInputData(grid);
    writer->SetFileName(empty.string().c_str());
    ASSERT_EQ(writer->Write(), 1);
  }
  const auto before = Listing(dir);

  struct Case
  {
    fs::path input, output;
    std::string expected; // part of the error line
  };
  const Case cases[] = {
    {dir / "missing.vtu", dir / "out.inp", "not found"},
    {good, dir / "out.stl", "unsupported extension"},
    {good, dir / "out", "unsupported extension"},
    {empty, dir / "out.feb", "no mesh"},
    {truncated, dir / "out.msh", "truncated.vtu"},
    {truncatedVtk, dir / "out.vtu", "truncated.vtk"},
    {good, dir / "no-such-folder" / "out.vtu", "no-such-folder"},
  };
  for (const auto& c : cases)
  {
    const auto result = Convert(c.input, c.output, dir);
    EXPECT_NE(result.status, 0) << c.input << " -> " << c.output;
    EXPECT_EQ(LineCount(result.err), 1u) << result.err;
    EXPECT_EQ(result.err.rfind("MeshConvert: error:", 0), 0u) << result.err;
    EXPECT_NE(result.err.find(c.expected), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(c.output)) << c.output;
    EXPECT_EQ(Listing(dir), before) << "leftover files after " << c.output; // no temporaries either
  }
  // Missing positional output: command-line error.
  const auto result = mmrep::testing::Run(std::string("'") + MESHCONVERT_EXECUTABLE + "' " + Quote(good), dir);
  EXPECT_NE(result.status, 0);
  EXPECT_EQ(LineCount(result.err), 1u) << result.err;
}

// --half: the atlas's left half, as LeftHalfModel makes it, in every format; a model that cannot be
// cut is one line and no output.
TEST(MeshConvert, HalfWritesTheLeftHalfModel)
{
  const auto dir = mmrep::testing::ScratchDir("MeshConvert");
  const fs::path atlas = fs::path(MMREP_SOURCE_DIR) / "Resources/Atlas/FaceAtlas.vtu";
  const auto half = dir / "half.vtu", inp = dir / "half.inp";
  for (const auto& out : {half, inp})
  {
    const auto result = mmrep::testing::Run(
      std::string("'") + MESHCONVERT_EXECUTABLE + "' --half " + Quote(atlas) + " " + Quote(out), dir);
    ASSERT_EQ(result.status, 0) << result.err;
  }
  mmrep::testing::ExpectSameMesh(mmrep::LeftHalfModel(mmrep::ReadFEMesh(atlas.string())),
                                 mmrep::ReadFEMesh(half.string()));
  EXPECT_NE(ReadText(inp).find("*TRANSFORM, NSET=symmetryBoundary, TYPE=R"), std::string::npos);

  const auto again = dir / "again.vtu";
  const auto result = mmrep::testing::Run(
    std::string("'") + MESHCONVERT_EXECUTABLE + "' --half " + Quote(half) + " " + Quote(again), dir);
  EXPECT_NE(result.status, 0);
  EXPECT_EQ(LineCount(result.err), 1u) << result.err;
  EXPECT_NE(result.err.find("already is a half model"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(again));
}
