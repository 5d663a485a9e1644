// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Pictures of a muscle activation: the deformed skin coloured by displacement over the rest skin,
// motion lines and landmarks, true scale, from the front and the left; optionally zoomed on the lips.
#pragma once

#include "mmrepMuscleActivation.h"

#include <string>
#include <vector>

namespace mmrep::simulation
{

// "A", "A + B", or "A + 3 more": fits a picture title.
std::string ShortList(const std::vector<std::string>& names);

// The largest displacement of a node of a solid element (mm).
double MaxSolidDisplacement(const FEMesh& mesh, const ActivationResult& result);

// Writes the PNGs to the paths that are not empty (needs an X display: see RequireDisplay).
void WriteActivationPictures(const FEMesh& mesh, const ActivationResult& result, double maxDisplacement,
                             const std::string& picture, const std::string& lipsPicture, const std::string& title);

} // namespace mmrep::simulation
