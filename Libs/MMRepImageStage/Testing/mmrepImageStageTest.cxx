// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Thresholds, masks and surfaces of the image stage, on the bundled CTs and on constructed volumes.
#include "mmrepCTThresholds.h"
#include "mmrepHeadSegmentation.h"
#include "mmrepSurfaceDistanceMap.h"
#include "mmrepSurfaceExtraction.h"

#include "mmrepSurfaceChecks.h"

#include <gtest/gtest.h>
#include <itkConnectedComponentImageFilter.h>
#include <vtkNew.h>

#include <cmath>
#include <limits>
#include <random>

namespace
{
const double NaN = std::numeric_limits<double>::quiet_NaN();

mmrep::CTImage::Pointer Sample(const std::string& name)
{
  return mmrep::ReadCTImage(std::string(MMREP_SAMPLE_DATA) + "/" + name);
}

mmrep::MaskImage::Pointer NewMask(unsigned nx, unsigned ny, unsigned nz)
{
  auto m = mmrep::MaskImage::New();
  mmrep::MaskImage::RegionType r;
  r.SetSize({{nx, ny, nz}});
  m->SetRegions(r);
  m->Allocate(true);
  return m;
}

// Independent count of 6-connected components (ITK) of voxels equal to `value`.
unsigned long Components(const mmrep::MaskImage* mask, unsigned char value)
{
  auto sel = mmrep::MaskImage::New();
  sel->CopyInformation(mask);
  sel->SetRegions(mask->GetBufferedRegion());
  sel->Allocate();
  const auto n = mask->GetBufferedRegion().GetNumberOfPixels();
  for (std::size_t i = 0; i < n; ++i)
    sel->GetBufferPointer()[i] = mask->GetBufferPointer()[i] == value;
  auto cc = itk::ConnectedComponentImageFilter<mmrep::MaskImage, itk::Image<unsigned, 3>>::New();
  cc->SetInput(sel);
  cc->Update();
  return cc->GetObjectCount();
}

} // namespace

TEST(ImageStageThresholds, HistogramSplitsAirTissueBoneOnBundledCTs)
{
  for (const char* name : {"cthead.nrrd", "headsq.nrrd"})
  {
    auto ct = Sample(name);
    EXPECT_FALSE(mmrep::LooksLikeHounsfield(ct)) << name;
    const auto t = mmrep::ChooseThresholds(ct, mmrep::ThresholdMode::Automatic, NaN, NaN);
    std::cout << name << ": skin " << t.skin << ", bone " << t.bone << " (" << t.source << ")\n";
    EXPECT_EQ(t.source, "histogram");
    // Air is below 200 and soft tissue peaks near 1000-1060 in both scans (see the sample README):
    // the skin threshold must fall between, the bone threshold above the soft-tissue peak.
    EXPECT_GT(t.skin, 200);
    EXPECT_LT(t.skin, 900);
    EXPECT_GT(t.bone, 1150);
    EXPECT_LT(t.bone, 2000);
  }
}

TEST(ImageStageThresholds, HounsfieldDataGetsHounsfieldDefaultsAndExplicitWins)
{
  auto ct = Sample("headsq.nrrd");
  short* p = ct->GetBufferPointer();
  for (std::size_t i = 0; i < ct->GetBufferedRegion().GetNumberOfPixels(); ++i)
    p[i] = static_cast<short>(p[i] - 1024); // scanner units to an HU-like scale
  EXPECT_TRUE(mmrep::LooksLikeHounsfield(ct));
  auto t = mmrep::ChooseThresholds(ct, mmrep::ThresholdMode::Automatic, NaN, NaN);
  EXPECT_EQ(t.source, "hounsfield");
  EXPECT_EQ(t.skin, mmrep::kHounsfieldSkinThreshold);
  EXPECT_EQ(t.bone, mmrep::kHounsfieldBoneThreshold);
  t = mmrep::ChooseThresholds(ct, mmrep::ThresholdMode::Automatic, -400, 250);
  EXPECT_EQ(t.source, "explicit");
  EXPECT_EQ(t.skin, -400);
  EXPECT_THROW(mmrep::ChooseThresholds(ct, mmrep::ThresholdMode::Automatic, 500, 100), std::runtime_error);
}

TEST(ImageStageThresholds, ConstantVolumeHasNoHead)
{
  auto ct = mmrep::CTImage::New();
  mmrep::CTImage::RegionType r;
  r.SetSize({{10, 10, 10}});
  ct->SetRegions(r);
  ct->Allocate();
  ct->FillBuffer(40);
  EXPECT_THROW(mmrep::ChooseThresholds(ct, mmrep::ThresholdMode::Histogram, NaN, NaN), std::runtime_error);
}

TEST(ImageStageFill, EnclosedAirFilledOpenAirKept)
{
  // A 20^3 block of tissue in a 30^3 volume (axial axis k) with: a closed cavity (sinus), a
  // vertical tunnel leaving through the bottom face (airway), and a side notch open to the air.
  auto m = NewMask(30, 30, 30);
  auto at = [&](int i, int j, int k) -> unsigned char& { return m->GetBufferPointer()[i + 30 * (j + 30 * k)]; };
  for (int k = 0; k < 30; ++k)
    for (int j = 5; j < 25; ++j)
      for (int i = 5; i < 25; ++i)
        at(i, j, k) = k >= 5 && k < 25 ? 1 : 0;
  for (int k = 5; k < 25; ++k) // extend the block down to the bottom face, like a neck
    for (int j = 10; j < 20; ++j)
      for (int i = 10; i < 20; ++i)
        at(i, j, k) = 1;
  for (int k = 0; k < 5; ++k)
    for (int j = 10; j < 20; ++j)
      for (int i = 10; i < 20; ++i)
        at(i, j, k) = 1;
  for (int k = 15; k < 18; ++k) // sinus
    for (int j = 15; j < 18; ++j)
      for (int i = 15; i < 18; ++i)
        at(i, j, k) = 0;
  for (int k = 0; k < 20; ++k) // airway from the bottom face up to k = 19
    at(14, 14, k) = 0;
  for (int k = 20; k < 23; ++k) // notch open on the side (i = 5 face)
    for (int i = 5; i < 9; ++i)
      at(i, 20, k) = 0;

  auto threeD = NewMask(30, 30, 30);
  std::copy_n(m->GetBufferPointer(), 27000, threeD->GetBufferPointer());
  mmrep::FillEnclosedBackground(threeD, false, 2);
  auto a3 = [&](int i, int j, int k) { return threeD->GetBufferPointer()[i + 30 * (j + 30 * k)]; };
  EXPECT_EQ(a3(16, 16, 16), 1); // sinus filled
  EXPECT_EQ(a3(14, 14, 10), 0); // airway open to the bottom face: kept in 3-D
  EXPECT_EQ(a3(6, 20, 21), 0);  // notch kept

  mmrep::FillEnclosedBackground(m, true, 2);
  auto a = [&](int i, int j, int k) { return m->GetBufferPointer()[i + 30 * (j + 30 * k)]; };
  EXPECT_EQ(a(16, 16, 16), 1);
  EXPECT_EQ(a(14, 14, 10), 1); // airway enclosed in every axial slice: filled
  EXPECT_EQ(a(14, 14, 0), 1);
  EXPECT_EQ(a(6, 20, 21), 0); // notch open within its slices: kept
  EXPECT_EQ(a(2, 2, 2), 0);   // outside air kept
  EXPECT_EQ(Components(m, 0), 1u);
}

class ImageStageHead : public ::testing::TestWithParam<const char*>
{
};

TEST_P(ImageStageHead, OneHeadOneSkullClosedSurfaces)
{
  auto ct = Sample(GetParam());
  const auto t = mmrep::ChooseThresholds(ct, mmrep::ThresholdMode::Automatic, NaN, NaN);
  mmrep::HeadSegmentationOptions o;
  o.skinThreshold = t.skin;
  o.boneThreshold = t.bone;
  const auto head = mmrep::SegmentHead(ct, o);
  std::cout << GetParam() << ": head " << head.skinVolume / 1000 << " ml, bone " << head.boneVolume / 1000 << " ml\n";
  // An adult head with part of the neck: a few litres; its bone: several hundred millilitres.
  EXPECT_GT(head.skinVolume, 2.0e6);
  EXPECT_LT(head.skinVolume, 8.0e6);
  EXPECT_GT(head.boneVolume, 2.0e5);
  EXPECT_LT(head.boneVolume, 2.0e6);
  EXPECT_EQ(Components(head.skin, 1), 1u);
  EXPECT_EQ(Components(head.skin, 0), 1u); // no enclosed air left
  EXPECT_EQ(Components(head.bone, 1), 1u);
  EXPECT_EQ(Components(head.bone, 0), 1u);

  // Surfaces straight from the masks, without keeping only the largest piece: already one each,
  // closed and 2-manifold.
  mmrep::SurfaceExtractionOptions s;
  s.largestPieceOnly = false;
  auto skin = mmrep::ExtractSurface(mmrep::MaskedIntensities(ct, head.skin, t.skin), t.skin, s);
  auto skull = mmrep::ExtractSurface(mmrep::MaskedIntensities(ct, head.bone, t.bone), t.bone, s);
  EXPECT_EQ(mmrep::testing::SurfacePieces(skin), 1);
  EXPECT_EQ(mmrep::testing::SurfacePieces(skull), 1);
  EXPECT_EQ(mmrep::testing::OpenOrNonManifoldEdges(skin), 0);
  EXPECT_EQ(mmrep::testing::OpenOrNonManifoldEdges(skull), 0);
}

INSTANTIATE_TEST_SUITE_P(BundledCTs, ImageStageHead, ::testing::Values("cthead.nrrd", "headsq.nrrd"),
                         [](const auto& info) {
                           return std::string(info.param).substr(0, std::string(info.param).find('.'));
                         });

// A small head (a child's, or an adult CT shrunk 2× per axis with its spacing kept: one eighth
// of the volume, about 470 ml) is found as a head, and measures what the full-size head does / 8.
TEST(ImageStageHead, SmallHeadInASmallVolumeIsFound)
{
  auto ct = Sample("cthead.nrrd");
  const auto t = mmrep::ChooseThresholds(ct, mmrep::ThresholdMode::Automatic, NaN, NaN);
  mmrep::HeadSegmentationOptions o;
  o.skinThreshold = t.skin;
  o.boneThreshold = t.bone;
  const auto full = mmrep::SegmentHead(ct, o);

  auto small = mmrep::CTImage::New();
  small->CopyInformation(ct);
  mmrep::CTImage::RegionType r;
  const auto size = ct->GetLargestPossibleRegion().GetSize();
  r.SetSize({{size[0] / 2, size[1] / 2, size[2] / 2}});
  small->SetRegions(r);
  small->Allocate();
  for (itk::IndexValueType k = 0; k < static_cast<itk::IndexValueType>(size[2] / 2); ++k)
    for (itk::IndexValueType j = 0; j < static_cast<itk::IndexValueType>(size[1] / 2); ++j)
      for (itk::IndexValueType i = 0; i < static_cast<itk::IndexValueType>(size[0] / 2); ++i)
        small->SetPixel({{i, j, k}}, ct->GetPixel({{2 * i, 2 * j, 2 * k}}));
  const auto head = mmrep::SegmentHead(small, o);
  std::cout << "full head " << full.skinVolume / 1000 << " ml, shrunk " << head.skinVolume / 1000 << " ml\n";
  EXPECT_LT(head.skinVolume, 5.0e5); // below the former fixed 500 ml bound
  EXPECT_NEAR(head.skinVolume, full.skinVolume / 8, 0.1 * full.skinVolume / 8);
  EXPECT_NEAR(head.boneVolume, full.boneVolume / 8, 0.2 * full.boneVolume / 8);
  EXPECT_EQ(Components(head.skin, 1), 1u);
}

TEST(ImageStageHeadErrors, EmptySegmentationAndNoHead)
{
  auto ct = Sample("headsq.nrrd");
  mmrep::HeadSegmentationOptions o;
  o.skinThreshold = 30000;
  o.boneThreshold = 31000;
  try
  {
    mmrep::SegmentHead(ct, o);
    FAIL() << "no exception";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("empty segmentation"), std::string::npos) << e.what();
  }
  // A small bright blob (a phantom, a few ml) in air is not a head.
  auto blob = mmrep::CTImage::New();
  mmrep::CTImage::RegionType r;
  r.SetSize({{40, 40, 40}});
  blob->SetRegions(r);
  blob->Allocate();
  blob->FillBuffer(0);
  for (int k = 15; k < 25; ++k)
    for (int j = 15; j < 25; ++j)
      for (int i = 15; i < 25; ++i)
        blob->SetPixel({{i, j, k}}, 1000);
  o.skinThreshold = 500;
  o.boneThreshold = 1500;
  try
  {
    mmrep::SegmentHead(blob, o);
    FAIL() << "no exception";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("no head"), std::string::npos) << e.what();
  }
}

TEST(ImageStageOpening, EqualsBruteForceBallOpening)
{
  // Random blobs with thin bridges; opening by a Euclidean ball of radius r (index units) computed
  // by brute force: erosion keeps p when every voxel within r is set (outside counts as set, as
  // the distance transform only sees background inside the image), dilation sets p when an eroded
  // voxel lies within r.
  const int n = 18;
  std::mt19937 rng(3);
  for (unsigned r : {1u, 2u})
  {
    auto m = NewMask(n, n, n);
    auto at = [&](mmrep::MaskImage* img, int i, int j, int k) -> unsigned char& {
      return img->GetBufferPointer()[i + n * (j + n * k)];
    };
    for (int b = 0; b < 6; ++b)
    {
      const int ci = rng() % n, cj = rng() % n, ck = rng() % n, rad = 2 + rng() % 4;
      for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i)
            if ((i - ci) * (i - ci) + (j - cj) * (j - cj) + (k - ck) * (k - ck) <= rad * rad)
              at(m, i, j, k) = 1;
    }
    for (int i = 0; i < n; ++i) // a one-voxel bridge the opening must remove
      at(m, i, n / 2, n / 2) = 1;
    auto eroded = NewMask(n, n, n), expected = NewMask(n, n, n);
    const int R = static_cast<int>(r);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
          bool keep = true;
          for (int dk = -R; dk <= R && keep; ++dk)
            for (int dj = -R; dj <= R && keep; ++dj)
              for (int di = -R; di <= R && keep; ++di)
              {
                const int x = i + di, y = j + dj, z = k + dk;
                if (di * di + dj * dj + dk * dk > R * R || x < 0 || y < 0 || z < 0 || x >= n || y >= n || z >= n)
                  continue;
                keep = at(m, x, y, z) != 0;
              }
          at(eroded, i, j, k) = keep;
        }
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
          bool set = false;
          for (int dk = -R; dk <= R && !set; ++dk)
            for (int dj = -R; dj <= R && !set; ++dj)
              for (int di = -R; di <= R && !set; ++di)
              {
                const int x = i + di, y = j + dj, z = k + dk;
                if (di * di + dj * dj + dk * dk > R * R || x < 0 || y < 0 || z < 0 || x >= n || y >= n || z >= n)
                  continue;
                set = at(eroded, x, y, z) != 0;
              }
          at(expected, i, j, k) = set;
        }
    mmrep::OpenWithBall(m, r);
    std::size_t differences = 0, kept = 0;
    for (int v = 0; v < n * n * n; ++v)
    {
      differences += m->GetBufferPointer()[v] != expected->GetBufferPointer()[v];
      kept += expected->GetBufferPointer()[v];
    }
    EXPECT_GT(kept, 0u) << "radius " << r;
    EXPECT_EQ(differences, 0u) << "radius " << r;
  }
}

TEST(ImageStageSignedMap, RealSkinSignAgreesWithTheHeadMask)
{
  // The skin of headsq, signed distance at its own voxel grid spacing: voxel centres well inside
  // the filled head mask (more than one voxel from the surface) are negative, well outside positive.
  auto ct = Sample("headsq.nrrd");
  const auto t = mmrep::ChooseThresholds(ct, mmrep::ThresholdMode::Automatic, NaN, NaN);
  mmrep::HeadSegmentationOptions o;
  o.skinThreshold = t.skin;
  o.boneThreshold = t.bone;
  const auto head = mmrep::SegmentHead(ct, o);
  auto skin = mmrep::ExtractSurface(mmrep::MaskedIntensities(ct, head.skin, t.skin), t.skin);
  mmrep::SurfaceDistanceMapOptions m;
  m.spacing = 2.0;
  m.margin = 4;
  m.signedDistance = true;
  auto map = mmrep::ComputeSurfaceDistanceMap(skin, m);
  std::size_t checked = 0, wrong = 0;
  const auto size = head.skin->GetBufferedRegion().GetSize();
  for (unsigned k = 0; k < size[2]; k += 2)
    for (unsigned j = 0; j < size[1]; j += 2)
      for (unsigned i = 0; i < size[0]; i += 2)
      {
        mmrep::MaskImage::IndexType idx{{i, j, k}};
        mmrep::MaskImage::PointType p;
        head.skin->TransformIndexToPhysicalPoint(idx, p);
        mmrep::FloatImage::IndexType q;
        if (!map->TransformPhysicalPointToIndex(p, q))
          continue;
        const float d = map->GetPixel(q);
        if (std::abs(d) < 4.0f) // within two map voxels of the surface: the mask's staircase differs
          continue;
        ++checked;
        wrong += (head.skin->GetPixel(idx) != 0) != (d < 0);
      }
  EXPECT_GT(checked, 5000u);
  EXPECT_EQ(wrong, 0u);
}
