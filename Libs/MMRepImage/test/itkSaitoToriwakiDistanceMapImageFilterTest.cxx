// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// itk::SaitoToriwakiDistanceMapImageFilter against independent references: brute-force O(N^2) distances on
// random images, analytic distances, itk::SignedMaurerDistanceMapImageFilter on the bundled CTs, and itself
// with other thread counts (bit-identical).
#include "itkSaitoToriwakiDistanceMapImageFilter.h"

#include <itkBinaryThresholdImageFilter.h>
#include <itkImageFileReader.h>
#include <itkImageRegionConstIteratorWithIndex.h>
#include <itkSignedMaurerDistanceMapImageFilter.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
template <unsigned int D> using MaskImage = itk::Image<unsigned char, D>;
template <unsigned int D> using DistanceImage = itk::Image<float, D>;
template <unsigned int D> using Filter = itk::SaitoToriwakiDistanceMapImageFilter<MaskImage<D>, DistanceImage<D>>;
using CTImage = itk::Image<short, 3>;

// Random mask with values 0..labels-1 (label > 0 with probability `density`); never empty.
template <unsigned int D>
typename MaskImage<D>::Pointer RandomMask(const std::array<unsigned int, D>& size, const std::array<double, D>& spacing,
                                          unsigned int seed, double density, unsigned char labels = 2)
{
  auto image = MaskImage<D>::New();
  typename MaskImage<D>::SizeType sz;
  typename MaskImage<D>::SpacingType sp;
  for (unsigned int k = 0; k < D; ++k)
  {
    sz[k] = size[k];
    sp[k] = spacing[k];
  }
  image->SetRegions(sz);
  image->SetSpacing(sp);
  image->Allocate();
  std::mt19937 rng(seed);
  unsigned char* p = image->GetBufferPointer();
  const size_t n = image->GetBufferedRegion().GetNumberOfPixels();
  for (size_t i = 0; i < n; ++i)
  {
    const bool on = static_cast<double>(rng() % 100000) < density * 100000.0;
    p[i] = on ? static_cast<unsigned char>(1 + rng() % (labels - 1)) : 0;
  }
  p[(seed * 7919u) % n] = 1; // at least one foreground voxel
  return image;
}

template <unsigned int D> std::vector<itk::Index<D>> AllIndices(const itk::ImageRegion<D>& region)
{
  std::vector<itk::Index<D>> out;
  auto empty = MaskImage<D>::New();
  empty->SetRegions(region);
  empty->Allocate();
  for (itk::ImageRegionConstIteratorWithIndex<MaskImage<D>> it(empty, region); !it.IsAtEnd(); ++it)
  {
    out.push_back(it.GetIndex());
  }
  return out; // buffer order
}

// Boundary as SignedMaurer defines it: foreground with a background voxel among its in-image 3^D-1 neighbours.
template <unsigned int D> std::vector<char> BruteBoundary(const MaskImage<D>* mask, const std::vector<char>& foreground)
{
  const auto region = mask->GetBufferedRegion();
  const auto indices = AllIndices<D>(region);
  std::vector<char> boundary(indices.size(), 0);
  for (size_t p = 0; p < indices.size(); ++p)
  {
    if (!foreground[p])
    {
      continue;
    }
    unsigned int count = 1;
    for (unsigned int k = 0; k < D; ++k)
    {
      count *= 3;
    }
    for (unsigned int code = 0; code < count; ++code)
    {
      itk::Index<D> q = indices[p];
      unsigned int c = code;
      for (unsigned int k = 0; k < D; ++k)
      {
        q[k] += static_cast<int>(c % 3) - 1;
        c /= 3;
      }
      if (region.IsInside(q) && !foreground[mask->ComputeOffset(q)])
      {
        boundary[p] = 1;
      }
    }
  }
  return boundary;
}

// min over features of the squared Euclidean distance, by brute force.
template <unsigned int D>
std::vector<double> BruteSquared(const MaskImage<D>* mask, const std::vector<char>& feature, bool useSpacing)
{
  const auto indices = AllIndices<D>(mask->GetBufferedRegion());
  std::vector<size_t> sites;
  for (size_t p = 0; p < indices.size(); ++p)
  {
    if (feature[p])
    {
      sites.push_back(p);
    }
  }
  std::vector<double> out(indices.size(), std::numeric_limits<double>::infinity());
  for (size_t p = 0; p < indices.size(); ++p)
  {
    for (size_t s : sites)
    {
      double sum = 0;
      for (unsigned int k = 0; k < D; ++k)
      {
        const double w = useSpacing ? mask->GetSpacing()[k] : 1.0;
        const double d = (indices[p][k] - indices[s][k]) * w;
        sum += d * d;
      }
      out[p] = std::min(out[p], sum);
    }
  }
  return out;
}

template <unsigned int D> std::vector<char> ForegroundOf(const MaskImage<D>* mask, int foregroundLabel = -1)
{
  const size_t n = mask->GetBufferedRegion().GetNumberOfPixels();
  std::vector<char> fg(n);
  for (size_t i = 0; i < n; ++i)
  {
    const int v = mask->GetBufferPointer()[i];
    fg[i] = foregroundLabel < 0 ? v != 0 : v == foregroundLabel;
  }
  return fg;
}

struct Mode
{
  bool squared = false;
  bool signedDistance = false;
  bool insideIsPositive = false;
  bool useSpacing = true;
};

template <unsigned int D>
std::vector<double> BruteReference(const MaskImage<D>* mask, const Mode& m, int foregroundLabel = -1)
{
  const auto fg = ForegroundOf<D>(mask, foregroundLabel);
  const auto feature = m.signedDistance ? BruteBoundary<D>(mask, fg) : fg;
  auto out = BruteSquared<D>(mask, feature, m.useSpacing);
  for (size_t p = 0; p < out.size(); ++p)
  {
    double v = m.squared ? out[p] : std::sqrt(out[p]);
    if (m.signedDistance && (fg[p] != 0) != m.insideIsPositive)
    {
      v = -v;
    }
    out[p] = v;
  }
  return out;
}

template <unsigned int D>
typename DistanceImage<D>::Pointer RunOurs(const MaskImage<D>* mask, const Mode& m, unsigned int workUnits = 2,
                                           bool vectors = false)
{
  auto filter = Filter<D>::New();
  filter->SetInput(mask);
  filter->SetSquaredDistance(m.squared);
  filter->SetSignedDistance(m.signedDistance);
  filter->SetInsideIsPositive(m.insideIsPositive);
  filter->SetUseImageSpacing(m.useSpacing);
  filter->SetComputeNearestVector(vectors);
  filter->SetNumberOfWorkUnits(workUnits);
  filter->Update();
  return filter->GetOutput();
}

template <unsigned int D>
void ExpectNear(const DistanceImage<D>* ours, const std::vector<double>& reference, double relative,
                const std::string& what)
{
  size_t failures = 0;
  for (size_t p = 0; p < reference.size(); ++p)
  {
    const double a = ours->GetBufferPointer()[p];
    const double b = reference[p];
    if (!(std::abs(a - b) <= relative * std::max(1.0, std::abs(b))) && failures++ < 5)
    {
      ADD_FAILURE() << what << ": voxel " << p << " ours " << a << " reference " << b;
    }
  }
  EXPECT_EQ(failures, 0u) << what;
}

std::string ModeName(const Mode& m)
{
  return std::string(m.signedDistance ? "signed" : "unsigned") + (m.squared ? " squared" : "") +
         (m.insideIsPositive ? " inside+" : "") + (m.useSpacing ? "" : " no-spacing");
}

TEST(SaitoToriwaki, RandomImagesMatchBruteForce)
{
  const std::array<unsigned int, 3> size{67, 10, 7}; // 67 > 64: two x-blocks in the strided passes
  const std::array<double, 3> spacing{0.7, 1.3, 2.1};
  for (unsigned int seed : {1u, 2u, 3u, 4u})
  {
    for (double density : {0.003, 0.05, 0.5, 0.95})
    {
      const auto mask = RandomMask<3>(size, spacing, seed, density);
      const auto fg = ForegroundOf<3>(mask);
      ASSERT_GT(std::count(fg.begin(), fg.end(), 0), 0) << "need background for the signed cases";
      for (bool signedDistance : {false, true})
      {
        for (bool squared : {false, true})
        {
          for (bool useSpacing : {true, false})
          {
            const Mode m{squared, signedDistance, signedDistance && seed % 2 == 0, useSpacing};
            const auto ours = RunOurs<3>(mask, m);
            ExpectNear<3>(ours, BruteReference<3>(mask, m), 1e-6,
                          "seed " + std::to_string(seed) + " density " + std::to_string(density) + " " + ModeName(m));
          }
        }
      }
    }
  }
}

TEST(SaitoToriwaki, SingleVoxelGivesAnalyticDistances)
{
  auto mask = RandomMask<3>({40, 35, 21}, {0.7, 1.3, 2.1}, 9, 0.0);
  const itk::Index<3> site{{33, 4, 17}};
  std::fill_n(mask->GetBufferPointer(), mask->GetBufferedRegion().GetNumberOfPixels(), 0);
  mask->SetPixel(site, 1);
  const auto out = RunOurs<3>(mask, Mode{});
  size_t failures = 0;
  for (const auto& index : AllIndices<3>(mask->GetBufferedRegion()))
  {
    double sum = 0;
    for (unsigned int k = 0; k < 3; ++k)
    {
      const double d = (index[k] - site[k]) * mask->GetSpacing()[k];
      sum += d * d;
    }
    if (std::abs(out->GetPixel(index) - std::sqrt(sum)) > 1e-6 * std::max(1.0, std::sqrt(sum)))
    {
      ++failures;
    }
  }
  EXPECT_EQ(failures, 0u);
}

TEST(SaitoToriwaki, ForegroundValueSelectsOneLabel)
{
  const auto mask = RandomMask<3>({17, 12, 9}, {0.7, 1.3, 2.1}, 5, 0.4, 4); // labels 0..3
  for (bool signedDistance : {false, true})
  {
    auto filter = Filter<3>::New();
    filter->SetInput(mask);
    filter->SetForegroundValue(2);
    EXPECT_TRUE(filter->GetUseForegroundValue());
    filter->SetSignedDistance(signedDistance);
    filter->Update();
    const Mode m{false, signedDistance, false, true};
    ExpectNear<3>(filter->GetOutput(), BruteReference<3>(mask, m, 2), 1e-6, "label 2 " + ModeName(m));
  }
}

// p + vector lands on a feature voxel at exactly the output distance; direction and origin are honoured.
TEST(SaitoToriwaki, NearestVectorPointsToNearestFeature)
{
  auto mask = RandomMask<3>({21, 14, 10}, {0.7, 1.3, 2.1}, 11, 0.03);
  // Rotation about z by 30 degrees, and an origin: vectors are in physical (LPS) space.
  itk::Matrix<double, 3, 3> direction;
  direction.SetIdentity();
  direction[0][0] = std::cos(0.5236);
  direction[0][1] = -std::sin(0.5236);
  direction[1][0] = std::sin(0.5236);
  direction[1][1] = std::cos(0.5236);
  mask->SetDirection(direction);
  mask->SetOrigin(itk::Point<double, 3>(std::array<double, 3>{{-12.0, 40.5, 7.25}}.data()));
  for (bool signedDistance : {false, true})
  {
    const Mode m{false, signedDistance, false, true};
    auto filter = Filter<3>::New();
    filter->SetInput(mask);
    filter->SetSignedDistance(signedDistance);
    filter->ComputeNearestVectorOn();
    filter->Update();
    const auto* out = filter->GetOutput();
    const auto* vec = filter->GetNearestVectorOutput();
    ASSERT_EQ(vec->GetBufferedRegion(), mask->GetBufferedRegion());

    const auto fg = ForegroundOf<3>(mask);
    const auto feature = signedDistance ? BruteBoundary<3>(mask, fg) : fg;
    const auto reference = BruteReference<3>(mask, m);
    size_t failures = 0;
    for (const auto& index : AllIndices<3>(mask->GetBufferedRegion()))
    {
      const size_t p = mask->ComputeOffset(index);
      const auto v = vec->GetPixel(index);
      itk::Point<double, 3> x;
      mask->TransformIndexToPhysicalPoint(index, x);
      for (unsigned int k = 0; k < 3; ++k)
      {
        x[k] += v[k];
      }
      itk::ContinuousIndex<double, 3> ci;
      mask->TransformPhysicalPointToContinuousIndex(x, ci);
      itk::Index<3> q;
      bool integral = true;
      for (unsigned int k = 0; k < 3; ++k)
      {
        q[k] = static_cast<itk::IndexValueType>(std::lround(ci[k]));
        integral = integral && std::abs(ci[k] - q[k]) < 1e-3;
      }
      const bool ok = integral && mask->GetBufferedRegion().IsInside(q) && feature[mask->ComputeOffset(q)] &&
                      std::abs(v.GetNorm() - std::abs(reference[p])) <= 1e-5 * std::max(1.0, std::abs(reference[p])) &&
                      std::abs(out->GetPixel(index) - reference[p]) <= 1e-6 * std::max(1.0, std::abs(reference[p]));
      if (!ok && failures++ < 5)
      {
        ADD_FAILURE() << ModeName(m) << " voxel " << index << " vector " << v << " reference " << reference[p];
      }
    }
    EXPECT_EQ(failures, 0u);

    // Tracking the arg-min does not change the distances.
    const auto plain = RunOurs<3>(mask, m);
    EXPECT_EQ(0, std::memcmp(plain->GetBufferPointer(), out->GetBufferPointer(),
                             sizeof(float) * mask->GetBufferedRegion().GetNumberOfPixels()));
  }
}

TEST(SaitoToriwaki, NearestVectorOutputIsEmptyWhenOff)
{
  const auto mask = RandomMask<3>({8, 7, 6}, {1, 1, 1}, 3, 0.2);
  auto filter = Filter<3>::New();
  filter->SetInput(mask);
  filter->Update();
  EXPECT_EQ(filter->GetNearestVectorOutput()->GetBufferedRegion().GetNumberOfPixels(), 0u);
}

TEST(SaitoToriwaki, TwoDimensionalMatchesBruteForce)
{
  for (unsigned int seed : {1u, 2u, 3u})
  {
    const auto mask = RandomMask<2>({37, 23}, {0.7, 1.3}, seed, 0.04);
    for (bool signedDistance : {false, true})
    {
      for (bool squared : {false, true})
      {
        const Mode m{squared, signedDistance, false, true};
        auto filter = itk::SaitoToriwakiDistanceMapImageFilter<MaskImage<2>, DistanceImage<2>>::New();
        filter->SetInput(mask);
        filter->SetSquaredDistance(squared);
        filter->SetSignedDistance(signedDistance);
        filter->ComputeNearestVectorOn();
        filter->Update();
        const auto reference = BruteReference<2>(mask, m);
        ExpectNear<2>(filter->GetOutput(), reference, 1e-6, "2-D seed " + std::to_string(seed) + " " + ModeName(m));
        // |vector|^2 or |vector| equals the distance.
        for (size_t p = 0; p < reference.size(); ++p)
        {
          const double norm = filter->GetNearestVectorOutput()->GetBufferPointer()[p].GetNorm();
          const double expected = squared ? std::sqrt(std::abs(reference[p])) : std::abs(reference[p]);
          ASSERT_NEAR(norm, expected, 1e-5 * std::max(1.0, expected)) << "voxel " << p;
        }
      }
    }
  }
}

TEST(SaitoToriwaki, EmptyForegroundThrows)
{
  auto mask = RandomMask<3>({9, 8, 7}, {1, 1, 1}, 1, 0.0);
  std::fill_n(mask->GetBufferPointer(), mask->GetBufferedRegion().GetNumberOfPixels(), 0);
  for (bool signedDistance : {false, true})
  {
    auto filter = Filter<3>::New();
    filter->SetInput(mask);
    filter->SetSignedDistance(signedDistance);
    try
    {
      filter->Update();
      ADD_FAILURE() << "no exception for an empty foreground";
    }
    catch (const itk::ExceptionObject& e)
    {
      EXPECT_NE(std::string(e.GetDescription()).find("input has no foreground voxel"), std::string::npos)
        << e.GetDescription();
    }
  }
}

TEST(SaitoToriwaki, AllForegroundIsZeroUnsignedAndThrowsSigned)
{
  auto mask = RandomMask<3>({9, 8, 7}, {1, 1, 1}, 1, 0.0);
  std::fill_n(mask->GetBufferPointer(), mask->GetBufferedRegion().GetNumberOfPixels(), 3);
  const auto out = RunOurs<3>(mask, Mode{});
  for (size_t p = 0; p < mask->GetBufferedRegion().GetNumberOfPixels(); ++p)
  {
    ASSERT_EQ(out->GetBufferPointer()[p], 0.0f);
  }
  auto filter = Filter<3>::New();
  filter->SetInput(mask);
  filter->SignedDistanceOn();
  try
  {
    filter->Update();
    ADD_FAILURE() << "no exception for a signed map without boundary";
  }
  catch (const itk::ExceptionObject& e)
  {
    EXPECT_NE(std::string(e.GetDescription()).find("no background voxel"), std::string::npos) << e.GetDescription();
  }
}

// ---- Bundled CTs vs itk::SignedMaurerDistanceMapImageFilter -------------------------------------------

MaskImage<3>::Pointer ThresholdCT(const std::string& file, short threshold)
{
  auto reader = itk::ImageFileReader<CTImage>::New();
  reader->SetFileName(std::string(MMREP_SAMPLE_DATA) + "/" + file);
  auto thresholder = itk::BinaryThresholdImageFilter<CTImage, MaskImage<3>>::New();
  thresholder->SetInput(reader->GetOutput());
  thresholder->SetLowerThreshold(threshold);
  thresholder->SetInsideValue(1);
  thresholder->SetOutsideValue(0);
  thresholder->Update();
  return thresholder->GetOutput();
}

DistanceImage<3>::Pointer RunMaurer(const MaskImage<3>* mask, bool squared, bool insideIsPositive)
{
  auto maurer = itk::SignedMaurerDistanceMapImageFilter<MaskImage<3>, DistanceImage<3>>::New();
  maurer->SetInput(mask);
  maurer->SetSquaredDistance(squared);
  maurer->SetInsideIsPositive(insideIsPositive);
  maurer->SetUseImageSpacing(true);
  maurer->Update();
  return maurer->GetOutput();
}

// Largest |ours - reference|, scaled for squared maps so that 1e-4 means 1e-4 mm on the distance.
double MaxDistanceError(const DistanceImage<3>* ours, const DistanceImage<3>* reference, bool squared,
                        bool clampNegative)
{
  double worst = 0;
  const size_t n = ours->GetBufferedRegion().GetNumberOfPixels();
  for (size_t p = 0; p < n; ++p)
  {
    double b = reference->GetBufferPointer()[p];
    if (clampNegative)
    {
      b = std::max(b, 0.0);
    }
    const double a = ours->GetBufferPointer()[p];
    double e = std::abs(a - b);
    if (squared)
    {
      // d(a^2) = 2 d da, plus float rounding of both squared values
      e = e / (2.0 * std::sqrt(std::max(std::abs(b), 1.0)) + 2e-7 * std::abs(b));
    }
    worst = std::max(worst, e);
  }
  return worst;
}

void CompareWithMaurer(const std::string& file, short threshold, bool alsoInsidePositive)
{
  SCOPED_TRACE(file + " > " + std::to_string(threshold));
  const auto mask = ThresholdCT(file, threshold);
  for (bool squared : {false, true})
  {
    const auto maurer = RunMaurer(mask, squared, false);
    const auto ours = RunOurs<3>(mask, Mode{squared, true, false, true});
    EXPECT_LE(MaxDistanceError(ours, maurer, squared, false), 1e-4) << "signed, squared " << squared;
    const auto unsignedOurs = RunOurs<3>(mask, Mode{squared, false, false, true});
    // Outside, SignedMaurer's distance to the boundary is the distance to the object; inside ours is 0.
    EXPECT_LE(MaxDistanceError(unsignedOurs, maurer, squared, true), 1e-4) << "unsigned, squared " << squared;
  }
  if (alsoInsidePositive)
  {
    const auto maurer = RunMaurer(mask, false, true);
    const auto ours = RunOurs<3>(mask, Mode{false, true, true, true});
    EXPECT_LE(MaxDistanceError(ours, maurer, false, false), 1e-4) << "inside positive";
  }
}

TEST(SaitoToriwaki, CTHeadSkinMatchesSignedMaurer)
{
  CompareWithMaurer("cthead.nrrd", 500, true);
}

TEST(SaitoToriwaki, CTHeadBoneMatchesSignedMaurer)
{
  CompareWithMaurer("cthead.nrrd", 1300, false);
}

TEST(SaitoToriwaki, HeadsqMatchesSignedMaurer)
{
  CompareWithMaurer("headsq.nrrd", 500, true);
  CompareWithMaurer("headsq.nrrd", 1150, false);
}

TEST(SaitoToriwaki, ThreadCountDoesNotChangeBits)
{
  const auto skin = ThresholdCT("cthead.nrrd", 500);
  const auto random = RandomMask<3>({45, 31, 27}, {0.7, 1.3, 2.1}, 21, 0.01);
  const size_t nSkin = skin->GetBufferedRegion().GetNumberOfPixels();
  const size_t nRandom = random->GetBufferedRegion().GetNumberOfPixels();
  const Mode signedMode{false, true, false, true};

  const auto skin1 = RunOurs<3>(skin, signedMode, 1);
  auto vectors = [&](unsigned int workUnits, DistanceImage<3>::Pointer& distance) {
    auto filter = Filter<3>::New();
    filter->SetInput(random);
    filter->ComputeNearestVectorOn();
    filter->SetNumberOfWorkUnits(workUnits);
    filter->Update();
    distance = filter->GetOutput();
    return Filter<3>::NearestVectorImageType::Pointer(filter->GetNearestVectorOutput());
  };
  DistanceImage<3>::Pointer random1;
  const auto vec1 = vectors(1, random1);
  for (unsigned int workUnits : {2u, 4u, 7u})
  {
    const auto skinN = RunOurs<3>(skin, signedMode, workUnits);
    EXPECT_EQ(0, std::memcmp(skin1->GetBufferPointer(), skinN->GetBufferPointer(), sizeof(float) * nSkin))
      << workUnits << " work units";
    DistanceImage<3>::Pointer randomN;
    const auto vecN = vectors(workUnits, randomN);
    EXPECT_EQ(0, std::memcmp(random1->GetBufferPointer(), randomN->GetBufferPointer(), sizeof(float) * nRandom));
    EXPECT_EQ(0, std::memcmp(vec1->GetBufferPointer(), vecN->GetBufferPointer(), sizeof(float) * 3 * nRandom));
  }
}
} // namespace
