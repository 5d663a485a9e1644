// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Speech gestures: which muscles to activate, how much, and the jaw opening.
//   smile: both zygomatici majores at full activation (the mouth corners move up and lateral);
//   round: the four orbicularis oris tracks of each side at full activation (lips forward, mouth narrower);
//   open:  a 10 degree jaw opening with the muscles at rest (the lips part);
//   close: bilabial closure (/p b m/): orbicularis oris marginalis at 0.6 and mentalis at 0.3 of each
//          side, jaw at rest (the lips press together).
// On a half model only the left muscles exist; they stand for the symmetric gesture.
// A gesture file (JSON) gives the same: {"name": "...", "muscles": {"ZygomaticusMajor_L": 1.0, ...},
// "jawAngle": 10}; both keys are optional but one must do something.
#pragma once

#include "mmrepCalculiXDeck.h"
#include "mmrepFEMesh.h"

#include <string>
#include <vector>

namespace mmrep::simulation
{

struct Gesture
{
  std::string name;
  std::vector<MuscleActivation> activations;
  double jawAngle = 0; // degrees
};

// "smile, round, open, close".
std::string GestureNames();

// The built-in gesture `name` for the muscles of `mesh`. Throws std::invalid_argument with one line
// for an unknown name (listing the valid ones) or a model that lacks the gesture's muscles.
Gesture BuiltInGesture(const std::string& name, const FEMesh& mesh);

// Reads a gesture file. Throws std::invalid_argument with one line naming the file and the problem.
Gesture ReadGestureFile(const std::string& path);

} // namespace mmrep::simulation
