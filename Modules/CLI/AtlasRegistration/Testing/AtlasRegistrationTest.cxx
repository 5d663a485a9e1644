// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// AtlasRegistration as a user runs it: synthetic atlas and subject files, planes given or
// estimated, outputs checked against the known truth; bad input gives one line and no output.
#include "mmrepImageIO.h"
#include "mmrepElasticTestData.h"
#include "mmrepFEMeshIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepModuleRunner.h"
#include "mmrepSurfaceIO.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <sstream>

using namespace mmrep::elastictest;
using mmrep::testing::ReadReturnParameters;
using mmrep::testing::RunModuleExecutable;
using mmrep::testing::ScratchDirectory;

namespace
{
struct Inputs
{
  std::string atlas, skin, skull, points, plane;
};

Inputs WriteInputs(const ScratchDirectory& dir, const Truth& truth = {})
{
  const auto atlas = MakeAtlas();
  Inputs in{dir / "atlas.vtu", dir / "skin.vtp", dir / "skull.vtp", dir / "points.mrk.json", ""};
  mmrep::WriteFEMesh(atlas.mesh, in.atlas);
  mmrep::WriteSurface(MakeSurface(SkinRadii(), truth), in.skin);
  mmrep::WriteSurface(MakeSurface(SkullRadii(), truth), in.skull);
  mmrep::WriteLandmarks(SubjectControlPoints(atlas.mesh, truth), in.points);
  const auto p = truth.SubjectPlane();
  std::ostringstream s;
  s.precision(17);
  s << p.point.x() << "," << p.point.y() << "," << p.point.z() << "," << p.normal.x() << "," << p.normal.y() << ","
    << p.normal.z();
  in.plane = s.str();
  return in;
}

void ExpectCleanFailure(const mmrep::testing::ModuleRun& run, const ScratchDirectory& dir, const std::string& needle)
{
  EXPECT_EQ(run.exitCode, 1) << run.err;
  ASSERT_EQ(run.ErrLines().size(), 1u) << run.err;
  EXPECT_NE(run.err.find(needle), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.vtu"));
  for (const auto& e : dir.Entries())
    EXPECT_EQ(e.find("mmrep-tmp"), std::string::npos) << e;
}
} // namespace

TEST(ElasticAtlasRegistrationModule, RegistersTheSyntheticSubjectAndWritesEverything)
{
  ScratchDirectory dir("atlasreg");
  const auto in = WriteInputs(dir);
  // Atlas plane from the 'midsagittal' node set (not given), subject plane given.
  const auto run = RunModuleExecutable("AtlasRegistration",
                                       {in.atlas, in.skin, in.skull, in.points, dir / "out.vtu", "--subjectPlane",
                                        in.plane, "--outputTransform", dir / "field.nrrd", "--transformSpacing", "4",
                                        "--report", dir / "report.json", "--returnparameterfile", dir / "values.txt"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto values = ReadReturnParameters(dir / "values.txt");
  EXPECT_LT(std::stod(values.at("skinMeanError")), 0.3);
  EXPECT_LT(std::stod(values.at("skullMeanError")), 0.3);
  EXPECT_LT(std::stod(values.at("controlPointMeanError")), 0.5);
  EXPECT_GT(std::stod(values.at("seconds")), 0.0);
  const auto out = mmrep::ReadFEMesh(dir / "out.vtu");
  const auto atlas = mmrep::ReadFEMesh(in.atlas);
  ASSERT_EQ(out.nodes.size(), atlas.nodes.size());
  EXPECT_EQ(out.nodeSets, atlas.nodeSets);
  // Control points of the output = subject control points (the landmarks moved with the mesh).
  const auto subjectPoints = mmrep::ReadLandmarks(in.points);
  for (std::size_t i = 0; i < subjectPoints.size(); ++i)
    EXPECT_LT((out.landmarks[i].position - subjectPoints[i].position).norm(), 1.0) << subjectPoints[i].name;
  // The field covers the atlas with the requested spacing.
  const auto field = mmrep::ReadDisplacementField(dir / "field.nrrd");
  EXPECT_GT(field->GetLargestPossibleRegion().GetNumberOfPixels(), 1000u);
  EXPECT_DOUBLE_EQ(field->GetSpacing()[0], 4.0);
  const auto json = nlohmann::json::parse(mmrep::testing::Slurp(dir / "report.json"));
  ASSERT_TRUE(json.contains("stages"));
  EXPECT_EQ(json["stages"][0]["name"], "similarity");
  EXPECT_GT(json["stages"][0]["skin"]["mean"].get<double>(), std::stod(values.at("skinMeanError")));
  EXPECT_EQ(json["controlPoints"].size(), 5u);
}

TEST(ElasticAtlasRegistrationModule, EstimatesTheSubjectPlaneWhenNotGiven)
{
  ScratchDirectory dir("atlasplane");
  const Truth truth;
  const auto in = WriteInputs(dir, truth);
  const auto run = RunModuleExecutable("AtlasRegistration", {in.atlas, in.skin, in.skull, in.points, dir / "out.vtu",
                                                             "--levels", "3", "--returnparameterfile", dir / "v.txt"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("Subject plane (estimated)"), std::string::npos);
  EXPECT_LT(std::stod(ReadReturnParameters(dir / "v.txt").at("skinMeanError")), 0.3);
  // The output is symmetric about the true subject plane up to the plane estimate's accuracy.
  const auto out = mmrep::ReadFEMesh(dir / "out.vtu");
  const auto atlas = MakeAtlas();
  const auto plane = truth.SubjectPlane();
  double worst = 0;
  for (const auto& [a, b] : atlas.mirrorPairs)
    worst = std::max(worst, (plane.Mirror(out.nodes[a]) - out.nodes[b]).norm());
  std::cout << "asymmetry about the true plane: " << worst << " mm" << std::endl;
  EXPECT_LT(worst, 0.05);
}

TEST(ElasticAtlasRegistrationModule, WritesAMarkdownReportForMdExtension)
{
  ScratchDirectory dir("atlasmd");
  const auto in = WriteInputs(dir);
  const auto run = RunModuleExecutable(
    "AtlasRegistration", {in.atlas, in.skin, in.skull, in.points, dir / "out.vtu", "--subjectPlane", in.plane,
                          "--levels", "2", "--report", dir / "report.md", "--returnparameterfile", dir / "v.txt"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto md = mmrep::testing::Slurp(dir / "report.md");
  const auto values = ReadReturnParameters(dir / "v.txt");
  char mean[32];
  std::snprintf(mean, sizeof(mean), "%.3f", std::stod(values.at("skinMeanError")));
  EXPECT_EQ(md.rfind("## Atlas registration", 0), 0u) << md;
  EXPECT_NE(md.find("| total | " + std::string(mean) + " |"), std::string::npos) << md;
  EXPECT_NE(md.find("| LowerLipCenter |"), std::string::npos) << md;
  // An unknown report extension is refused before anything is written.
  const auto bad = RunModuleExecutable("AtlasRegistration", {in.atlas, in.skin, in.skull, in.points, dir / "out2.vtu",
                                                             "--subjectPlane", in.plane, "--report", dir / "r.txt"});
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find("r.txt"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out2.vtu"));
}

TEST(ElasticAtlasRegistrationModule, BadInputGivesOneLineAndNoOutput)
{
  ScratchDirectory dir("atlasbad");
  const auto in = WriteInputs(dir);
  const std::vector<std::string> tail = {dir / "out.vtu", "--subjectPlane", in.plane};
  auto runWith = [&](const std::string& skin, const std::string& skull, const std::string& points) {
    std::vector<std::string> args = {in.atlas, skin, skull, points};
    args.insert(args.end(), tail.begin(), tail.end());
    return RunModuleExecutable("AtlasRegistration", args);
  };
  // Renamed control point.
  auto points = mmrep::ReadLandmarks(in.points);
  points[1].name = "Nose";
  mmrep::WriteLandmarks(points, dir / "renamed.mrk.json");
  ExpectCleanFailure(runWith(in.skin, in.skull, dir / "renamed.mrk.json"), dir, "LeftEyeOuterCorner");
  // Missing control point.
  points = mmrep::ReadLandmarks(in.points);
  points.pop_back();
  mmrep::WriteLandmarks(points, dir / "missing.fcsv");
  ExpectCleanFailure(runWith(in.skin, in.skull, dir / "missing.fcsv"), dir, "LowerLipCenter");
  // A skin without triangles.
  auto empty = vtkSmartPointer<vtkPolyData>::New();
  empty->SetPoints(mmrep::ReadSurface(in.skin)->GetPoints());
  mmrep::WriteSurface(empty, dir / "empty.vtp");
  ExpectCleanFailure(runWith(dir / "empty.vtp", in.skull, in.points), dir, "skin");
  // Surfaces 500 mm away from the control points.
  vtkNew<vtkTransform> shift;
  shift->Translate(0, 0, 500);
  for (const auto& [src, dst] : {std::pair{in.skin, dir / "far-skin.vtp"}, std::pair{in.skull, dir / "far-skull.vtp"}})
  {
    vtkNew<vtkTransformPolyDataFilter> f;
    f->SetInputData(mmrep::ReadSurface(src));
    f->SetTransform(shift);
    f->Update();
    mmrep::WriteSurface(f->GetOutput(), dst);
  }
  ExpectCleanFailure(runWith(dir / "far-skin.vtp", dir / "far-skull.vtp", in.points), dir, "do not overlap");
  // A plane with four numbers.
  auto run = RunModuleExecutable(
    "AtlasRegistration", {in.atlas, in.skin, in.skull, in.points, dir / "out.vtu", "--subjectPlane", "0,0,0,1"});
  ExpectCleanFailure(run, dir, "subjectPlane");
}
