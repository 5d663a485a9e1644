// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// CalculiX (ccx) input deck for a muscle-activation solve of an FE face model.
//
// Units: the mesh is in mm, so forces are N, stresses/moduli N/mm² (= MPa; 1 Pa = 1e-6 N/mm²),
// the compressibility D N⁻¹mm², cable forces N.
//
// Model written (Modules/CLI/SimulateMuscleActivation/README.md explains the choices):
//   * solids: hyperelastic polynomial N=2 (C10, C01, C20, C11, C02, D1, D2), one material per
//     tissue layer; hexahedra as C3D8/C3D8I/C3D8R, wedges C3D6, tetrahedra C3D4;
//   * cables: SPRINGA (axial, large-rotation) elements, force N along the fibre. Each cable of a
//     track carries the Hill-type law of CableForce (active force-length times activation times the
//     track's maximum force, plus a small stabilising slope), written as a piecewise-linear
//     force-elongation curve at "temperature" 0 (activation 0) and 1 (the muscle's level); the
//     temperature is only a load parameter ramped 0 -> 1 over the step (no thermal expansion
//     anywhere), so the activation grows gradually;
//   * embedding: every muscle node follows its solid element, u_m − Σ N_i(pcoords) u_i = 0 (three
//     *EQUATION per node, the element's own shape functions, so it is exact for any deformation);
//   * fixed nodes (node set "skull" by default; `maxilla` on a model with a jaw): *BOUNDARY 1–3;
//   * a jaw opening: the `mandible` nodes' rigid rotation as prescribed displacements (mmrepJaw.h);
//   * lips: GAPUNI gap elements between the facing nodes of the mouth slit (no interpenetration);
//   * sliding nodes (optional, e.g. the lips' inner surface on the teeth): n·u = 0 by *EQUATION;
//   * a half model (mmrepHalfModel.h): its symmetry boundary's solid nodes keep n·u = 0, n the
//     refitted plane's normal, by *EQUATION too (a node that also slides gets both constraints);
//   * nodal loads (optional, *CLOAD, ramped with the step), e.g. for element tests;
//   * one *STEP, NLGEOM, *STATIC with automatic incrementation; *NODE FILE U (.frd).
#pragma once

#include "mmrepCableLaw.h"
#include "mmrepEmbedding.h"
#include "mmrepFEMesh.h"
#include "mmrepLipSupport.h"
#include "mmrepTissue.h"

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace mmrep::simulation
{

// The activated state of one muscle: activation level in [0, 1].
struct MuscleActivation
{
  std::string muscle; // name as stored in FEMesh::muscles (case-sensitive)
  double level = 1.0;
};

struct StepControl
{
  double initialIncrement = 0.5; // fraction of the step; ccx halves it (cutback) when it fails
  double minIncrement = 1e-4;
  double maxIncrement = 1.0;
  int maxIncrements = 100;
};

// A concentrated force (N) on a node of a solid element (*CLOAD), ramped from 0 over the step.
struct NodalLoad
{
  std::int32_t node = -1;
  Point3 force = Point3::Zero();
};

struct DeckOptions
{
  // Index = TissueLayer (None, Epidermis, Dermis, Hypodermis); elements of layer None use [0].
  std::array<HyperelasticMaterial, 4> materials{FaceTissue(), FaceTissue(), FaceTissue(), FaceTissue()};
  std::string hexahedronType = "C3D8R"; // C3D8R, C3D8I or C3D8 (see the module README: C3D8 locks)
  std::vector<MuscleActivation> activations;
  CableModel cables;
  std::string fixedNodeSet = "skull";
  std::vector<SlidingNode> slidingNodes; // e.g. LipSupportNodes(mesh); fixed nodes among them are skipped
  bool symmetry = true;                  // a half model: its symmetry boundary's nodes move within the plane
  std::vector<NodalLoad> loads;          // with loads, `activations` may be empty (a purely passive solve)
  StepControl step;
  // Jaw opening (degrees, mmrepJaw.h): on a model with a jaw the `maxilla` nodes are fixed and the
  // `mandible` nodes rotate rigidly about the condylar axis (prescribed displacements, ramped over
  // the step); the lip-support nodes nearest the mandible are then left free (their support, the
  // lower teeth, moves away with it). Without a jaw the angle must be 0 and `fixedNodeSet` is fixed.
  double jawAngle = 0;
  // The lips' facing surfaces (mmrepLipContact.h) kept from interpenetrating: a gap element (GAPUNI,
  // frictionless) per pair of facing nodes along the upper surface's normal, penalty
  // `contactStiffness` (N/mm of overclosure per pair).
  bool lipContact = true;
  double contactStiffness = 50.0;
};

// What the deck contains (for reports and tests).
struct DeckSummary
{
  std::size_t solids = 0, springs = 0, equations = 0, fixedNodes = 0, slidingNodes = 0, symmetryNodes = 0;
  std::size_t jawNodes = 0, contactNodes = 0, contactFaces = 0; // mandible nodes moved; lip gap pairs, facing faces
  std::vector<std::string> activeMuscles;                       // muscles written as springs, in activation order
};

// Names of the muscles of `mesh`, in stored (sorted) order.
std::vector<std::string> MuscleNames(const FEMesh& mesh);

// Throws std::invalid_argument with one line when the mesh has no muscles, a muscle name is unknown
// (the message lists the valid names; on a half model a right-side "_R" muscle says so), a level is outside [0, 1], a muscle is named twice, or no
// muscle has a positive level.
// With `requireActive` false (a jaw opening alone), no muscle or only zero levels are accepted.
void CheckActivations(const FEMesh& mesh, const std::vector<MuscleActivation>& activations, bool requireActive = true);

// Writes the deck. Node id = node index + 1; element id = element index + 1. Only the cables of
// muscles with a positive level are written (inactive cables would only add the small stabilising slope), with
// their track nodes and equations; other muscle nodes are left out of the deck.
// Throws std::invalid_argument (see CheckActivations, skipped when there are loads and no
// activations; also an empty or missing fixed node set, an unknown hexahedron type, a muscle node
// without a valid embedding, a load on a node that is not a solid's).
DeckSummary WriteCalculiXDeck(const FEMesh& mesh, const DeckOptions& options, std::ostream& out);

// Shape functions of the embedding: ShapeFunctions in mmrepEmbedding.h (MMRepFE).
using mmrep::ShapeFunctions;

} // namespace mmrep::simulation
