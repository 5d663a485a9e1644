// How far the nodes of a named node set lie from a triangle surface: the accuracy measure of the
// repair report (skin, skull and lips nodes against the skin / skull surfaces).
#pragma once

#include "mmrepFEMesh.h"

#include <vtkPolyData.h>

#include <cstddef>
#include <string>

namespace mmrep
{

struct SurfaceDistance
{
  std::size_t count = 0; // nodes measured (0: the set is absent or empty)
  double mean = 0, max = 0; // mm, distance to the closest point of the triangles
};

// Distances of the set's nodes to `surface` (vtkStaticCellLocator::FindClosestPoint on its cells).
// Throws std::invalid_argument when the surface has no cells.
SurfaceDistance MeasureSurfaceDistance(const FEMesh& mesh, const std::string& nodeSet, vtkPolyData* surface);

} // namespace mmrep
