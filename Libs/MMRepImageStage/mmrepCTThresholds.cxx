// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepCTThresholds.h"

#include <itkImageRegionConstIterator.h>
#include <itkOtsuMultipleThresholdsCalculator.h>
#include <itkStatisticsImageFilter.h>
#include <itkHistogram.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mmrep
{

bool LooksLikeHounsfield(const CTImage* image)
{
  // HU volumes store air as about -1000; scanner-unit volumes are non-negative. Use a low
  // percentile rather than the minimum so that a few padding voxels do not decide.
  const auto& region = image->GetBufferedRegion();
  const std::size_t n = region.GetNumberOfPixels();
  std::size_t below = 0;
  const short* p = image->GetBufferPointer();
  for (std::size_t i = 0; i < n; ++i)
    below += p[i] < -500;
  return below > n / 20; // at least 5% air-like voxels in HU
}

namespace
{
// Three-class Otsu thresholds (air | soft tissue | bone) from a 256-bin histogram.
std::pair<double, double> OtsuAirTissueBone(const CTImage* image)
{
  using HistogramType = itk::Statistics::Histogram<double>;
  const short* p = image->GetBufferPointer();
  const std::size_t n = image->GetBufferedRegion().GetNumberOfPixels();
  if (n == 0)
    throw std::runtime_error("the volume is empty");
  short lo = p[0], hi = p[0];
  for (std::size_t i = 1; i < n; ++i)
  {
    lo = std::min(lo, p[i]);
    hi = std::max(hi, p[i]);
  }
  if (hi - lo < 3)
    throw std::runtime_error("the volume has a constant intensity: no head to segment");

  auto histogram = HistogramType::New();
  HistogramType::SizeType size(1);
  size.Fill(256);
  HistogramType::MeasurementVectorType lower(1), upper(1);
  lower[0] = lo;
  upper[0] = static_cast<double>(hi) + 1.0;
  histogram->SetMeasurementVectorSize(1);
  histogram->Initialize(size, lower, upper);
  HistogramType::MeasurementVectorType m(1);
  HistogramType::IndexType index(1);
  for (std::size_t i = 0; i < n; ++i)
  {
    m[0] = p[i];
    histogram->GetIndex(m, index);
    histogram->IncreaseFrequencyOfIndex(index, 1);
  }
  auto otsu = itk::OtsuMultipleThresholdsCalculator<HistogramType>::New();
  otsu->SetInputHistogram(histogram);
  otsu->SetNumberOfThresholds(2);
  otsu->Compute();
  const auto& t = otsu->GetOutput();
  return {t[0], t[1]};
}
} // namespace

CTThresholds ChooseThresholds(const CTImage* image, ThresholdMode mode, double skin, double bone)
{
  CTThresholds result;
  const bool explicitSkin = !std::isnan(skin), explicitBone = !std::isnan(bone);
  const bool hu = mode == ThresholdMode::Hounsfield || (mode == ThresholdMode::Automatic && LooksLikeHounsfield(image));
  // Hounsfield thresholds on scanner units would take the whole volume (air included) as the head.
  if (mode == ThresholdMode::Hounsfield && !(explicitSkin && explicitBone) && !LooksLikeHounsfield(image))
    throw std::runtime_error("--thresholdMode hounsfield: the volume is not in Hounsfield units (less than 5 % of "
                             "its voxels lie below -500, where air is); use --thresholdMode automatic or give "
                             "--skinThreshold and --boneThreshold");
  if (explicitSkin && explicitBone)
  {
    result = {skin, bone, "explicit"};
  }
  else if (hu)
  {
    result = {kHounsfieldSkinThreshold, kHounsfieldBoneThreshold, "hounsfield"};
  }
  else
  {
    const auto [airTissue, tissueBone] = OtsuAirTissueBone(image);
    result = {airTissue, tissueBone, "histogram"};
  }
  if (explicitSkin != explicitBone)
  {
    if (explicitSkin)
      result.skin = skin;
    if (explicitBone)
      result.bone = bone;
    result.source += "+explicit";
  }
  if (!(result.bone > result.skin))
  {
    const auto number = [](double v) {
      std::ostringstream s;
      s << v;
      return s.str();
    };
    const auto named = [&](const char* flag, const char* what, bool given, double v) {
      return (given ? std::string("--") + flag : std::string("the automatic ") + what) + " " + number(v);
    };
    throw std::runtime_error(named("boneThreshold", "bone threshold", explicitBone, result.bone) + " must be above " +
                             named("skinThreshold", "skin threshold", explicitSkin, result.skin));
  }
  return result;
}

ThresholdMode ThresholdModeFromName(const std::string& name)
{
  if (name == "hounsfield")
    return ThresholdMode::Hounsfield;
  if (name == "histogram")
    return ThresholdMode::Histogram;
  return ThresholdMode::Automatic;
}

} // namespace mmrep
