// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Points embedded in solid elements (muscle track points): their position from the element's
// nodes and parametric coordinates (VTK's interpolation functions of that cell type).
#pragma once

#include "mmrepFEMesh.h"

#include <array>
#include <vector>

namespace mmrep
{

// Shape-function weights of a point with parametric coordinates `pcoords` in a solid element
// (VTK convention for hexahedra, wedges and tetrahedra), in the element's node order. Throws
// std::invalid_argument for a cable.
std::vector<double> ShapeFunctions(ElementType type, const std::array<double, 3>& pcoords);

// The point at `embedding`'s parametric coordinates in its element. Throws std::invalid_argument
// for an element index out of range or a cable.
Point3 EmbeddedPosition(const FEMesh& mesh, const Embedding& embedding);

// Muscle track points that belong to no solid element follow their embedding element: each one
// whose element has a node that moved since `before` (node positions of the same mesh) is put back
// at its parametric coordinates. Returns how many points moved.
std::size_t FollowEmbeddings(FEMesh& mesh, const std::vector<Point3>& before);

} // namespace mmrep
