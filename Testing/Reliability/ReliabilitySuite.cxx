// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The bad-input suite: each case of BadInputCases.h runs a module as a user would and checks what
// the user is left with: the exit code, exactly one stderr line naming the culprit, and the case's
// folder (inputs, earlier outputs, $TMPDIR) byte for byte as it was, with nothing added.
#include "BadInputCases.h"
#include "mmrepFEMeshIO.h"
#include "mmrepImageIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepModuleRunner.h"
#include "mmrepSurfaceIO.h"

#include <itkRegionOfInterestImageFilter.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>

namespace
{
namespace fs = std::filesystem;
using namespace mmrep::testing;

const std::string kSampleData = std::string(MMREP_SOURCE_DIR) + "/Resources/SampleData/";
const std::string kAtlasData = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/";

void WriteFile(const fs::path& path, const std::string& bytes)
{
  std::ofstream f(path, std::ios::binary);
  f << bytes;
  ASSERT_TRUE(f.good()) << path;
}

// Control points that contradict the anatomy: all five 15 mm in front of the face (in the air) or
// 15 mm to the side, the lips swapped, the face 1.8 times too large, one point not placed (positionStatus "undefined").
void WriteWrongControlPoints(const fs::path& d)
{
  const auto points = mmrep::ReadLandmarks(kSampleData + "cthead.ControlPoints.mrk.json");
  auto shifted = points, sideways = points, swapped = points, scaled = points;
  mmrep::Point3 centre = mmrep::Point3::Zero();
  for (const auto& p : points)
    centre += p.position / static_cast<double>(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    shifted[i].position.y() -= 15.0;  // LPS: -y is anterior
    sideways[i].position.x() += 15.0; // to the patient's left, along the face
    scaled[i].position = centre + 1.8 * (points[i].position - centre);
    if (points[i].name == "UpperLipCenter")
      swapped[i].name = "LowerLipCenter";
    else if (points[i].name == "LowerLipCenter")
      swapped[i].name = "UpperLipCenter";
  }
  mmrep::WriteLandmarks(shifted, (d / "shifted.mrk.json").string());
  mmrep::WriteLandmarks(sideways, (d / "sideways.mrk.json").string());
  mmrep::WriteLandmarks(swapped, (d / "swapped.mrk.json").string());
  mmrep::WriteLandmarks(scaled, (d / "scaled.mrk.json").string());
  auto json = nlohmann::json::parse(Slurp(kSampleData + "cthead.ControlPoints.mrk.json"));
  json["markups"][0]["controlPoints"][2]["positionStatus"] = "undefined";
  WriteFile(d / "undefined.mrk.json", json.dump(4));
}

// The bundled CT with a wrong orientation header, as scanners and converters write them: turned 90
// degrees about the vertical axis (its control points turned with it: the face then looks to the
// patient's left), and upside down (rotated 180 degrees about the left axis, with the control
// points of the upright head). Both rotate about the volume's centre, so the extent stays put.
// The centre of the bundled CT's volume, which the reoriented fixtures turn about.
Eigen::Vector3d VolumeCentre(const mmrep::CTImage* ct)
{
  const auto size = ct->GetLargestPossibleRegion().GetSize();
  itk::ContinuousIndex<double, 3> middle;
  for (unsigned a = 0; a < 3; ++a)
    middle[a] = 0.5 * (static_cast<double>(size[a]) - 1.0);
  mmrep::CTImage::PointType c;
  ct->TransformContinuousIndexToPhysicalPoint(middle, c);
  return {c[0], c[1], c[2]};
}

void WriteReorientedHeads(const fs::path& d)
{
  auto rotated = [&](const Eigen::Matrix3d& r, const std::string& name) {
    auto ct = mmrep::ReadCTImage(kSampleData + "cthead.nrrd");
    const Eigen::Vector3d centre = VolumeCentre(ct);
    auto move = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d { return centre + r * (p - centre); };
    Eigen::Matrix3d direction;
    for (unsigned i = 0; i < 3; ++i)
      for (unsigned j = 0; j < 3; ++j)
        direction(i, j) = ct->GetDirection()[i][j];
    direction = r * direction;
    mmrep::CTImage::DirectionType itkDirection;
    for (unsigned i = 0; i < 3; ++i)
      for (unsigned j = 0; j < 3; ++j)
        itkDirection[i][j] = direction(i, j);
    const Eigen::Vector3d origin = move({ct->GetOrigin()[0], ct->GetOrigin()[1], ct->GetOrigin()[2]});
    ct->SetDirection(itkDirection);
    ct->SetOrigin(origin.data());
    mmrep::WriteImage(ct.GetPointer(), (d / (name + ".nrrd")).string());
    auto points = mmrep::ReadLandmarks(kSampleData + "cthead.ControlPoints.mrk.json");
    for (auto& p : points)
      p.position = move(p.position);
    mmrep::WriteLandmarks(points, (d / (name + ".mrk.json")).string());
  };
  Eigen::Matrix3d turn, upsideDown;
  turn << 0, -1, 0, 1, 0, 0, 0, 0, 1;        // about +z (superior) by 90 degrees
  upsideDown << 1, 0, 0, 0, -1, 0, 0, 0, -1; // about +x (left) by 180 degrees
  rotated(turn, "turned");
  rotated(upsideDown, "upsidedown");
}

// The generated fixtures, made once per test program.
const fs::path& Fixtures()
{
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("mmrep-reliability-fixtures-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d / "dicomjunk");
    const std::string lps = "space: left-posterior-superior\nspace directions: (4,0,0) (0,4,0) (0,0,4)\n"
                            "space origin: (0,0,0)\nendian: little\nencoding: raw\n\n";
    // 2048^3 shorts declared, 4 kB present.
    WriteFile(d / "big.nrrd",
              "NRRD0004\ntype: short\ndimension: 3\nsizes: 2048 2048 2048\n" + lps + std::string(4000, '\0'));
    // A float volume of air with one NaN voxel.
    std::vector<float> voxels(16 * 16 * 16, -1000.0f);
    voxels[5 + 16 * (6 + 16 * 7)] = std::numeric_limits<float>::quiet_NaN();
    std::string raw(voxels.size() * sizeof(float), '\0');
    std::memcpy(raw.data(), voxels.data(), raw.size());
    WriteFile(d / "nan.nrrd", "NRRD0004\ntype: float\ndimension: 3\nsizes: 16 16 16\n" + lps + raw);
    WriteFile(d / "field.nrrd", "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 2 2 2\n"
                                "kinds: vector domain domain domain\nspace: left-posterior-superior\n"
                                "space directions: none (1,0,0) (0,1,0) (0,0,1)\nspace origin: (0,0,0)\n"
                                "encoding: ascii\n\n" +
                                  std::string(24, '0').replace(0, 24, [] {
                                    std::string zeros;
                                    for (int i = 0; i < 24; ++i)
                                      zeros += "0\n";
                                    return zeros;
                                  }()));
    const std::string points =
      R"(<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0</DataArray></Points>)";
    WriteFile(d / "bigvtu.vtu",
              R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
  <UnstructuredGrid>
    <Piece NumberOfPoints="100000000000" NumberOfCells="1">
      )" + points +
                R"(
      <Cells>
        <DataArray type="Int64" Name="connectivity" format="ascii">0 1 2</DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">3</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">5</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)");
    WriteFile(d / "bigvtp.vtp",
              R"(<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">
  <PolyData>
    <Piece NumberOfPoints="100000000000" NumberOfPolys="1">
      )" + points +
                R"(
      <Polys>
        <DataArray type="Int64" Name="connectivity" format="ascii">0 1 2</DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">3</DataArray>
      </Polys>
    </Piece>
  </PolyData>
</VTKFile>
)");
    WriteFile(d / "dicomjunk" / "IM0001.dcm", std::string(128, '\0') + "DICM" + std::string(300, '\x7f'));
    WriteFile(d / "dicomjunk" / "notes.txt", "not an image\n");
    // A MetaImage header whose data file is missing; a single slice.
    WriteFile(d / "noraw.mhd", "ObjectType = Image\nNDims = 3\nDimSize = 64 64 64\nElementType = MET_SHORT\n"
                               "ElementDataFile = noraw.raw\n");
    WriteFile(d / "oneslice.nrrd",
              "NRRD0004\ntype: short\ndimension: 3\nsizes: 64 64 1\n" + lps + std::string(64 * 64 * 2, '\0'));
    WriteFile(d / "twice.json",
              R"({"name": "smile", "muscles": {"ZygomaticusMajor_L": 1.0, "ZygomaticusMajor_L": 0.2}})");
    // The bundled CT cut 5 mm below the lower lip: the control points stay inside, the chin is gone.
    const auto ct = mmrep::ReadCTImage(kSampleData + "cthead.nrrd");
    auto region = ct->GetLargestPossibleRegion();
    mmrep::CTImage::PointType lip;
    lip[0] = 111.1;
    lip[1] = 25.2;
    lip[2] = 59.2 - 5.0; // LowerLipCenter (cthead.ControlPoints.mrk.json), z superior
    const auto cut = ct->TransformPhysicalPointToIndex(lip);
    const auto keep = region.GetIndex(2) + region.GetSize(2) - cut[2];
    region.SetIndex(2, cut[2]);
    region.SetSize(2, static_cast<itk::SizeValueType>(keep));
    auto crop = itk::RegionOfInterestImageFilter<mmrep::CTImage, mmrep::CTImage>::New();
    crop->SetInput(ct);
    crop->SetRegionOfInterest(region);
    crop->Update();
    mmrep::WriteImage(crop->GetOutput(), (d / "cropped.nrrd").string());
    // Damaged volumes in each format: cut to half their length, or a MetaImage of an unknown type.
    const auto headsq = mmrep::ReadCTImage(kSampleData + "headsq.nrrd");
    for (const char* name : {"truncated.nrrd", "truncated.mha", "truncated.nii", "truncated.nii.gz"})
    {
      mmrep::WriteImage(headsq.GetPointer(), (d / name).string());
      fs::resize_file(d / name, fs::file_size(d / name) / 2);
    }
    // One byte flipped halfway through the compressed voxels of the atlas's CT in each compressed format
    // (the stream's checksum fails; the readers alone returned a volume with wrong voxels).
    for (const char* name : {"corrupt.nrrd", "corrupt.mha", "corrupt.nii.gz"})
    {
      mmrep::WriteImage(ct.GetPointer(), (d / name).string());
      std::fstream f(d / name, std::ios::in | std::ios::out | std::ios::binary);
      const auto middle = static_cast<std::streamoff>(fs::file_size(d / name) / 2);
      char byte = 0;
      f.seekg(middle);
      f.get(byte);
      f.seekp(middle);
      f.put(static_cast<char>(byte ^ 0x5a));
    }
    WriteFile(d / "badtype.mha", "ObjectType = Image\nNDims = 3\nDimSize = 4 4 4\nElementType = MET_FOO\n"
                                 "ElementDataFile = LOCAL\n" +
                                   std::string(64, '\0'));
    // The atlas with one landmark not a number; a surface cut short; a PLY without coordinates.
    auto atlas = mmrep::ReadFEMesh(kAtlasData + "FaceAtlas.vtu");
    // A zero displacement field over the whole atlas (10 mm grid): MuscleInference runs to its writer.
    {
      Eigen::Vector3d low = atlas.nodes.front(), high = atlas.nodes.front();
      for (const auto& x : atlas.nodes)
      {
        low = low.cwiseMin(x);
        high = high.cwiseMax(x);
      }
      auto zero = mmrep::DisplacementField::New();
      mmrep::DisplacementField::SizeType size;
      mmrep::DisplacementField::PointType origin;
      mmrep::DisplacementField::SpacingType spacing;
      for (int a = 0; a < 3; ++a)
      {
        origin[a] = low[a] - 20.0;
        spacing[a] = 10.0;
        size[a] = static_cast<std::size_t>(std::ceil((high[a] - low[a] + 40.0) / 10.0)) + 1;
      }
      zero->SetRegions(size);
      zero->SetOrigin(origin);
      zero->SetSpacing(spacing);
      zero->Allocate();
      zero->FillBuffer(mmrep::DisplacementField::PixelType(0.0f));
      mmrep::WriteDisplacementField(zero, (d / "zerofield.nrrd").string());
    }
    // The atlas with its leftmost node moved 2 mm back: no longer symmetric (MeshConvert --half).
    {
      auto asymmetric = atlas;
      auto leftmost = std::max_element(asymmetric.nodes.begin(), asymmetric.nodes.end(),
                                       [](const auto& a, const auto& b) { return a.x() < b.x(); });
      leftmost->y() += 2.0;
      mmrep::WriteFEMesh(asymmetric, (d / "asymmetric.vtu").string());
    }
    atlas.landmarks.at(1).position.x() = std::numeric_limits<double>::quiet_NaN();
    mmrep::WriteFEMesh(atlas, (d / "nanatlas.vtu").string());
    fs::copy(kAtlasData + "FaceAtlasSkin.vtp", d / "truncated.vtp");
    fs::resize_file(d / "truncated.vtp", fs::file_size(d / "truncated.vtp") / 2);
    WriteFile(d / "noxyz.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n2\n3\n");
    // The atlas skin as PLY and STL, cut to half their length (vtkPLYReader crashed on such files).
    const auto skin = mmrep::ReadSurface(kAtlasData + "FaceAtlasSkin.vtp");
    for (const char* name : {"truncated.ply", "truncated.stl"})
    {
      mmrep::WriteSurface(skin, (d / name).string());
      fs::resize_file(d / name, fs::file_size(d / name) / 2);
    }
    WriteWrongControlPoints(d);
    WriteReorientedHeads(d);
    return d;
  }();
  struct RemoveAtExit
  {
    fs::path path;
    ~RemoveAtExit()
    {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  };
  static const RemoveAtExit cleanup{dir};
  return dir;
}

const std::map<std::string, fs::path>& Placeholders()
{
  static const std::map<std::string, fs::path> p = {
    {"{ct}", kSampleData + "cthead.nrrd"},
    {"{points}", kSampleData + "cthead.ControlPoints.mrk.json"},
    {"{atlas}", kAtlasData + "FaceAtlas.vtu"},
    {"{landmarks}", kAtlasData + "FaceAtlasLandmarks.mrk.json"},
    {"{skin}", kAtlasData + "FaceAtlasSkin.vtp"},
    {"{skull}", kAtlasData + "FaceAtlasSkull.vtp"},
    {"{field}", Fixtures() / "field.nrrd"},
    {"{zerofield}", Fixtures() / "zerofield.nrrd"},
    {"{nan}", Fixtures() / "nan.nrrd"},
    {"{big}", Fixtures() / "big.nrrd"},
    {"{bigvtu}", Fixtures() / "bigvtu.vtu"},
    {"{bigvtp}", Fixtures() / "bigvtp.vtp"},
    {"{dicomjunk}", Fixtures() / "dicomjunk"},
    {"{cropped}", Fixtures() / "cropped.nrrd"},
    {"{truncnrrd}", Fixtures() / "truncated.nrrd"},
    {"{truncmha}", Fixtures() / "truncated.mha"},
    {"{truncnii}", Fixtures() / "truncated.nii"},
    {"{truncniigz}", Fixtures() / "truncated.nii.gz"},
    {"{badtype}", Fixtures() / "badtype.mha"},
    {"{nanatlas}", Fixtures() / "nanatlas.vtu"},
    {"{truncvtp}", Fixtures() / "truncated.vtp"},
    {"{noxyz}", Fixtures() / "noxyz.ply"},
    {"{truncply}", Fixtures() / "truncated.ply"},
    {"{truncstl}", Fixtures() / "truncated.stl"},
    {"{asymmetric}", Fixtures() / "asymmetric.vtu"},
    {"{gesturetwice}", Fixtures() / "twice.json"},
    {"{noraw}", Fixtures() / "noraw.mhd"},
    {"{oneslice}", Fixtures() / "oneslice.nrrd"},
    {"{corruptnrrd}", Fixtures() / "corrupt.nrrd"},
    {"{corruptmha}", Fixtures() / "corrupt.mha"},
    {"{corruptniigz}", Fixtures() / "corrupt.nii.gz"},
    {"{shifted}", Fixtures() / "shifted.mrk.json"},
    {"{sideways}", Fixtures() / "sideways.mrk.json"},
    {"{swapped}", Fixtures() / "swapped.mrk.json"},
    {"{scaled}", Fixtures() / "scaled.mrk.json"},
    {"{undefined}", Fixtures() / "undefined.mrk.json"},
    {"{turnedct}", Fixtures() / "turned.nrrd"},
    {"{turnedpoints}", Fixtures() / "turned.mrk.json"},
    {"{upsidedownct}", Fixtures() / "upsidedown.nrrd"},
    {"{vhf}", kSampleData + "vhf_head_ct.nrrd"},
    {"{vhfpoints}", kSampleData + "vhf_head_ct.ControlPoints.mrk.json"},
  };
  return p;
}

// Every file and folder under `root`, with the bytes of the files.
std::map<std::string, std::string> Snapshot(const fs::path& root)
{
  std::map<std::string, std::string> entries;
  for (const auto& e : fs::recursive_directory_iterator(root))
    entries[fs::relative(e.path(), root).string()] = e.is_directory() ? std::string("<folder>") : Slurp(e.path());
  return entries;
}

std::string Differences(const std::map<std::string, std::string>& before,
                        const std::map<std::string, std::string>& after)
{
  std::string d;
  for (const auto& [name, bytes] : before)
    if (!after.count(name))
      d += " removed " + name + ";";
    else if (after.at(name) != bytes)
      d += " changed " + name + ";";
  for (const auto& [name, bytes] : after)
    if (!before.count(name))
      d += " added " + name + ";";
  return d;
}

class BadInput : public ::testing::TestWithParam<BadInputCase>
{
};

TEST_P(BadInput, OneLineNothingTouchedNothingLeft)
{
  const BadInputCase& c = GetParam();
  ScratchDirectory scratch("bad-" + c.name);
  const fs::path dir = scratch.path() / "case", logs = scratch.path() / "logs";
  fs::create_directories(dir / "tmp");
  fs::create_directories(logs);

  // Inputs: the fixtures the case names, copied in; then the earlier outputs.
  std::vector<std::string> args;
  const fs::path full = dir / "full";
  if (c.fullDiskFreeKiB >= 0)
    fs::create_directories(full);
  for (std::string a : c.args)
  {
    for (std::size_t at; (at = a.find("{full}")) != std::string::npos;)
      a.replace(at, 6, full.string());
    for (const auto& [key, source] : Placeholders())
      for (std::size_t at; (at = a.find(key)) != std::string::npos;)
      {
        const fs::path copy = dir / source.filename();
        if (!fs::exists(copy))
          fs::copy(source, copy, fs::copy_options::recursive);
        a.replace(at, key.size(), copy.string());
      }
    for (std::size_t at; (at = a.find("{d}")) != std::string::npos;)
      a.replace(at, 3, dir.string());
    args.push_back(a);
  }
  for (const std::string& e : c.earlier)
    if (e.back() == '/')
    {
      fs::create_directories(dir / e);
      std::ofstream(dir / e / "model.vtu") << "an earlier run's model\n";
      std::ofstream(dir / e / "report.md") << "an earlier run's report\n";
    }
    else
      std::ofstream(dir / e) << "an earlier run's " << e << "\n";
  const auto before = Snapshot(dir);

  std::string cmd = "cd " + Quote(dir.string()) + " && TMPDIR=" + Quote((dir / "tmp").string()) + " ";
  const char* display = std::getenv("DISPLAY");
  if (c.display && (display == nullptr || *display == '\0'))
    cmd += "xvfb-run -a -n " + std::to_string(100 + ::getpid() % 20000) + " -f " +
           Quote((logs / "Xauthority").string()) + " -s \"-screen 0 1600x1200x24 -noreset\" ";
  // The full disk: a tmpfs in a private mount namespace (gone with the run), filled to leave the case's free
  // space; what the run leaves on it is listed before it goes.
  if (c.fullDiskFreeKiB >= 0)
    cmd += "env LEFT=" + Quote((logs / "left").string()) +
           " FILL=" + std::to_string((4096 - c.fullDiskFreeKiB) * 1024) +
           " unshare -m sh -c 'mount -t tmpfs -o size=4096k mmrep-full \"$0\" || exit 97; "
           "head -c $FILL /dev/zero > \"$0/.filler\" 2>/dev/null; \"$@\"; rc=$?; rm -f \"$0/.filler\"; "
           "ls -A \"$0\" > \"$LEFT\"; exit $rc' " +
           Quote(full.string()) + " ";
  if (c.addressSpaceKiB > 0)
    cmd += "sh -c 'ulimit -v " + std::to_string(c.addressSpaceKiB) + " && exec \"$0\" \"$@\"' ";
  cmd += Quote(std::string(MMREP_BINARY_DIR) + "/bin/" + c.module);
  for (const auto& a : args)
    cmd += " " + Quote(a);
  cmd += " > " + Quote((logs / "out").string()) + " 2> " + Quote((logs / "err").string()) + " < /dev/null";
  const int status = std::system(cmd.c_str());
  ModuleRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.err = Slurp(logs / "err");

  EXPECT_EQ(run.exitCode, c.exitCode) << run.err;
  const auto lines = run.ErrLines();
  ASSERT_EQ(lines.size(), 1u) << run.err;
  std::printf("%s\n", lines[0].c_str()); // what the user reads
  EXPECT_EQ(lines[0].rfind(c.module + ": error: ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(c.culprit), std::string::npos) << "culprit '" << c.culprit << "' not named: " << lines[0];
  // No toolkit internals: object addresses, ITK's and VTK's class prefixes, source locations.
  EXPECT_FALSE(
    std::regex_search(lines[0], std::regex(R"(0x[0-9a-fA-F]{6,}|ITK ERROR|itk::|\bvtk[A-Z]\w* \(|\.(cxx|hxx):\d+)")))
    << lines[0];
  EXPECT_EQ(Differences(before, Snapshot(dir)), "") << lines[0];
  // Staging names are never shown.
  EXPECT_EQ(lines[0].find(".mmrep-tmp-"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[0].find(".partial-"), std::string::npos) << lines[0];
  if (c.fullDiskFreeKiB >= 0)
  {
    ASSERT_TRUE(fs::exists(logs / "left")) << "the full disk was not mounted: " << run.err;
    EXPECT_EQ(Slurp(logs / "left"), "") << "left on the full disk";
  }
}

// A module command line run with its stdout dropped and its stderr kept in `err`.
ModuleRun RunCommand(const std::string& command, const fs::path& err)
{
  const int status = std::system((command + " > /dev/null 2> " + Quote(err.string())).c_str());
  ModuleRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = Slurp(err);
  return run;
}

// The explicit way past the field-of-view refusal: the CT without the chin gives a partial model,
// with the missing part (as the refusal names it) in report.json and report.md and one warning line.
TEST(PartialFieldOfView, ModelBuiltMissingRegionReported)
{
  ScratchDirectory scratch("partial-fov");
  const fs::path dir = scratch.path();
  const std::string common = Quote(std::string(MMREP_BINARY_DIR) + "/bin/FaceModelPipeline") + " " +
                             Quote((Fixtures() / "cropped.nrrd").string()) + " " +
                             Quote(kSampleData + "cthead.ControlPoints.mrk.json") + " --noPictures --outputDirectory ";
  ASSERT_NE(std::system(
              (common + Quote((dir / "refused").string()) + " > /dev/null 2> " + Quote((dir / "refused.err").string()))
                .c_str()),
            0);
  const std::string refusal = Slurp(dir / "refused.err");
  std::smatch chin;
  ASSERT_TRUE(std::regex_search(refusal, chin, std::regex(R"(chin by \d+ mm)"))) << refusal;
  EXPECT_FALSE(fs::exists(dir / "refused"));

  const ModuleRun run =
    RunCommand(common + Quote((dir / "speaker").string()) + " --allowPartialFieldOfView", dir / "err");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto lines = run.ErrLines();
  ASSERT_EQ(lines.size(), 1u) << run.err;
  EXPECT_EQ(lines[0].rfind("FaceModelPipeline: warning: partial model: the CT misses the " + chin.str(), 0), 0u)
    << lines[0];
  const std::string report = Slurp(dir / "speaker" / "report.json");
  EXPECT_NE(report.find("\"complete\": false"), std::string::npos);
  EXPECT_NE(report.find("\"missing\": \"" + chin.str() + "\""), std::string::npos) << report.substr(0, 400);
  EXPECT_NE(Slurp(dir / "speaker" / "report.md").find("**Partial model**: the CT misses the " + chin.str()),
            std::string::npos);
  // A real model: the atlas's mesh, read back.
  const auto model = mmrep::ReadFEMesh((dir / "speaker" / "model.vtu").string());
  EXPECT_EQ(model.elements.size(), mmrep::ReadFEMesh(kAtlasData + "FaceAtlas.vtu").elements.size());
}

// The bundled CT stored turned 90 degrees about the vertical by its header ({turnedct}, its points turned
// with it): refused by default, put upright with --reorientToFace. The corrected frame is the stored one
// turned back (R = the turn's inverse), so the model is the upright CT's model moved by R·c − c (c: the
// centre the fixture turned about), node for node.
TEST(Orientation, ReorientToFaceBuildsTheUprightModel)
{
  ScratchDirectory scratch("reorient");
  const fs::path dir = scratch.path();
  const std::string module = Quote(std::string(MMREP_BINARY_DIR) + "/bin/FaceModelPipeline");
  const ModuleRun turned =
    RunCommand(module + " " + Quote((Fixtures() / "turned.nrrd").string()) + " " +
                 Quote((Fixtures() / "turned.mrk.json").string()) +
                 " --noPictures --reorientToFace --outputDirectory " + Quote((dir / "turned").string()),
               dir / "turned.err");
  ASSERT_EQ(turned.exitCode, 0) << turned.err;
  ASSERT_EQ(turned.ErrLines().size(), 1u) << turned.err;
  EXPECT_NE(turned.err.find("warning: the CT's orientation header was corrected (--reorientToFace): the face was "
                            "looking to the patient's left, its top to the top"),
            std::string::npos)
    << turned.err;
  const ModuleRun upright = RunCommand(module + " " + Quote(kSampleData + "cthead.nrrd") + " " +
                                         Quote(kSampleData + "cthead.ControlPoints.mrk.json") +
                                         " --noPictures --outputDirectory " + Quote((dir / "upright").string()),
                                       dir / "upright.err");
  ASSERT_EQ(upright.exitCode, 0) << upright.err;
  const auto report = nlohmann::json::parse(Slurp(dir / "turned" / "report.json"));
  const Eigen::Matrix3d expected = (Eigen::Matrix3d() << 0, 1, 0, -1, 0, 0, 0, 0, 1).finished();
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r(i, j) = report.at("reorientation").at("rotation").at(i).at(j).get<double>();
  EXPECT_TRUE(r.isApprox(expected, 1e-12)) << r;
  // The fixture's centre of turning, as it computed it.
  const Eigen::Vector3d centre = VolumeCentre(mmrep::ReadCTImage(kSampleData + "cthead.nrrd"));
  const Eigen::Vector3d shift = expected * centre - centre;
  const auto a = mmrep::ReadFEMesh((dir / "turned" / "model.vtu").string());
  const auto b = mmrep::ReadFEMesh((dir / "upright" / "model.vtu").string());
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  // Not bytes: the distance maps' grids are anchored in absolute coordinates, so they sample the moved
  // head at other points; the model agrees to far below the fit's own error nearly everywhere.
  std::vector<double> d;
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    d.push_back((a.nodes[i] - shift - b.nodes[i]).norm());
  std::sort(d.begin(), d.end());
  double sum = 0;
  for (double x : d)
    sum += x;
  const double mean = sum / static_cast<double>(d.size()), p95 = d[d.size() * 95 / 100];
  std::cout << "reoriented model vs upright: mean " << mean << " mm, 95th percentile " << p95 << " mm, max " << d.back()
            << " mm\n";
  EXPECT_LT(mean, 0.05);
  EXPECT_LT(p95, 0.1);
  EXPECT_LT(d.back(), 2.0);
}

// The Visible Human Female CT, whose nose tip lies outside the reconstruction circle, as a partial
// model: the warning names the nose tip, the report says so, and every node of set `notImaged` lies
// at the flat cut: within 4 mm in front of it the CT holds the padding value.
TEST(PartialFieldOfView, NoseTipNotImagedIsFlaggedOnTheModel)
{
  ScratchDirectory scratch("partial-vhf");
  const fs::path dir = scratch.path();
  const ModuleRun run = RunCommand(
    Quote(std::string(MMREP_BINARY_DIR) + "/bin/FaceModelPipeline") + " " + Quote(kSampleData + "vhf_head_ct.nrrd") +
      " " + Quote(kSampleData + "vhf_head_ct.ControlPoints.mrk.json") +
      " --noPictures --allowPartialFieldOfView --outputDirectory " + Quote((dir / "speaker").string()),
    dir / "err");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto lines = run.ErrLines();
  ASSERT_EQ(lines.size(), 1u) << run.err;
  EXPECT_NE(lines[0].find("warning: partial model: "), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("the nose tip is outside the scanner's field of view"), std::string::npos) << lines[0];
  const auto report = nlohmann::json::parse(Slurp(dir / "speaker" / "report.json"));
  EXPECT_FALSE(report["fieldOfView"]["complete"].get<bool>());
  EXPECT_NE(report["fieldOfView"]["notImaged"].get<std::string>().find("the nose tip"), std::string::npos);
  const auto model = mmrep::ReadFEMesh((dir / "speaker" / "model.vtu").string());
  ASSERT_TRUE(model.nodeSets.count("notImaged"));
  const auto& cut = model.nodeSets.at("notImaged");
  EXPECT_EQ(report["fieldOfView"]["notImagedNodes"].get<std::size_t>(), cut.size());
  ASSERT_GE(cut.size(), 1u);
  const auto ct = mmrep::ReadCTImage(kSampleData + "vhf_head_ct.nrrd");
  for (const auto id : cut)
  {
    const mmrep::Point3& x = model.nodes.at(static_cast<std::size_t>(id));
    bool padded = false;
    for (double ahead = 1.0; ahead <= 4.0; ahead += 0.5)
    {
      mmrep::CTImage::PointType front;
      front[0] = x.x();
      front[1] = x.y() - ahead; // LPS: -y is anterior
      front[2] = x.z();
      mmrep::CTImage::IndexType index;
      ASSERT_TRUE(ct->TransformPhysicalPointToIndex(front, index));
      padded = padded || ct->GetPixel(index) == -1024;
    }
    EXPECT_TRUE(padded) << "node " << id << " at " << x.transpose() << ": no padding within 4 mm in front";
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInput, ::testing::ValuesIn(BadInputCases()),
                         [](const ::testing::TestParamInfo<BadInputCase>& info) { return info.param.name; });

} // namespace
