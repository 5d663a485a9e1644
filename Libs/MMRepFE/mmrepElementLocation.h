// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Where a point lies relative to one solid element: VTK's inverse isoparametric map
// (vtkCell::EvaluatePosition) on the element's nodes, with the parametric coordinates and the
// interpolation weights of the point when it is inside, of its closest point on the element when not.
#pragma once

#include "mmrepFEMesh.h"

#include <array>
#include <limits>
#include <vector>

namespace mmrep
{

struct ElementLocation
{
  bool valid = false; // VTK could evaluate the position (a degenerate element may not)
  bool inside = false;
  double distance = std::numeric_limits<double>::infinity(); // mm, 0 inside
  std::array<double, 3> pcoords{};                           // VTK's convention for the cell type
  std::vector<double> weights;                               // one per element node
};

ElementLocation LocateInElement(const FEMesh& mesh, const Element& element, const Point3& p);

} // namespace mmrep
