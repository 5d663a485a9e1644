// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Where each node of a mesh under repair may move (mmrepMeshRepair.h): `skin` and `skull` nodes
// slide on their surface, nodes on the symmetry plane stay on it, mirror partners move together
// (mmrepMirrorPairs.h), nodes of a surface set without any surface stay fixed. The nodes next to the
// plane's sheet of nodes stay on the side of it where their elements lie: a node pushed across (a
// mirror pair swapped) leaves every corner Jacobian positive while the two halves overlap.
#pragma once

#include "mmrepMeshRepair.h"
#include "mmrepNodeElements.h"
#include "mmrepSurfaceProjector.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace mmrep
{

enum class SurfaceKind : std::uint8_t
{
  None,
  Skin,
  Skull
};

class RepairConstraints
{
public:
  // Throws std::invalid_argument for a given symmetry plane without a valid normal.
  RepairConstraints(const FEMesh& mesh, const NodeElements& adjacency, const RepairOptions& options);

  // A proposed position made admissible: on the node's surface, then on the plane.
  Point3 Constrain(std::size_t node, Point3 p) const;
  // Unit directions spanning the node's admissible moves at p.
  std::vector<Point3> Directions(std::size_t node, const Point3& p) const;

  SurfaceKind Surface(std::size_t node) const { return surface_[node]; }
  bool OnPlane(std::size_t node) const { return onPlane_[node] != 0; }
  bool Constrained(std::size_t node) const { return surface_[node] != SurfaceKind::None || onPlane_[node]; }
  bool IsFixed(std::size_t node) const;
  std::size_t Partner(std::size_t node) const { return static_cast<std::size_t>(partner_[node]); }
  bool MirrorPairs() const { return pairs_; } // mirror partners move together
  // The side of the plane the node must keep (+1 along the normal, -1, 0: either), and whether p
  // is on it.
  int Side(std::size_t node) const { return side_.empty() ? 0 : side_[node]; }
  bool OnItsSide(std::size_t node, const Point3& p) const;
  const Plane& SymmetryPlane() const { return plane_; }

private:
  void FitPlane(const std::vector<std::int32_t>& ids);
  void FindSides(const NodeElements& adjacency);
  double Diagonal() const;

  const FEMesh& mesh_;
  std::vector<SurfaceKind> surface_;
  std::vector<char> onPlane_;
  std::vector<signed char> side_;  // empty without a plane
  std::vector<double> sideMargin_; // mm a node keeps from the plane on its side
  std::vector<std::int32_t> partner_;
  std::vector<std::size_t> fixed_; // sorted
  bool pairs_ = false, hasPlane_ = false;
  Plane plane_;
  std::vector<vtkSmartPointer<vtkPolyData>> ownSurfaces_;
  std::unique_ptr<SurfaceProjector> skin_, skull_;
};

} // namespace mmrep
