// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Closest points on a triangle surface (vtkStaticCellLocator), used to keep skin and skull nodes on
// their surfaces while the repair slides them, and to measure surface accuracy.
#pragma once

#include "mmrepBoundaryFaces.h" // BoundarySurface, the surface a mesh's own nodes are projected onto
#include "mmrepFEMesh.h"

#include <vtkAbstractCellLocator.h>
#include <vtkGenericCell.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>

#include <vector>

namespace mmrep
{

class SurfaceProjector
{
public:
  // Throws std::invalid_argument when the surface is null or has no cells.
  explicit SurfaceProjector(vtkPolyData* surface);
  Point3 Project(const Point3& p) const; // closest point of the surface
  double Distance(const Point3& p) const;
  // Unit normal of the surface cell closest to p (zero for a degenerate cell).
  Point3 Normal(const Point3& p) const;

private:
  Point3 Closest(const Point3& p, vtkIdType& cellId) const; // leaves the closest cell in cell_
  vtkSmartPointer<vtkPolyData> surface_;
  vtkSmartPointer<vtkStaticCellLocator> locator_;
  vtkSmartPointer<vtkGenericCell> cell_; // scratch cell: the projector is not thread-safe
};

// Builds a VTK static locator with VTK's SMP tools in their sequential backend. The parallel build
// orders the cells of a bin differently from run to run, and that order decides which of two
// equidistant cells FindClosestPoint returns; ties are common here (points on the symmetry plane
// of a mirror-symmetric surface), so a parallel build makes projections, and repairs, vary.
void BuildLocatorSequentially(vtkAbstractCellLocator* locator);

} // namespace mmrep
