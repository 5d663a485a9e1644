// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Geometric targets of a node in the repair's local search (mmrepMeshRepair.cxx): where the node
// would make its elements well shaped.
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepNodeElements.h"

#include <utility>
#include <vector>

namespace mmrep
{

// Where the node would make each of its elements an affine (parallelepiped / straight prism)
// cell, averaged over its elements; the mean of the element centroids as a smoothing target.
// Per-element ideal positions are appended to `each` (tried one by one when the means fail:
// a neighbour that is itself misplaced spoils the mean but not every element's ideal).
// Returns (mean ideal position, mean element centroid); the node's own position where it has none.
std::pair<Point3, Point3> IdealPositions(const FEMesh& mesh, const NodeElements& adjacency, std::size_t node,
                                         std::vector<Point3>& each);

} // namespace mmrep
