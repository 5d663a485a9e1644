// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// What BuildFaceAtlas reports about a finished atlas: its element quality measured independently
// of the construction's own checks, and its counts.
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepMeshQuality.h"

#include <string>

namespace mmrep
{

struct FaceAtlasQuality
{
  quality::QualitySummary summary; // scaled Jacobian (inverted: from the Jacobian)
  double percentile1 = 0, percentile5 = 0, median = 0;
  std::string line; // one line: min, percentiles, median, mean, max, inverted, below the threshold
};

// Scaled Jacobian and Jacobian of every solid (one thread: deterministic).
FaceAtlasQuality MeasureFaceAtlasQuality(const FEMesh& mesh, double threshold);
// Throws std::runtime_error when an element is inverted or below the threshold.
void RequireFaceAtlasQuality(const FaceAtlasQuality& quality, double threshold);
// "Atlas: N nodes, … midsagittal M nodes" (the mesh's counts and main node sets).
std::string FaceAtlasCounts(const FEMesh& mesh);

} // namespace mmrep
