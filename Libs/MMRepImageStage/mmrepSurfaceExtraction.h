// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Iso-surface of a CT at a threshold as a clean triangle surface (LPS mm): our Marching Cubes,
// then optionally only the largest connected piece, windowed-sinc smoothing and quadric
// decimation to a target vertex count.
#pragma once

#include "mmrepImageIO.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstddef>

namespace mmrep
{

struct SurfaceExtractionOptions
{
  bool closeAtBorder = true;            // pad the volume so surfaces leaving it are closed
  bool largestPieceOnly = true;         // keep the largest connected piece of the surface
  unsigned int smoothingIterations = 0; // windowed-sinc iterations, 0 = none
  double smoothingPassBand = 0.1;       // windowed-sinc pass band (lower = smoother)
  std::size_t targetVertexCount = 0;    // quadric decimation target, 0 = none
};

vtkSmartPointer<vtkPolyData> ExtractSurface(const CTImage* image, double isoValue,
                                            const SurfaceExtractionOptions& options = {});

} // namespace mmrep
