// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// SkinSkullSurfaces as a user runs it: bundled CTs (with pictures), a DICOM series, bad input.
#include "mmrepImageIO.h"
#include "mmrepModuleRunner.h"
#include "mmrepSurfaceIO.h"

#include "mmrepSurfaceChecks.h"

#include <gtest/gtest.h>
#include <itkImage.h>
#include <itkImageFileWriter.h>
#include <vtkNew.h>

using mmrep::testing::ReadReturnParameters;
using mmrep::testing::RunModuleExecutable;
using mmrep::testing::ScratchDirectory;

namespace
{
// Pictures are kept in the build tree (build/Testing/Pictures) for people to look at.
std::string PictureDir()
{
  const std::string dir = std::string(MMREP_BINARY_DIR) + "/Testing/Pictures";
  std::filesystem::create_directories(dir);
  return dir;
}
} // namespace

class SkinSkullSurfacesOnCT : public ::testing::TestWithParam<const char*>
{
};

TEST_P(SkinSkullSurfacesOnCT, OneClosedSkinOneClosedSkullAndAPicture)
{
  ScratchDirectory dir("sss");
  const std::string name = GetParam();
  const std::string picture = PictureDir() + "/SkinSkullSurfaces-" + name + ".png";
  std::filesystem::remove(picture);
  const auto run = RunModuleExecutable("SkinSkullSurfaces",
                                       {std::string(MMREP_SAMPLE_DATA) + "/" + name + ".nrrd", dir / "skin.vtp",
                                        dir / "skull.stl", "--skinMask", dir / "skin.nrrd", "--snapshot", picture,
                                        "--returnparameterfile", dir / "out.txt"},
                                       true);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("<filter-end>"), std::string::npos);
  auto skin = mmrep::ReadSurface(dir / "skin.vtp");
  auto skull = mmrep::ReadSurface(dir / "skull.stl");
  EXPECT_EQ(mmrep::testing::SurfacePieces(skin), 1);
  EXPECT_EQ(mmrep::testing::SurfacePieces(skull), 1);
  EXPECT_EQ(mmrep::testing::OpenOrNonManifoldEdges(skin), 0);
  EXPECT_EQ(mmrep::testing::OpenOrNonManifoldEdges(skull), 0);
  const auto values = ReadReturnParameters(dir / "out.txt");
  EXPECT_EQ(values.at("thresholdSource"), "histogram");
  EXPECT_EQ(std::stoll(values.at("skinVertices")), skin->GetNumberOfPoints());
  // The skull lies inside the skin: its bounds are within the skin's.
  double sb[6], kb[6];
  skin->GetBounds(sb);
  skull->GetBounds(kb);
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_GE(kb[2 * a], sb[2 * a] - 1e-6);
    EXPECT_LE(kb[2 * a + 1], sb[2 * a + 1] + 1e-6);
  }
  auto mask = mmrep::ReadMaskImage(dir / "skin.nrrd");
  EXPECT_EQ(mask->GetBufferedRegion().GetSize()[2], name == std::string("cthead") ? 113u : 93u);
  EXPECT_TRUE(std::filesystem::exists(picture));
  EXPECT_GT(std::filesystem::file_size(picture), 10000u);
}

INSTANTIATE_TEST_SUITE_P(BundledCTs, SkinSkullSurfacesOnCT, ::testing::Values("cthead", "headsq"),
                         [](const auto& info) { return std::string(info.param); });

TEST(SkinSkullSurfaces, DicomSeriesGivesTheSameSurfacesAsTheVolume)
{
  ScratchDirectory dir("sss-dicom");
  auto ct = mmrep::ReadCTImage(std::string(MMREP_SAMPLE_DATA) + "/cthead.nrrd");
  std::filesystem::create_directories(dir / "dicom");
  mmrep::WriteDicomSeries(ct, dir / "dicom");
  const auto fromDicom = RunModuleExecutable("SkinSkullSurfaces", {dir / "dicom", dir / "a.vtp", dir / "b.vtp"});
  ASSERT_EQ(fromDicom.exitCode, 0) << fromDicom.err;
  const auto fromNrrd = RunModuleExecutable(
    "SkinSkullSurfaces", {std::string(MMREP_SAMPLE_DATA) + "/cthead.nrrd", dir / "c.vtp", dir / "d.vtp"});
  ASSERT_EQ(fromNrrd.exitCode, 0) << fromNrrd.err;
  auto a = mmrep::ReadSurface(dir / "a.vtp"), c = mmrep::ReadSurface(dir / "c.vtp");
  ASSERT_EQ(a->GetNumberOfPoints(), c->GetNumberOfPoints());
  double pa[3], pc[3];
  double worst = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); i += 97)
  {
    a->GetPoint(i, pa);
    c->GetPoint(i, pc);
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, std::abs(pa[k] - pc[k]));
  }
  EXPECT_LT(worst, 1e-3); // DICOM stores positions as decimal strings
}

TEST(SkinSkullSurfaces, BadInputOneLineNonZeroNoOutput)
{
  ScratchDirectory dir("sss-bad");
  // A 2-D image.
  {
    auto img = itk::Image<short, 2>::New();
    itk::Image<short, 2>::RegionType r;
    r.SetSize({{16, 16}});
    img->SetRegions(r);
    img->Allocate(true);
    auto w = itk::ImageFileWriter<itk::Image<short, 2>>::New();
    w->SetInput(img);
    w->SetFileName(dir / "flat.nrrd");
    w->Update();
  }
  // A volume without a head: a small bright cube in air.
  {
    auto img = mmrep::CTImage::New();
    mmrep::CTImage::RegionType r;
    r.SetSize({{40, 40, 40}});
    img->SetRegions(r);
    img->Allocate(true);
    for (int k = 15; k < 25; ++k)
      for (int j = 15; j < 25; ++j)
        for (int i = 15; i < 25; ++i)
          img->SetPixel({{i, j, k}}, 1000);
    for (int i = 0; i < 40; ++i)
      img->SetPixel({{i, 2, 2}}, 2000);
    mmrep::WriteImage(img.GetPointer(), dir / "nohead.nrrd");
  }
  const std::string ct = std::string(MMREP_SAMPLE_DATA) + "/headsq.nrrd";
  {
    // The sample CT cut in the middle of its compressed data.
    const std::string bytes = mmrep::testing::Slurp(ct);
    std::ofstream(dir / "truncated.nrrd", std::ios::binary).write(bytes.data(), bytes.size() / 2);
  }
  struct Case
  {
    std::vector<std::string> args;
    std::string expect;
  };
  const std::vector<Case> cases = {
    {{dir / "missing.nrrd", dir / "s.vtp", dir / "k.vtp"}, "missing.nrrd"},
    {{dir / "flat.nrrd", dir / "s.vtp", dir / "k.vtp"}, "3"},
    {{dir / "truncated.nrrd", dir / "s.vtp", dir / "k.vtp"}, "truncated.nrrd"},
    {{dir / "nohead.nrrd", dir / "s.vtp", dir / "k.vtp"}, "no head"},
    {{ct, dir / "s.vtp", dir / "k.vtp", "--skinThreshold", "30000", "--boneThreshold", "31000"}, "empty segmentation"},
    {{ct, dir / "s.vtp", dir / "k.vtp", "--skinThreshold", "abc"}, "skinThreshold"},
    {{ct, dir / "s.xyz", dir / "k.vtp"}, "xyz"},
    {{ct, dir / "no-such-folder/s.vtp", dir / "k.vtp"}, "no-such-folder"},
  };
  for (const auto& c : cases)
  {
    const auto run = RunModuleExecutable("SkinSkullSurfaces", c.args);
    EXPECT_NE(run.exitCode, 0) << c.expect;
    const auto lines = run.ErrLines();
    ASSERT_EQ(lines.size(), 1u) << run.err;
    EXPECT_NE(lines[0].find(c.expect), std::string::npos) << lines[0];
    for (const auto& e : dir.Entries())
      EXPECT_TRUE(e == "flat.nrrd" || e == "nohead.nrrd" || e == "truncated.nrrd")
        << "left behind: " << e << " (" << c.expect << ")";
  }
}
