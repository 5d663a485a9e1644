// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Not-imaged tissue: a constructed scan with a reconstruction circle against a brute-force count,
// a scan whose air is clamped to the minimum, and the bundled CTs (cthead: none; VHF: the nose tip).
#include "mmrepImageIO.h"
#include "mmrepNotImaged.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <tuple>

namespace
{
constexpr short kPadding = -1024;

// 40 x 40 x 20 voxels of 1 mm: noisy air (never the padding value) inside the circle of radius 17
// of each axial slice, the padding outside it; a ball of tissue (radius 10) that reaches past the
// circle at the front (small j). With clampedAir, all air is the padding value and there is no circle.
mmrep::CTImage::Pointer Scan(bool clampedAir)
{
  auto ct = mmrep::CTImage::New();
  mmrep::CTImage::RegionType r;
  r.SetSize({{40, 40, 20}});
  ct->SetRegions(r);
  ct->Allocate();
  std::mt19937 noise(7);
  std::uniform_int_distribution<int> air(-1015, -985);
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i)
      {
        const bool inCircle = std::hypot(i - 19.5, j - 19.5) <= 17.0;
        const bool inBall =
          std::sqrt((i - 19.5) * (i - 19.5) + (j - 9.0) * (j - 9.0) + (k - 10.0) * (k - 10.0)) <= 10.0;
        short v = clampedAir ? kPadding : static_cast<short>(air(noise));
        if (inBall && (inCircle || clampedAir))
          v = 40;
        else if (!inCircle && !clampedAir)
          v = kPadding;
        ct->SetPixel({{i, j, k}}, v);
      }
  return ct;
}

TEST(NotImaged, CutIsTheTissueTouchingTheCircleAsCountedByBruteForce)
{
  const auto ct = Scan(false);
  const auto found = mmrep::FindNotImagedTissue(ct, -300.0);
  ASSERT_TRUE(found.padded);
  EXPECT_EQ(found.paddingValue, kPadding);
  // Brute force: tissue voxels with a face neighbour outside the circle and none in the air inside it.
  std::set<std::tuple<int, int, int>> expected;
  std::size_t outside = 0;
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i)
      {
        if (std::hypot(i - 19.5, j - 19.5) > 17.0)
          ++outside;
        if (ct->GetPixel({{i, j, k}}) < -300)
          continue;
        const int n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        bool outsideCircle = false, measuredAir = false;
        for (const auto& d : n)
        {
          const int a = i + d[0], b = j + d[1], c = k + d[2];
          if (a < 0 || a >= 40 || b < 0 || b >= 40 || c < 0 || c >= 20)
            continue;
          if (std::hypot(a - 19.5, b - 19.5) > 17.0)
            outsideCircle = true;
          else if (ct->GetPixel({{a, b, c}}) < -300)
            measuredAir = true;
        }
        if (outsideCircle && !measuredAir)
          expected.insert({i, j, k});
      }
  EXPECT_EQ(found.paddingVoxels, outside);
  ASSERT_GT(expected.size(), 20u);
  std::set<std::tuple<int, int, int>> got;
  for (const auto& p : found.cut)
    got.insert({static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())),
                static_cast<int>(std::lround(p.z()))});
  EXPECT_EQ(got, expected);
  EXPECT_EQ(found.cut.size(), expected.size());

  // A box that holds only the back of the ball: nothing cut there.
  const std::array<double, 6> back = {0, 39, 12, 39, 0, 19};
  EXPECT_TRUE(mmrep::FindNotImagedTissue(ct, -300.0, &back).cut.empty());
}

TEST(NotImaged, AirClampedToTheMinimumIsNotACircle)
{
  const auto found = mmrep::FindNotImagedTissue(Scan(true), -300.0);
  EXPECT_FALSE(found.padded);
  EXPECT_TRUE(found.cut.empty());
}

TEST(NotImaged, BundledCTs)
{
  // cthead: a few stray voxels of its minimum (0) in noisy air, no circle.
  const auto cthead = mmrep::ReadCTImage(std::string(MMREP_SAMPLE_DATA) + "/cthead.nrrd");
  const auto none = mmrep::FindNotImagedTissue(cthead, 562.5);
  EXPECT_FALSE(none.padded);
  EXPECT_TRUE(none.cut.empty());
  // VHF: the nose tip is cut flat at y ~ 131 mm (README of the sample data); over the face, the cut
  // is there and nowhere else.
  const auto vhf = mmrep::ReadCTImage(std::string(MMREP_SAMPLE_DATA) + "/vhf_head_ct.nrrd");
  const std::array<double, 6> face = {150, 350, 116, 220, 40, 150};
  const auto nose = mmrep::FindNotImagedTissue(vhf, -300.0, &face);
  ASSERT_TRUE(nose.padded);
  EXPECT_EQ(nose.paddingValue, -1024);
  EXPECT_GE(nose.cut.size(), 25u);
  for (const auto& p : nose.cut)
  {
    EXPECT_LE(p.y(), 134.0);
    EXPECT_GE(p.z(), 80.0);
    EXPECT_LE(p.z(), 120.0);
    EXPECT_NEAR(p.x(), 254.0, 25.0); // within 25 mm of the mid-sagittal plane
  }
}

} // namespace
