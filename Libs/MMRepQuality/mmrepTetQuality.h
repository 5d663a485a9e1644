// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Quality measures of a linear tetrahedron given its 4 nodes in VTK order (vtkTetra: node 3 on the
// side where (1-0) x (2-0) points). Definitions and degenerate-cell rules are Verdict's as shipped
// with VTK 9.1, so every value equals vtkMeshQuality::Tet<Measure>(cell).
#pragma once

#include "mmrepVerdictMath.h"

#include <array>

namespace mmrep::quality
{

using TetNodes = std::array<Point3, 4>;

double TetJacobian(const TetNodes& p);        // (1-0) x (2-0) . (3-0), the same at every corner; 6 x volume
double TetVolume(const TetNodes& p);          // signed volume
double TetScaledJacobian(const TetNodes& p);  // sqrt(2) det / max corner edge-length product, in [-1, 1]
double TetShape(const TetNodes& p);           // 3 (sqrt(2) det)^(2/3) / weighted |J|^2; 0 if det <= 0
double TetEdgeRatio(const TetNodes& p);       // longest / shortest edge
double TetAspectRatio(const TetNodes& p);     // longest edge / (2 sqrt(6) inradius), any orientation
double TetRadiusRatio(const TetNodes& p);     // circumradius / (3 inradius), unoriented
double TetAspectBeta(const TetNodes& p);      // VTK 9.1: same as the radius ratio
double TetAspectGamma(const TetNodes& p);     // rms edge^3 / (8.485 volume)
double TetAspectFrobenius(const TetNodes& p); // Frobenius condition number w.r.t. the regular tet
double TetMinAngle(const TetNodes& p);        // minimum dihedral angle, degrees
double TetCollapseRatio(const TetNodes& p);   // min signed height / longest edge of its face
double TetCondition(const TetNodes& p);       // condition number of the weighted Jacobian (< 0 if inverted)

} // namespace mmrep::quality
