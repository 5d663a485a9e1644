// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Distance map of a triangle surface on a regular grid, as the registration consumes it.
//
// Near the surface the map holds the exact Euclidean distance to the triangles (not to voxel
// centres): every voxel within `exactBand` voxels of a triangle gets the exact point-to-triangle
// distance. Farther away, the Saito–Toriwaki transform gives the nearest band voxel q of each
// voxel p and the map stores |p - q| + d(q), an upper bound that is exact along straight
// approach paths and within about one voxel elsewhere (far from the surface, where only the
// direction of descent matters).
#pragma once

#include "mmrepImageIO.h"

#include <vtkPolyData.h>

#include <array>
#include <string>
#include <functional>

namespace mmrep
{

struct SurfaceDistanceMapOptions
{
  double spacing = 1.5;   // mm, isotropic voxel size (the paper: 1.5 mm overall, 0.5 mm for the lips)
  double margin = 10.0;   // mm added around the region on every side
  double exactBand = 2.0; // voxels: half-width of the band of exact distances
  // Negative inside a closed surface (sign from angle-weighted pseudo-normals, Bærentzen & Aanæs
  // 2005; far voxels take the sign of their nearest band voxel). A signed map interpolates
  // linearly through the surface, where an unsigned one rounds off its V. Needs a closed,
  // consistently oriented surface (each edge in two triangles); the orientation is taken from the
  // sign of the enclosed volume.
  bool signedDistance = false;
  // Region covered, in LPS mm: {xmin, xmax, ymin, ymax, zmin, zmax}. Empty (min > max): the
  // surface's bounding box.
  std::array<double, 6> region{1, 0, 1, 0, 1, 0};
};

// Throws std::runtime_error for a surface without triangles or a grid too large (> 512³ voxels).
FloatImage::Pointer ComputeSurfaceDistanceMap(vtkPolyData* surface, const SurfaceDistanceMapOptions& options,
                                              const std::function<void(double)>& progress = {});

// Refuses, before any work, a grid over `box` (xmin, xmax, ymin, ymax, zmin, zmax) grown by `margin`
// at `spacing` with more voxels than a map may have (512^3), in floating point so that no count can
// wrap around; std::runtime_error "<parameter> <spacing>: the distance map over a x b x c mm would
// have N million voxels ...". Returns the voxel count per axis.
std::array<double, 3> CheckDistanceMapGrid(const std::array<double, 6>& box, double margin, double spacing,
                                           const std::string& parameter);

} // namespace mmrep
