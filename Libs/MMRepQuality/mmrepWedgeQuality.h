// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Quality measures of a linear wedge (triangular prism) given its 6 nodes in VTK order (vtkWedge:
// triangle 0-1-2 whose right-hand normal points away from triangle 3-4-5, node 3 above 0, 4 above 1,
// 5 above 2). VTK 9.1's vtkMeshQuality has no wedge measures; these follow the wedge definitions of
// later Verdict releases (as used by vtkMeshQuality in VTK >= 9.3, which maps VTK order onto
// Verdict's mirrored order by swapping nodes 0<->1 and 3<->4). A valid VTK wedge has positive
// corner Jacobians; a right prism on an equilateral unit triangle with unit height scores 1.
#pragma once

#include "mmrepVerdictMath.h"

#include <array>

namespace mmrep::quality
{

using WedgeNodes = std::array<Point3, 6>;

// Corner Jacobian determinants, entry i at node i: the triple product of the two triangle edges and
// the vertical edge leaving node i, oriented so that a valid wedge gives positive values. For a right
// prism it equals 2 x (triangle area) x height at every corner.
std::array<double, 6> WedgeCornerJacobians(const WedgeNodes& p);
double WedgeJacobian(const WedgeNodes& p); // minimum corner determinant; < 0 means inverted
// min over corners of det / (product of the three edge lengths at the corner), times 2/sqrt(3) so the
// equilateral right prism scores 1. kVerdictMax (degenerate flag) when an edge has zero length.
double WedgeScaledJacobian(const WedgeNodes& p);
// min over corners of 3 (2 det / sqrt(3))^(2/3) / (sum of the three squared edge lengths): 1 for the
// equilateral right prism with unit height, 0 when any corner determinant is <= 0.
double WedgeShape(const WedgeNodes& p);
double WedgeEdgeRatio(const WedgeNodes& p); // longest / shortest of the 9 edges (>= 1)

} // namespace mmrep::quality
