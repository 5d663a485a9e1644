// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The mouth slit of an FE face model: the upper and lower lips are separate element sets whose
// facing surfaces (node sets upperLipContact / lowerLipContact) coincide at rest, node for node,
// except along the two corner lines, whose nodes both lips share. A registration moves coincident
// nodes together; a stage that moves nodes one by one (the repair) closes the slit first (the lower
// lip's elements use the upper lip's nodes) and reopens it afterwards, so the lips stay closed at
// rest while a simulation can part them.
#pragma once

#include "mmrepFEMesh.h"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace mmrep
{

inline const std::string kUpperLipSet = "upperLip";               // element set
inline const std::string kLowerLipSet = "lowerLip";               // element set
inline const std::string kUpperLipContactSet = "upperLipContact"; // node set (corner lines included)
inline const std::string kLowerLipContactSet = "lowerLipContact"; // node set (corner lines included)

// True when the model has the four sets above (non-empty).
bool HasMouthSlit(const FEMesh& mesh);

// The facing-node pairs (upper-lip node, lower-lip twin): the i-th lower-lip-only contact node, in
// index order, with the i-th upper-lip-only one (the atlas numbers them so, and every stage keeps the
// node order). Empty on a model without a slit. Throws std::invalid_argument when the two lips have
// different numbers of facing nodes.
std::vector<std::pair<std::int32_t, std::int32_t>> MouthTwins(const FEMesh& mesh);

struct ClosedMouth
{
  std::vector<std::pair<std::int32_t, std::int32_t>> twins; // (upper-lip node, lower-lip node) at one point
  std::vector<std::pair<std::size_t, int>> slots;           // (element, corner) that used a lower-lip node
};

// Makes the lower lip's elements use the upper lip's node of each twin pair (MouthTwins): the twins
// are then used by no element. Nothing to do (empty result) on a model without a slit.
ClosedMouth CloseMouth(FEMesh& mesh);

// Undoes CloseMouth: the twins take their partner's current position and the lower lip's elements
// use them again.
void ReopenMouth(FEMesh& mesh, const ClosedMouth& closed);

// A facing surface: the faces of the lip's elements whose corners all are contact nodes of that lip.
// `face` is the CalculiX/Abaqus face number of a C3D8 (1..6); nodes in that face's order, which
// turns counter-clockwise seen from outside the element (outward normal).
struct LipContactFace
{
  std::int32_t element = -1;
  int face = 0;
  std::array<std::int32_t, 4> nodes{};
};
std::vector<LipContactFace> LipContactFaces(const FEMesh& mesh, bool upperLip);

// Signed gap (mm) between the lips with the given node displacements (empty: at rest): for every
// lower-lip contact node that is not on a corner line, its distance to the upper lip's facing
// surface, negative when it lies inside the upper lip (a node whose closest point is on the
// surface's rim lies beyond the facing region: positive). Returns the smallest and the mean.
struct LipGap
{
  double minimum = 0, mean = 0;
  std::size_t nodes = 0;
};
LipGap MeasureLipGap(const FEMesh& mesh, const std::vector<Point3>& displacements = {});

} // namespace mmrep
