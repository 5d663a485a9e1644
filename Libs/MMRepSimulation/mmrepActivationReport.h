// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The text report of a muscle activation: solver figures, each muscle's length and force, every
// landmark's displacement, and the mouth measures (width, aperture, protrusion, lip gap).
#pragma once

#include "mmrepMouthMeasures.h"

#include <string>

namespace mmrep::simulation
{

std::string ActivationReport(const ActivationResult& result, int threads, double jawAngle, const MouthMeasures& mouth,
                             double maxDisplacement);

} // namespace mmrep::simulation
