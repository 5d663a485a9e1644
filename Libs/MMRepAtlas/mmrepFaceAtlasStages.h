// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The phases of BuildFaceAtlas (mmrepFaceAtlas.h, steps 2-7), one concept per source file:
// the grid of rays (mmrepFaceAtlasGrid.cxx), the through-thickness columns under the skin
// (mmrepFaceAtlasColumns.cxx), the mirrored mesh and its node sets (mmrepFaceAtlasMesh.cxx), and
// its quality: repair, re-symmetrisation, surface projection (mmrepFaceAtlasQuality.cxx).
// Internal to MMRepAtlas: the atlas builder is their only caller.
#pragma once

#include "mmrepFaceAtlas.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mmrep
{

// The mouth in the grid's parameters: the rows between the labiomental fold (mouthLo) and the
// subnasale (mouthHi), the columns out to `lateral` radians; `rho` is the lip corner's distance
// from the vertical axis through the face centre (mm per radian of theta there).
struct FaceMouthRegion
{
  double mouthLo = 0, mouthHi = 0, lateral = 0, rho = 1;
  // x^2 + y^2 of grid cell (i, j) in the ellipse through the mouth's rows and `lateralAngle`: <= 1 inside.
  double Ellipse(const FaceGrid& grid, int i, int j, double lateralAngle) const
  {
    const double y = (grid.phi[i] - 0.5 * (mouthLo + mouthHi)) / (0.5 * (mouthHi - mouthLo));
    const double x = grid.theta[j] / lateralAngle;
    return x * x + y * y;
  }
};

// Step 2: rows (phi) and columns (theta) of the left half's grid, and the levels through the thickness.
FaceMouthRegion LayOutFaceGrid(const SurfaceRays& skin, const Eigen::Vector3d& centre, const FaceLandmarkSet& lm,
                               const FaceAtlasOptions& options, FaceGrid& grid);

// Steps 3-4, per grid cell q = i * cols + j (left half).
struct FaceColumns
{
  std::vector<Eigen::Vector3d> outer; // skin node (local)
  std::vector<Eigen::Vector3d> dir;   // inward through-thickness direction
  std::vector<double> thickness;      // mm, from the skin node to the inner node
  std::vector<char> onBone;           // the inner node is a bone crossing (set `skull`)
};
// Skin nodes: the outermost crossing of each grid ray with the skin.
std::vector<Eigen::Vector3d> FaceSkinNodes(const SurfaceRays& skin, const Eigen::Vector3d& centre,
                                           const FaceGrid& grid);
// Directions, bone depths (outliers rejected) and the harmonic fill of the thickness; the log
// gets the counts of followed, rejected and shallow bone crossings.
FaceColumns FaceThroughThickness(std::vector<Eigen::Vector3d> outer, const SurfaceRays& bone, const FaceGrid& grid,
                                 const FaceMouthRegion& mouth, const FaceAtlasOptions& options,
                                 std::vector<std::string>& log);

// Steps 5-6: the left half's local node positions (grid.local) from the columns, then the world
// mesh (left nodes, mirrored right nodes, left hexahedra, mirrored hexahedra).
void PlaceLeftHalfNodes(const FaceColumns& columns, FaceGrid& grid);
FEMesh MirroredFaceMesh(const FaceGrid& grid, const FaceFrame& frame);
// World nodes from grid.local: the left half as is, the right half its exact mirror image.
void WriteNodesFromLeftHalf(const FaceGrid& grid, const FaceFrame& frame, FEMesh& mesh);
// Node sets skin, skull, inner, midsagittal and lips (sorted).
void AddFaceNodeSets(const FaceGrid& grid, const FaceColumns& columns, const FaceMouthRegion& mouth,
                     const FaceLandmarkSet& lm, FEMesh& mesh);

// Step 7: the reference surfaces (left half of a local surface and its mirror image, cut to the
// atlas region), the repair rounds with exact re-symmetrisation, and the surface nodes projected
// exactly back onto their surfaces (mid-sagittal inner nodes left off the bone move to `inner`).
vtkSmartPointer<vtkPolyData> SymmetrisedSurface(vtkPolyData* local, const FaceFrame& frame, const FaceGrid& grid);
void RepairFaceAtlas(const FaceAtlasOptions& options, FaceAtlas& atlas);
void ProjectFaceSurfaceNodes(const FaceAtlasOptions& options, std::vector<char>& onBone, FaceAtlas& atlas);

// printf-style line for the construction log.
std::string FaceAtlasLogLine(const char* format, double a, double b = 0, double c = 0);

} // namespace mmrep
