// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Tangles of a real atlas mesh (Resources/Atlas/FaceAtlas.vtu and its reference surfaces), as a
// registration could leave it: random node noise (tangential of the element size, through the
// thickness of the thinnest adjacent layer), local folds (a node pushed past one of its edge
// neighbours, which inverts the elements between them) and extreme smooth warps (a shear of the
// deep levels against the skin and a few large Gaussian bumps). Perturbations are in millimetres
// scaled by each node's local element size. Skin and skull nodes are put back on their reference
// surfaces (as after a surface registration), mid-sagittal nodes on the symmetry plane (on the
// plane's trace of the surface when they are also skin or skull nodes). Symmetric tangles perturb
// the left half and mirror it exactly.
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepMeshRepair.h"
#include "mmrepPlane.h"
#include "mmrepTangledMeshGenerator.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>

#include <string>
#include <vector>

namespace mmrep::testing
{

struct MeshTangleContext
{
  FEMesh mesh;
  vtkSmartPointer<vtkPolyData> skin, skull;
  vtkSmartPointer<vtkStaticCellLocator> skinLocator, skullLocator;
  Plane plane; // least-squares plane of the `midsagittal` nodes
  // Mirror node (itself on the plane and for nodes of no solid element); empty when not symmetric.
  std::vector<std::int32_t> partner;
  std::vector<double> size;                          // per node: mean length of its edges to the same level (mm)
  std::vector<double> layer;                         // per node: its shortest edge to another level (mm)
  std::vector<Point3> normal;                        // per node: outward skin normal at its closest skin point
  std::vector<double> skinDistance;                  // per node: distance to the skin (mm)
  std::vector<std::int32_t> top;                     // per node: skin node of its through-thickness column (-1: none)
  std::vector<std::vector<std::int32_t>> neighbours; // edge neighbours per node, ascending
  std::vector<double> depth;                         // 0 skin, 1/3 and 2/3 the inner levels, 1 skull/inner surface
  double meanSize = 0;
  double diagonal = 0; // bounding-box diagonal (mm)
};

// Reads the atlas mesh and surfaces (.vtu, .vtp). Throws std::runtime_error on unreadable files.
MeshTangleContext LoadTangleContext(const std::string& meshPath, const std::string& skinPath,
                                    const std::string& skullPath);

// The shipped atlas's context (Resources/Atlas/FaceAtlas.vtu and its surfaces), loaded once.
const MeshTangleContext& ShippedAtlasTangleContext();

// Repair options for a tangle of the context's mesh: its skin and skull surfaces and its plane.
RepairOptions TangleRepairOptions(const MeshTangleContext& c);
MeshTangleContext MakeTangleContext(FEMesh mesh, vtkSmartPointer<vtkPolyData> skin, vtkSmartPointer<vtkPolyData> skull);

// The mesh with perturbed nodes (TangleOptions: noise and warp in element sizes, fold count, seed,
// symmetric). Same elements and sets.
FEMesh TangleMesh(const MeshTangleContext& context, const TangleOptions& options);

// The elements whose centroid lies in the lowest `fraction` of the mesh along the plane's vertical
// direction (mirror-invariant, so a symmetric mesh stays symmetric), nodes renumbered, sets and
// layers kept (muscles and landmarks dropped): smaller meshes of the same kind, for the scaling.
FEMesh CropMesh(const FEMesh& mesh, const Plane& plane, double fraction);

// Largest |mirror(node) - partner node| over the solid elements' nodes, relative to the bounding-box diagonal.
double SymmetryError(const FEMesh& mesh, const MeshTangleContext& context);

} // namespace mmrep::testing
