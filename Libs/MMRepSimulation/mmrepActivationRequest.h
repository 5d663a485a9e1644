// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// What a user asks SimulateMuscleActivation for (muscles or a gesture, jaw, tissue, element, solver),
// turned into the library's ActivationOptions with every check the solve depends on.
#pragma once

#include "mmrepGesture.h"
#include "mmrepMuscleActivation.h"

#include <array>
#include <string>
#include <vector>

namespace mmrep::simulation
{

struct ActivationRequest
{
  std::vector<std::string> muscles;
  std::vector<double> levels;    // one per muscle, or one for all
  std::string gesture;           // built-in name or a .json gesture file; empty: `muscles`
  bool hasJawAngle = false;      // false: the gesture's jaw angle (0 without a gesture)
  double jawAngle = 0;           // degrees
  double c10 = 2500, c20 = 1175; // Pa (Nazari et al. 2010)
  double poissonRatio = 0.49;
  std::array<double, 3> layerScale{1, 1, 1}; // epidermis, dermis, hypodermis
  std::string elementType = "C3D8R";
  double forceScale = 1;
  double initialIncrement = 0; // fraction of the step; 0: DefaultInitialIncrement (StepControl's own is 0.5)
  int maxIncrements = 100;
  bool lipContact = true;
  bool lipSupport = true;
  bool boneSliding = false; // the maxilla's nodes slide on the bone except the anchors (mmrepBoneSliding.h)
};

// First increment when the request gives none: 0.1 for a jaw opening with the muscles at rest (a
// prescribed motion, no activation ramp: ccx converges in fewer, larger increments), 0.05 otherwise.
double DefaultInitialIncrement(const std::vector<MuscleActivation>& activations, double jawAngle);

// One material per layer: C10 and C20 from the request (Pa -> N/mm²) with D1 keeping the Poisson
// ratio, each layer's coefficients multiplied by its factor (D1 divided: the Poisson ratio stays).
std::array<HyperelasticMaterial, 4> LayerMaterials(double c10Pa, double c20Pa, double poissonRatio,
                                                   const std::array<double, 3>& layerScale);

// The deck options of a request on `mesh` (read from `modelName`, for messages); `gesture` receives the gesture used (empty name
// without one). Throws std::invalid_argument with one line: unknown gesture or muscle, --gesture
// with --muscles, nothing to do, level count, a jaw opening or a gesture on a model without a jaw or
// mouth slit, bad material coefficients (see also CheckActivations).
DeckOptions MakeDeckOptions(const FEMesh& mesh, const ActivationRequest& request, const std::string& modelName,
                            Gesture& gesture);

// Why the simulation has no lip contact although it was asked for (a model without the mouth slit's
// sets), in words for a warning line; empty when it has.
std::string LipContactWarning(const FEMesh& mesh, const DeckOptions& deck, const std::string& modelName);

} // namespace mmrep::simulation
