// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Quality measures of a trilinear hexahedron given its 8 nodes in VTK order (vtkHexahedron:
// 0-1-2-3 bottom face, 4-5-6-7 above them). Definitions and degenerate-cell rules are Verdict's as
// shipped with VTK 9.1, so every value equals vtkMeshQuality::Hex<Measure>(cell).
#pragma once

#include "mmrepVerdictMath.h"

#include <array>

namespace mmrep::quality
{

using HexNodes = std::array<Point3, 8>;

// The 8 corner Jacobian determinants, entry i at node i: det[e_xi, e_eta, e_zeta] of the three edge
// vectors leaving node i along the parametric axes. Positive for a valid hex, 1 for the unit cube.
std::array<double, 8> HexCornerJacobians(const HexNodes& p);
// Determinant at the centre (1/64 of the principal-axis triple product), same scale as the corners.
double HexCenterJacobian(const HexNodes& p);

double HexJacobian(const HexNodes& p);       // min(centre, 8 corners); < 0 means inverted
double HexScaledJacobian(const HexNodes& p); // min over centre and corners of det / edge lengths, in [-1, 1]
double HexShape(const HexNodes& p);          // min over corners of 3 det^(2/3) / |J|_F^2; 0 if any corner det <= 0
double HexShear(const HexNodes& p);          // min over corners of scaled Jacobian; 0 if any corner det <= 0
double HexSkew(const HexNodes& p);           // max |cos| between the principal axes
double HexTaper(const HexNodes& p);          // max ratio of cross-derivatives to principal axes
double HexStretch(const HexNodes& p);        // sqrt(3) min edge / max diagonal
double HexDiagonal(const HexNodes& p);       // min diagonal / max diagonal
// Verdict's hex edge ratio as in VTK 9.1: the longest of the first six edges (0-1, 1-2, 2-3, 3-0,
// 4-5, 5-6) over the shortest of all twelve. This reproduces a Verdict quirk on purpose.
double HexEdgeRatio(const HexNodes& p);
double HexMaxEdgeRatio(const HexNodes& p);       // max ratio of principal-axis lengths
double HexMaxAspectFrobenius(const HexNodes& p); // max corner Frobenius condition number / 3
double HexMedAspectFrobenius(const HexNodes& p); // mean corner Frobenius condition number / 3
double HexCondition(const HexNodes& p);          // = HexMaxAspectFrobenius
double HexOddy(const HexNodes& p);               // max Oddy distortion over centre and corners
double HexVolume(const HexNodes& p);             // VTK 9.1: the centre Jacobian (exact for parallelepipeds)

} // namespace mmrep::quality
