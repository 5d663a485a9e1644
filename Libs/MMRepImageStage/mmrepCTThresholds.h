// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Choice of the skin and bone thresholds of a head CT.
//
// CTs in Hounsfield units (air near -1000) get the usual fixed values (skin -300 HU, bone 300 HU).
// Data in scanner units (both bundled sample CTs) get a three-class Otsu split of the histogram
// (air | soft tissue | bone): the lower threshold separates air from skin, the upper one soft
// tissue from bone. Explicit values always win.
#pragma once

#include "mmrepImageIO.h"

#include <string>

namespace mmrep
{

struct CTThresholds
{
  double skin = 0;
  double bone = 0;
  std::string source; // "hounsfield", "histogram" or "explicit", for reports
};

enum class ThresholdMode
{
  Automatic,  // Hounsfield defaults when the data looks like HU, histogram otherwise
  Hounsfield, // fixed HU values
  Histogram   // three-class Otsu on the histogram
};

// The modules' names of the modes: "hounsfield", "histogram", anything else automatic.
ThresholdMode ThresholdModeFromName(const std::string& name);

constexpr double kHounsfieldSkinThreshold = -300.0;
constexpr double kHounsfieldBoneThreshold = 300.0;

// True when the volume's intensities look like Hounsfield units (air around -1000).
bool LooksLikeHounsfield(const CTImage* image);

// NaN skin/bone means "choose"; a given value is kept as is. Throws std::runtime_error when the
// histogram has no air / soft tissue / bone structure (e.g. a constant or empty volume).
CTThresholds ChooseThresholds(const CTImage* image, ThresholdMode mode, double skin, double bone);

} // namespace mmrep
