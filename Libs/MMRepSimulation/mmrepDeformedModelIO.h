// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The deformed model of a muscle activation as a VTK .vtu: nodes at their deformed positions, the
// FE model's sets, muscles and landmarks, point arrays Displacement (mm, the active vectors) and
// DisplacementMagnitude.
#pragma once

#include "mmrepMuscleActivation.h"

#include <string>

namespace mmrep::simulation
{

// Throws std::runtime_error when the file cannot be written.
void WriteDeformedModel(const FEMesh& mesh, const ActivationResult& result, const std::string& path);

} // namespace mmrep::simulation
