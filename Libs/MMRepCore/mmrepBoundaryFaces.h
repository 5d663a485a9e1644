// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Faces of the solid elements: one local face table per element type, and the boundary of a mesh
// (the faces used by exactly one solid), as (element, local face) pairs or as a VTK surface.
#pragma once

#include "mmrepFEMesh.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace mmrep
{

// Local node indices of a face in VTK node order, counter-clockwise seen from outside the element;
// a triangle has -1 as its fourth entry.
using LocalFace = std::array<int, 4>;
// The faces of a solid type (empty for cables). Hexahedron faces are in the order of Abaqus' and
// CalculiX's C3D8 faces S1..S6 (face f is S(f+1)), so a face index is also the solver's face label.
const std::vector<LocalFace>& LocalFaces(ElementType type);

struct BoundaryFace
{
  std::int32_t element = -1;
  int face = -1;                       // index into LocalFaces(type of the element)
  std::array<std::int32_t, 4> nodes{}; // mesh nodes of the face in its local order, -1 last for a triangle
  int NodeCount() const { return nodes[3] < 0 ? 3 : 4; }
};

// Faces used by exactly one solid element, ordered by their sorted node ids (so the result does
// not depend on the element order). With a mask (one entry per node), only the faces whose nodes
// are all marked.
std::vector<BoundaryFace> BoundaryFaces(const FEMesh& mesh, const std::vector<char>* nodeMask = nullptr);

// 1 for the nodes of the node set, 0 elsewhere (all 0 when the set is absent).
std::vector<char> NodeSetMask(const FEMesh& mesh, const std::string& set);

// The boundary as a vtkPolyData whose point i is node i (double precision): each quadrilateral
// split into the triangles (0,1,2), (0,2,3) of its local order (a surface to project onto).
vtkSmartPointer<vtkPolyData> BoundarySurface(const FEMesh& mesh, const std::vector<char>* nodeMask = nullptr);
// The same faces kept as they are (quadrilaterals and triangles; for pictures).
vtkSmartPointer<vtkPolyData> BoundaryPolygons(const FEMesh& mesh, const std::vector<char>* nodeMask = nullptr);

} // namespace mmrep
