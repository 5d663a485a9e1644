// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// FaceModelPipeline end to end on the bundled real CT with its shipped control points: the model,
// its exports read by tools nobody here wrote (VTK, Gmsh, CalculiX), the report re-measured
// independently, the pictures; muscle activation of that speaker model with CalculiX (issue 8);
// and the user-facing errors.
#include "mmrepFEMeshIO.h"
#include "mmrepLipContact.h"
#include "mmrepModuleRunner.h"

#include <nlohmann/json.hpp>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkGenericCell.h>
#include <vtkMeshQuality.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

namespace
{
using namespace mmrep;
using namespace mmrep::testing;
namespace fs = std::filesystem;

const std::string kCT = std::string(MMREP_SOURCE_DIR) + "/Resources/SampleData/cthead.nrrd";
const std::string kPoints = std::string(MMREP_SOURCE_DIR) + "/Resources/SampleData/cthead.ControlPoints.mrk.json";

int Shell(const std::string& command)
{
  const int status = std::system((command + " > /dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

// Mean distance of the nodes of `set` to the triangles of a .vtp, with VTK's own locator.
double MeanDistanceWithVTK(const FEMesh& mesh, const std::string& set, const fs::path& vtp)
{
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(vtp.c_str());
  reader->Update();
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(reader->GetOutput());
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  double sum = 0;
  for (auto n : mesh.nodeSets.at(set))
  {
    double closest[3], d2;
    vtkIdType id;
    int sub;
    locator->FindClosestPoint(mesh.nodes[static_cast<std::size_t>(n)].data(), closest, cell, id, sub, d2);
    sum += std::sqrt(d2);
  }
  return sum / static_cast<double>(mesh.nodeSets.at(set).size());
}

TEST(FaceModelPipelineModule, BundledCTGivesAValidModelReportAndPictures)
{
  ScratchDirectory dir("pipeline");
  const fs::path out = dir.path() / "speaker";
  const std::string ret = dir / "ret.txt";
  const ModuleRun run = RunModuleExecutable(
    "FaceModelPipeline", {kCT, kPoints, "--outputDirectory", out.string(), "--returnparameterfile", ret}, true);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::printf("%s", run.out.substr(run.out.find("Model:")).c_str());
  for (const char* f : {"model.vtu", "model.inp", "model.feb", "model.msh", "transform.nrrd", "skin.vtp", "skull.vtp",
                        "landmarks.mrk.json", "report.json", "report.md"})
    EXPECT_GT(fs::exists(out / f) ? fs::file_size(out / f) : 0u, 100u) << f;
  for (const char* f : {"model-skin-error.png", "lips.png", "muscles.png"})
    EXPECT_TRUE(IsPNG(out / f)) << f;
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos)
      << "staging directory left: " << e.path();

  // VTK reads the model with its arrays; VTK's quality filter agrees with the report.
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((out / "model.vtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  const FEMesh model = ReadFEMesh((out / "model.vtu").string());
  ASSERT_EQ(grid->GetNumberOfPoints(), static_cast<vtkIdType>(model.nodes.size()));
  EXPECT_NE(grid->GetCellData()->GetArray("Layer"), nullptr);
  EXPECT_EQ(model.muscles.size(), 26u);
  EXPECT_EQ(model.landmarks.size(), 5u);
  vtkNew<vtkMeshQuality> quality;
  quality->SetInputData(grid);
  quality->SetHexQualityMeasureToScaledJacobian();
  quality->Update();
  vtkDataArray* q = quality->GetOutput()->GetCellData()->GetArray("Quality");
  double minQ = 2;
  std::size_t hexes = 0;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    if (grid->GetCellType(c) == VTK_HEXAHEDRON)
    {
      minQ = std::min(minQ, q->GetTuple1(c));
      ++hexes;
    }
  EXPECT_EQ(hexes, 11016u);
  EXPECT_GE(minQ, 0.3 - 1e-9);

  // The report: numbers measured on the written mesh against the written surfaces.
  std::ifstream rj(out / "report.json");
  const auto report = nlohmann::json::parse(rj);
  const auto& final = report.at("accuracy").back();
  EXPECT_NEAR(final.at("skin").at("mean").get<double>(), MeanDistanceWithVTK(model, "skin", out / "skin.vtp"), 1e-6);
  EXPECT_NEAR(final.at("skull").at("mean").get<double>(), MeanDistanceWithVTK(model, "skull", out / "skull.vtp"), 1e-6);
  EXPECT_NEAR(final.at("lips").at("mean").get<double>(), MeanDistanceWithVTK(model, "lips", out / "skin.vtp"), 1e-6);
  EXPECT_NEAR(report.at("quality").at("afterRepair").at("minScaledJacobian").get<double>(), minQ, 1e-9);
  // Accuracy on the atlas's own CT, on the fitted half (issue 13's targets: skin 0.15, skull 0.25 mm
  // mean; the paper's repaired figures: 0.3, 0.5). The whole model's right half is the mirror image
  // of the left, and this head is asymmetric by about 1.2 mm RMS.
  EXPECT_EQ(report.at("fitted").get<std::string>().rfind("left half", 0), 0u);
  const auto& half = final.at("fittedHalf");
  EXPECT_LT(half.at("skin").at("mean").get<double>(), 0.15);
  EXPECT_LT(half.at("skull").at("mean").get<double>(), 0.25);
  EXPECT_LT(half.at("skin").at("nodes").get<double>(), final.at("skin").at("nodes").get<double>());
  EXPECT_LT(final.at("skin").at("mean").get<double>(), 1.0);
  EXPECT_LT(final.at("controlPoints").at("max").get<double>(), 1.0);
  const auto values = ReadReturnParameters(ret);
  EXPECT_NEAR(std::stod(values.at("skinMeanError")), final.at("skin").at("mean").get<double>(), 1e-6);

  // Gmsh loads the .msh; the .feb holds the model's node and element counts.
  const std::string gmshLog = (dir.path() / "gmsh.log").string();
  // (Not Shell(): it sends the output to /dev/null.)
  const int status =
    std::system(("gmsh -check '" + (out / "model.msh").string() + "' > '" + gmshLog + "' 2>&1").c_str());
  const int gmsh = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
  EXPECT_NE(Slurp(gmshLog).find("Checking for duplicate nodes"), std::string::npos) << Slurp(gmshLog);
  EXPECT_EQ(gmsh, 0) << Slurp(gmshLog);
  // Gmsh's findings are Error and Warning lines: none, the mouth slit's twins included (they are
  // written a hair apart, below Gmsh's duplicate tolerance of 1e-8 of the model's size ×100).
  EXPECT_EQ(Slurp(gmshLog).find("Error"), std::string::npos) << Slurp(gmshLog);
  EXPECT_EQ(Slurp(gmshLog).find("already exists in the mesh"), std::string::npos) << Slurp(gmshLog);
  {
    FEMesh closed = model;
    const auto twins = CloseMouth(closed).twins;
    ASSERT_FALSE(twins.empty());
    // The written twins: apart by more than Gmsh's tolerance, by far less than anything measured.
    std::istringstream msh(Slurp(out / "model.msh"));
    std::string line;
    while (std::getline(msh, line) && line != "$Nodes")
    {
    }
    std::size_t blocks = 0, count = 0;
    msh >> blocks >> count;
    std::getline(msh, line);
    std::getline(msh, line); // the one block's header
    for (std::size_t i = 0; i < count; ++i)
      std::getline(msh, line); // tags
    std::vector<Point3> written(count);
    for (auto& p : written)
      msh >> p.x() >> p.y() >> p.z();
    ASSERT_EQ(written.size(), model.nodes.size());
    Point3 lo = model.nodes.front(), hi = lo;
    for (const auto& x : model.nodes)
    {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    for (const auto& [upper, lower] : twins)
    {
      const double gap = (written[static_cast<std::size_t>(upper)] - written[static_cast<std::size_t>(lower)]).norm();
      EXPECT_GT(gap, 1e-8 * (hi - lo).norm());
      EXPECT_LT(gap, 1e-3); // mm
    }
  }
  // The lips' contact surfaces in all three formats.
  EXPECT_NE(Slurp(out / "model.msh").find("\"upperLipContactFaces\""), std::string::npos);
  EXPECT_NE(Slurp(out / "model.inp").find("*SURFACE, NAME=S_LOWERLIP, TYPE=ELEMENT"), std::string::npos);
  EXPECT_NE(Slurp(out / "model.feb").find("<contact type=\"sliding-elastic\" surface_pair=\"lips\">"),
            std::string::npos);
  const std::string feb = Slurp(out / "model.feb");
  const auto count = [&](const std::regex& r) {
    return static_cast<std::size_t>(
      std::distance(std::sregex_iterator(feb.begin(), feb.end(), r), std::sregex_iterator()));
  };
  EXPECT_EQ(count(std::regex("<node id=")), model.nodes.size());
  EXPECT_EQ(count(std::regex("<elem id=")), model.elements.size());

  // CalculiX reads the .inp as written and completes a static step: skull clamped, muscle nodes
  // held, the skin pulled 0.1 mm forward.
  const fs::path job = dir.path() / "ccx";
  fs::create_directories(job);
  const std::string inp = Slurp(out / "model.inp");
  std::string holdMuscles; // muscle nodes are embedded by the simulation deck, not by the export
  const std::regex muscleSet("\\*NSET, NSET=(muscle_[A-Za-z0-9_]+)");
  for (auto it = std::sregex_iterator(inp.begin(), inp.end(), muscleSet); it != std::sregex_iterator(); ++it)
    holdMuscles += (*it)[1].str() + ", 1, 3\n";
  ASSERT_FALSE(holdMuscles.empty());
  std::ofstream(job / "job.inp") << inp << R"(*MATERIAL, NAME=TISSUE
*ELASTIC
0.02, 0.45
*SOLID SECTION, ELSET=ESOLID, MATERIAL=TISSUE
*MATERIAL, NAME=FIBRE
*ELASTIC
0.5, 0.3
*SOLID SECTION, ELSET=ECABLE, MATERIAL=FIBRE
0.25
*BOUNDARY
skull, 1, 3
)" << holdMuscles << R"(*STEP
*STATIC
*BOUNDARY
skin, 2, 2, -0.1
*NODE FILE
U
*END STEP
)";
  const int ccx = Shell("cd '" + job.string() + "' && OMP_NUM_THREADS=1 ccx -i job");
  EXPECT_EQ(ccx, 0) << Slurp(job / "job.sta");
  EXPECT_NE(Slurp(job / "job.frd").find("DISP"), std::string::npos);
}

// The default speaker model's gestures (smile, rounding, jaw opening) with CalculiX: SpeechGestures.*
// (FaceModelGesturesTest.cxx).

// Bad input: one line on stderr, exit code 1, and no output directory presented as a result.
void ExpectCleanFailure(const ModuleRun& run, const fs::path& out, const std::string& message)
{
  EXPECT_EQ(run.exitCode, 1) << run.err;
  EXPECT_EQ(run.ErrLines().size(), 1u) << run.err;
  EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
  for (const auto& e : fs::directory_iterator(out.parent_path()))
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << e.path();
}

TEST(FaceModelPipelineModule, BadInputFailsCleanly)
{
  ScratchDirectory dir("pipeline-bad");
  const fs::path out = dir.path() / "speaker";
  // No control points file.
  ExpectCleanFailure(RunModuleExecutable("FaceModelPipeline", {kCT, dir / "none.mrk.json", "--outputDirectory",
                                                               out.string(), "--noPictures"}),
                     out, "none.mrk.json");
  // An empty list of control points.
  std::ofstream(dir / "empty.mrk.json")
    << R"({"markups": [{"type": "Fiducial", "coordinateSystem": "LPS", "controlPoints": []}]})";
  ExpectCleanFailure(RunModuleExecutable("FaceModelPipeline", {kCT, dir / "empty.mrk.json", "--outputDirectory",
                                                               out.string(), "--noPictures"}),
                     out, "control points");
  // A control point outside the volume (here: the file's points shifted 1 m).
  std::string shifted = Slurp(kPoints);
  shifted = std::regex_replace(shifted, std::regex("\"position\": \\[\\s*([-0-9.e]+)"), "\"position\": [$1e3");
  ASSERT_NE(shifted, Slurp(kPoints));
  std::ofstream(dir / "far.mrk.json") << shifted;
  ExpectCleanFailure(RunModuleExecutable("FaceModelPipeline", {kCT, dir / "far.mrk.json", "--outputDirectory",
                                                               out.string(), "--noPictures"}),
                     out, "outside the CT volume");
  // A CT without a head: a uniform block of air (its five points all at one place, which the
  // plausibility checks would refuse first: trusted here).
  std::ofstream air(dir / "air.nrrd");
  air << "NRRD0004\ntype: short\ndimension: 3\nsizes: 24 24 24\nspace: left-posterior-superior\n"
         "space directions: (4,0,0) (0,4,0) (0,0,4)\nspace origin: (0,0,0)\nencoding: ascii\n\n";
  for (int i = 0; i < 24 * 24 * 24; ++i)
    air << "-1000\n";
  air.close();
  std::string nearAir =
    std::regex_replace(Slurp(kPoints), std::regex("\"position\": \\[[^\\]]*\\]"), "\"position\": [40, 40, 40]");
  std::ofstream(dir / "inair.mrk.json") << nearAir;
  const ModuleRun noHead =
    RunModuleExecutable("FaceModelPipeline", {dir / "air.nrrd", dir / "inair.mrk.json", "--outputDirectory",
                                              out.string(), "--noPictures", "--trustControlPoints"});
  const ModuleRun coincident = RunModuleExecutable(
    "FaceModelPipeline", {dir / "air.nrrd", dir / "inair.mrk.json", "--outputDirectory", out.string(), "--noPictures"});
  EXPECT_EQ(coincident.exitCode, 1) << coincident.err;
  EXPECT_NE(coincident.err.find("control points: they place no face (coincident or collinear)"), std::string::npos)
    << coincident.err;
  EXPECT_EQ(noHead.exitCode, 1) << noHead.err;
  EXPECT_EQ(noHead.ErrLines().size(), 1u) << noHead.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_NE(noHead.err.find("skin threshold"), std::string::npos) << noHead.err;
  // An unwritable output directory (its parent is a regular file).
  std::ofstream(dir / "file") << "x";
  const fs::path under = dir.path() / "file" / "speaker";
  const ModuleRun unwritable =
    RunModuleExecutable("FaceModelPipeline", {kCT, kPoints, "--outputDirectory", under.string(), "--noPictures"});
  EXPECT_EQ(unwritable.exitCode, 1);
  EXPECT_EQ(unwritable.ErrLines().size(), 1u) << unwritable.err;
  EXPECT_NE(unwritable.err.find((dir.path() / "file").string()), std::string::npos) << unwritable.err;
}

} // namespace
