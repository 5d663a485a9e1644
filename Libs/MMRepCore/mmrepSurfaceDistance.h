// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// How far mesh nodes lie from a triangle surface (closest point on its cells): the accuracy
// measure of the registration, the refinement, the repair and the speaker model's report.
#pragma once

#include "mmrepFEMesh.h"

#include <vtkPolyData.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mmrep
{

struct SurfaceDistance
{
  std::size_t count = 0;    // nodes measured (0: no nodes, or a surface without cells)
  double mean = 0, max = 0; // mm, distance to the closest point of the surface's cells
  double sigma = 0;         // mm, standard deviation of the distances
};

// Distance of each node `ids[i]` to `surface` (vtkStaticCellLocator::FindClosestPoint), in the
// order of `ids`; empty when the surface is null or has no cells.
std::vector<double> NodeSurfaceDistances(const std::vector<Point3>& nodes, const std::vector<std::int32_t>& ids,
                                         vtkPolyData* surface);
// Their count, mean (summed in the order of `ids`: deterministic), maximum and sigma.
SurfaceDistance MeasureSurfaceDistance(const std::vector<Point3>& nodes, const std::vector<std::int32_t>& ids,
                                       vtkPolyData* surface);
// Of the nodes of a node set (count 0 when the set is absent). Throws std::invalid_argument when
// the surface has no cells.
SurfaceDistance MeasureSurfaceDistance(const FEMesh& mesh, const std::string& nodeSet, vtkPolyData* surface);

} // namespace mmrep
