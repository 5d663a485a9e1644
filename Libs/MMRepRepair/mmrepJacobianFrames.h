// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Jacobian frames of solid elements for the foldover-free untangling (mmrepFoldoverFreeUntangling.h):
// the linear maps whose determinants must all be positive for an element to be valid at its corners.
// A hexahedron has nine (its eight corners, as Verdict's corner Jacobians, and its centre), a wedge
// six (its corners), a tetrahedron one. Each frame's Jacobian J = sum_k x_k w_k^T maps the element's
// ideal reference shape (a box with the element's mean edge lengths, an equilateral prism, a regular
// tetrahedron) to the element, so det J is 1 for the ideal element and has the sign of the corner.
#pragma once

#include "mmrepFEMesh.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace mmrep
{

struct JacobianFrame
{
  std::uint32_t element = 0;
  std::uint8_t count = 0;              // nodes taking part (4 for a corner, 8 for a hexahedron's centre)
  std::array<std::int32_t, 8> nodes{}; // mesh node ids
  std::array<Eigen::Vector3d, 8> w{};  // J = sum_k x_{nodes[k]} w[k]^T
  double weight = 0;                   // the reference volume this frame stands for (mm^3)
  bool corner = true;                  // false for a hexahedron's centre frame
};

// The frames of element `e` (none for cables), appended to `frames`; the reference shape is sized
// from the element's current edge lengths.
void AppendJacobianFrames(const FEMesh& mesh, std::size_t e, std::vector<JacobianFrame>& frames);

// J of a frame at the mesh's current node positions.
Eigen::Matrix3d FrameJacobian(const JacobianFrame& frame, const std::vector<Point3>& nodes);

} // namespace mmrep
