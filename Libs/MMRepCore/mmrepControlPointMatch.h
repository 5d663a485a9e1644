// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Control points of a subject paired with the landmarks of the atlas by name.
#pragma once

#include "mmrepFEMesh.h"

#include <vector>

namespace mmrep
{

// For each landmark (in its order) the position of the control point of the same name. Throws
// std::invalid_argument("control points: ...") when there are no points or no landmarks, a point
// has no name or is given twice, a landmark has no point, or a point matches no landmark.
std::vector<Point3> MatchControlPointsByName(const std::vector<Landmark>& landmarks,
                                             const std::vector<Landmark>& points);

} // namespace mmrep
