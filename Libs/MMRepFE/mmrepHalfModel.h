// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The half-face model (paper §3.2; ArtiSynth's face simulates a symmetric half face): the patient's
// left half of an FE face model that is exactly symmetric about its mid-sagittal plane, with the
// plane's nodes carrying the symmetry boundary condition (displacement along the plane normal = 0).
//
// A half model is recognised by its node set `symmetryBoundary` (the nodes on the plane); the plane
// itself is refitted from that set (FitPlaneToNodeSet), so it survives every .vtu/.vtk round trip
// without extra fields. The exporters (.inp, .feb, .msh) and the CalculiX simulation read it there.
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepPlane.h"

#include <cstdint>
#include <string>
#include <vector>

namespace mmrep
{

inline const std::string kSymmetryBoundarySet = "symmetryBoundary";

struct HalfModelOptions
{
  std::string planeSet = "midsagittal"; // node set on the symmetry plane (its fit is the plane)
  double tolerance = 1e-3;              // mm: a node this close to the plane is on it
  double symmetryTolerance = 0.01;      // mm: how far a solid node's mirror image may lie from its partner
};

// The left half (the +x side of the plane's normal, oriented to the patient's left) of a symmetric
// model: solid elements whose centroid lies on the left; muscle tracks (and their cables) of the
// left side, a track crossing the plane cut at its point on the plane (further left pieces are
// named "<muscle>_part2", …); the nodes these use, renumbered in their original order; every node
// and element set restricted to what is kept (sets left empty are dropped); landmarks on the left
// or on the plane; a track point embedded in a dropped (right) element re-embedded in a kept one.
// Adds node set `symmetryBoundary` = the kept nodes of `planeSet`.
// The mirror map (FEMesh::mirror) is dropped: the kept nodes' partners are gone.
// Throws std::invalid_argument with one line when the model is not symmetric (a solid node's mirror
// image farther than `symmetryTolerance` from its stored mirror partner, or from every solid node
// when the model has no mirror map), when the plane set is missing or not planar (a node
// of it farther than `tolerance` from the fitted plane), a solid element straddles the plane (the
// model is not cut along its plane nodes), a muscle cable crosses the plane without a point on it,
// or the model already is a half model.
FEMesh LeftHalfModel(const FEMesh& full, const HalfModelOptions& options = {});

// True when the mesh carries a symmetry boundary (a non-empty `symmetryBoundary` node set).
bool IsHalfModel(const FEMesh& mesh);

// The symmetry plane of a half model, refitted from `symmetryBoundary`, normal towards +x (the
// kept half). Throws std::invalid_argument when the mesh is not a half model or the set is degenerate.
Plane SymmetryPlaneOf(const FEMesh& half);

// The faces of the symmetry boundary: faces of solid elements whose nodes all belong to
// `symmetryBoundary` and that no other element shares, as node lists (VTK face order of the element:
// 4 nodes for quadrilaterals, 3 for triangles) turned so that their normal points out of the model.
std::vector<std::vector<std::int32_t>> SymmetryBoundaryFaces(const FEMesh& half);

} // namespace mmrep
