// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Landmark files: round trips in both coordinate systems, raw file contents, Slicer variants.
#include "mmrepLandmarkIO.h"
#include "mmrepTestDir.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;
using mmrep::CoordinateSystem;
using mmrep::Landmark;

namespace
{

std::vector<Landmark> Sample()
{
  return {{"nasion", {1.25, -80.5, 42.125}},
          {"subnasale", {-0.3333333333333333, -95.75, 10.0}},
          {"pogonion, soft", {3.0e-3, -102.0, -40.875}}, // comma exercises CSV quoting
          {"cheilion \"left\"", {27.5, -78.0, -5.5}}};
}

void ExpectSame(const std::vector<Landmark>& a, const std::vector<Landmark>& b)
{
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    EXPECT_EQ(a[i].name, b[i].name);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_DOUBLE_EQ(a[i].position[k], b[i].position[k]) << a[i].name << " axis " << k;
    }
  }
}

// LPS -> RAS flips x and y; z is kept.
double Expected(const Landmark& lm, int axis, CoordinateSystem system)
{
  return (system == CoordinateSystem::RAS && axis < 2) ? -lm.position[axis] : lm.position[axis];
}

void CheckJson(CoordinateSystem system)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const std::string path = (dir / "points.mrk.json").string();
  mmrep::WriteLandmarks(Sample(), path, system);
  ExpectSame(Sample(), mmrep::ReadLandmarks(path));

  nlohmann::json doc;
  std::ifstream(path) >> doc;
  EXPECT_NE(doc["@schema"].get<std::string>().find("markups-schema-v1.0."), std::string::npos);
  ASSERT_EQ(doc["markups"].size(), 1u);
  const auto& markup = doc["markups"][0];
  EXPECT_EQ(markup["type"], "Fiducial");
  EXPECT_EQ(markup["coordinateSystem"], system == CoordinateSystem::LPS ? "LPS" : "RAS");
  ASSERT_EQ(markup["controlPoints"].size(), Sample().size());
  for (std::size_t i = 0; i < Sample().size(); ++i)
  {
    const auto& cp = markup["controlPoints"][i];
    EXPECT_EQ(cp["label"], Sample()[i].name);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_DOUBLE_EQ(cp["position"][k].get<double>(), Expected(Sample()[i], k, system));
    }
  }
}

void CheckFcsv(CoordinateSystem system)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const std::string path = (dir / "points.fcsv").string();
  mmrep::WriteLandmarks(Sample(), path, system);
  ExpectSame(Sample(), mmrep::ReadLandmarks(path));

  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "# Markups fiducial file version = 4.11");
  std::getline(in, line);
  EXPECT_EQ(line, std::string("# CoordinateSystem = ") + (system == CoordinateSystem::LPS ? "LPS" : "RAS"));
  std::getline(in, line);
  EXPECT_EQ(line, "# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,associatedNodeID");
  for (const Landmark& lm : Sample())
  {
    ASSERT_TRUE(std::getline(in, line));
    // The first four fields never need quoting: id, x, y, z.
    std::stringstream fields(line);
    std::string id, x, y, z;
    std::getline(fields, id, ',');
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    std::getline(fields, z, ',');
    EXPECT_DOUBLE_EQ(std::stod(x), Expected(lm, 0, system)) << line;
    EXPECT_DOUBLE_EQ(std::stod(y), Expected(lm, 1, system)) << line;
    EXPECT_DOUBLE_EQ(std::stod(z), Expected(lm, 2, system)) << line;
  }
}

} // namespace

TEST(LandmarkIO, MarkupsJsonRoundTripLPS)
{
  CheckJson(CoordinateSystem::LPS);
}
TEST(LandmarkIO, MarkupsJsonRoundTripRAS)
{
  CheckJson(CoordinateSystem::RAS);
}
TEST(LandmarkIO, FcsvRoundTripLPS)
{
  CheckFcsv(CoordinateSystem::LPS);
}
TEST(LandmarkIO, FcsvRoundTripRAS)
{
  CheckFcsv(CoordinateSystem::RAS);
}

TEST(LandmarkIO, ExplicitFormatOverridesExtension)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const std::string path = (dir / "points.fcsv").string();
  mmrep::WriteLandmarks(Sample(), path, "fcsv", CoordinateSystem::RAS);
  ExpectSame(Sample(), mmrep::ReadLandmarks(path));
  EXPECT_THROW(mmrep::WriteLandmarks(Sample(), path, "csv", CoordinateSystem::LPS), std::invalid_argument);
}

TEST(LandmarkIO, ReadsSlicerRasJsonAndSkipsMissingPoints)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const std::string path = (dir / "slicer.mrk.json").string();
  std::ofstream(path) << R"({
  "@schema": "https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/Markups/Resources/Schema/markups-schema-v1.0.0.json#",
  "markups": [{
    "type": "Fiducial", "coordinateSystem": "RAS",
    "controlPoints": [
      {"id": "1", "label": "F-1", "position": [10.5, -20.25, 30.0], "positionStatus": "defined"},
      {"id": "2", "label": "F-2", "positionStatus": "missing"},
      {"id": "3", "label": "F-3", "position": [-1.0, 2.0, -3.0]}
    ]}]})";
  const std::vector<Landmark> lms = mmrep::ReadLandmarks(path);
  ASSERT_EQ(lms.size(), 2u);
  EXPECT_EQ(lms[0].name, "F-1");
  EXPECT_DOUBLE_EQ(lms[0].position.x(), -10.5);
  EXPECT_DOUBLE_EQ(lms[0].position.y(), 20.25);
  EXPECT_DOUBLE_EQ(lms[0].position.z(), 30.0);
  EXPECT_EQ(lms[1].name, "F-3");
  EXPECT_DOUBLE_EQ(lms[1].position.x(), 1.0);
  EXPECT_DOUBLE_EQ(lms[1].position.y(), -2.0);
}

// coordinateUnits are honoured (Slicer's "um" for microscopy): a file in micrometres gives the
// same millimetres; a unit we do not know, and a point nobody placed, are refused naming them.
TEST(LandmarkIO, HonoursCoordinateUnitsAndRefusesUnplacedPoints)
{
  const fs::path dir = mmrep::test::ScratchDir();
  auto write = [&](const std::string& name, const std::string& units, const std::string& status) {
    const std::string path = (dir / name).string();
    std::ofstream(path) << R"({"markups": [{"type": "Fiducial", "coordinateSystem": "LPS", )" << units
                        << R"("controlPoints": [
      {"id": "1", "label": "A", "position": [120350.0, -49000.5, 1500.0], "positionStatus": "defined"},
      {"id": "2", "label": "LeftLipCorner", "position": [1.0, 2.0, 3.0], "positionStatus": ")"
                        << status << R"("}]}]})";
    return path;
  };
  const auto um = mmrep::ReadLandmarks(write("um.mrk.json", R"("coordinateUnits": "um", )", "defined"));
  ASSERT_EQ(um.size(), 2u);
  EXPECT_DOUBLE_EQ(um[0].position.x(), 120.35);
  EXPECT_DOUBLE_EQ(um[0].position.y(), -49.0005);
  EXPECT_DOUBLE_EQ(um[0].position.z(), 1.5);
  const auto perAxis =
    mmrep::ReadLandmarks(write("axes.mrk.json", R"("coordinateUnits": ["m", "m", "m"], )", "defined"));
  EXPECT_DOUBLE_EQ(perAxis[1].position.z(), 3000.0);
  const auto mm = mmrep::ReadLandmarks(write("mm.mrk.json", R"("coordinateUnits": "mm", )", "defined"));
  EXPECT_DOUBLE_EQ(mm[0].position.x(), 120350.0);

  auto refusal = [](const std::string& path) {
    try
    {
      mmrep::ReadLandmarks(path);
    }
    catch (const std::runtime_error& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refusal(write("ft.mrk.json", R"("coordinateUnits": "ft", )", "defined")).find("coordinateUnits 'ft'"),
            std::string::npos);
  EXPECT_NE(refusal(write("mixed.mrk.json", R"("coordinateUnits": ["mm", "um", "mm"], )", "defined"))
              .find("coordinateUnits differ"),
            std::string::npos);
  for (const char* status : {"undefined", "preview"})
  {
    const std::string why = refusal(write(std::string(status) + ".mrk.json", "", status));
    EXPECT_NE(why.find("control point 'LeftLipCorner' is not placed (positionStatus '" + std::string(status) + "')"),
              std::string::npos)
      << why;
  }
}

TEST(LandmarkIO, ReadsLegacyNumericFcsvCoordinateSystems)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const std::string ras = (dir / "old-ras.fcsv").string();
  std::ofstream(ras) << "# Markups fiducial file version = 4.4\n# CoordinateSystem = 0\n"
                        "# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,associatedNodeID\n"
                        "vtkMRMLMarkupsFiducialNode_0,1.5,2.5,3.5,0,0,0,1,1,1,0,A,,\n";
  const std::string lps = (dir / "old-lps.fcsv").string();
  std::ofstream(lps) << "# Markups fiducial file version = 4.10\n# CoordinateSystem = 1\n"
                        "# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,associatedNodeID\n"
                        "vtkMRMLMarkupsFiducialNode_0,1.5,2.5,3.5,0,0,0,1,1,1,0,B,,\n";
  const auto a = mmrep::ReadLandmarks(ras);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].name, "A");
  EXPECT_DOUBLE_EQ(a[0].position.x(), -1.5);
  EXPECT_DOUBLE_EQ(a[0].position.y(), -2.5);
  EXPECT_DOUBLE_EQ(a[0].position.z(), 3.5);
  const auto b = mmrep::ReadLandmarks(lps);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].name, "B");
  EXPECT_DOUBLE_EQ(b[0].position.x(), 1.5);
  EXPECT_DOUBLE_EQ(b[0].position.y(), 2.5);
}

TEST(LandmarkIO, BadFilesThrowNamingThePath)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const std::string missing = (dir / "missing.mrk.json").string();
  EXPECT_THROW(mmrep::ReadLandmarks(missing), std::runtime_error);
  const std::string bad = (dir / "bad.mrk.json").string();
  std::ofstream(bad) << "{ not json";
  try
  {
    mmrep::ReadLandmarks(bad);
    ADD_FAILURE() << "no exception";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
  }
  const std::string badNumber = (dir / "bad.fcsv").string();
  std::ofstream(badNumber) << "# CoordinateSystem = LPS\n1,abc,2,3,0,0,0,1,1,1,0,X,,\n";
  EXPECT_THROW(mmrep::ReadLandmarks(badNumber), std::runtime_error);
  EXPECT_THROW(mmrep::ReadLandmarks((dir / "points.txt").string()), std::runtime_error);
}
