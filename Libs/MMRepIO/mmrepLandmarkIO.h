// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Landmarks (control points): Slicer markups .mrk.json and legacy .fcsv, read and write.
// The file's coordinate system field (LPS or RAS) is honoured; in memory everything is LPS.
#pragma once

#include "mmrepFEMesh.h"

#include <string>
#include <vector>

namespace mmrep
{

enum class CoordinateSystem
{
  LPS,
  RAS
};

std::vector<Landmark> ReadLandmarks(const std::string& path); // throws std::runtime_error
// Writes positions (given in LPS) expressed in `system` in the file.
void WriteLandmarks(const std::vector<Landmark>& landmarks, const std::string& path,
                    CoordinateSystem system = CoordinateSystem::LPS);
void WriteLandmarks(const std::vector<Landmark>& landmarks, const std::string& path, const std::string& format,
                    CoordinateSystem system); // format "mrk.json" or "fcsv"

} // namespace mmrep
