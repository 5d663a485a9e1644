// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Benchmark sections shared by the benchmark programs. Each prints a table with one row per
// implementation: best wall time over `repeats`, voxels per second, and ratio ours/theirs.
#pragma once

#include <ostream>
#include <string>

namespace mmrep::bench
{
// Ours vs itk::SignedMaurerDistanceMapImageFilter, itk::DanielssonDistanceMapImageFilter and
// vtkImageEuclideanDistance, on the skin and bone masks of the CT.
void RunDistanceMapBenchmark(const std::string& ctPath, int repeats, std::ostream& out);
// Ours vs vtkFlyingEdges3D, vtkMarchingCubes and itk::BinaryMask3DMeshSource.
void RunMarchingCubesBenchmark(const std::string& ctPath, int repeats, std::ostream& out);
} // namespace mmrep::bench
