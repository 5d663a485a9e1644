// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The lips' support by the teeth and gums: nodes that slide on a rigid surface.
#pragma once

#include "mmrepFEMesh.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace mmrep::simulation
{

// A node that slides on a rigid support: its displacement along `normal` is zero (frictionless,
// bilateral contact, linearised at the rest position).
struct SlidingNode
{
  std::int32_t node = -1;
  Point3 normal = Point3::UnitY();
  bool onBone = false; // a bone node (of the fixed set) that slides instead of being fixed
};

// Area-weighted unit normals at the nodes of the boundary quadrilaterals of hexahedra whose four
// nodes belong to node set `nodeSet` (orientation consistent per node, not outward); empty when the
// set is missing.
std::map<std::int32_t, Point3> SurfaceNodeNormals(const FEMesh& mesh, const std::string& nodeSet);

// The nodes of set "inner" (inner surface where no bone was found) that lie behind the lips, i.e.
// whose x (left-right) and z (inferior-superior) fall within the bounding box of node set "lips"
// widened by `margin` mm; normal = area-weighted normal of the inner boundary faces at the node.
// Empty when the model has no "inner" or "lips" set.
std::vector<SlidingNode> LipSupportNodes(const FEMesh& mesh, double margin = 5.0);

} // namespace mmrep::simulation
