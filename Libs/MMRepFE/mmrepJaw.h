// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The jaw of an FE face model: the bone attachment (node set `skull`) split into `maxilla` (held
// fixed) and `mandible` (moves rigidly with the jaw), and the jaw's rotation axis through the two
// condyles, stored as the two nodes of set `jawAxis` (left condyle first). Those two nodes belong to
// no element: every stage that moves the model's nodes (registration, refinement) carries them, so
// a speaker's model has the speaker's axis. A half model (mmrepHalfModel.h) keeps only the left
// condyle: the axis of a symmetric jaw is the symmetry plane's normal through it.
#pragma once

#include "mmrepFEMesh.h"

#include <Eigen/Geometry>

#include <string>

namespace mmrep
{

inline const std::string kMaxillaSet = "maxilla";
inline const std::string kMandibleSet = "mandible";
inline const std::string kJawAxisSet = "jawAxis";

// The range of jaw opening angles the simulation accepts, degrees (negative: clenching past rest).
constexpr double kMinJawAngle = -5.0, kMaxJawAngle = 30.0;

// True when the model has non-empty `mandible` and `maxilla` sets and a two-node `jawAxis` (one
// node on a half model).
bool HasJaw(const FEMesh& mesh);

// The rigid motion of the mandible for an opening of `degrees` about the condylar axis; the sense
// is the one that moves the mandible's nodes away from the maxilla's (the mouth opens for > 0).
// Throws std::invalid_argument with one line when the model has no jaw (see HasJaw).
Eigen::Isometry3d JawRotation(const FEMesh& mesh, double degrees);

} // namespace mmrep
