// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Mirror node pairs for a repair that keeps a mesh symmetric about a plane: which node moves with
// which, so that one move places both (the partner at the mirror image).
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepNodeElements.h"
#include "mmrepPlane.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace mmrep
{

// The partner of every node (itself for nodes of no solid element and for solid nodes on the
// plane), or nullopt when the mesh is not symmetric about `plane`: a node of a solid element whose
// partner is no node of a solid element with the same `kind` (skin, skull, …) within `tolerance` of
// its mirror image. Nodes of no solid element (embedded muscle points, mouth-slit twins while the
// slit is closed) never move in the repair and keep themselves.
//
// The partners are the mesh's stored mirror map (FEMesh::mirror, written by the atlas builder).
// A mesh without a map (a plain VTK mesh, a file written before the map existed) falls back to a
// geometric search: the solid node nearest the mirror image within `tolerance`; among coincident
// candidates (a tangle can project two skin nodes onto one surface point) the one whose
// neighbourhood (centroid of its elements' nodes) is the mirror of the node's.
std::optional<std::vector<std::int32_t>> MirrorPairs(const FEMesh& mesh, const NodeElements& adjacency,
                                                     const Plane& plane, const std::vector<std::uint8_t>& kind,
                                                     double tolerance);

} // namespace mmrep
