// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// A displacement-field image as a point map: x -> x + u(x), u linearly interpolated. This is how
// a transform written by AtlasRegistration or FaceModelPipeline (u = T(x) - x sampled in atlas
// space) moves atlas points to the subject.
#pragma once

#include "mmrepImageIO.h"
#include "mmrepMuscleInference.h"

namespace mmrep
{

// The returned map throws std::out_of_range for a point outside the field's grid (there the
// transform is unknown). Throws std::invalid_argument for a null or empty field.
PointMap DisplacementFieldMap(const DisplacementField* field);

} // namespace mmrep

namespace mmrep
{

// u(x) = map(x) - x at every voxel of a grid of `spacing` mm covering the points' bounding box
// grown by `margin` mm (axis-aligned LPS). Voxels run in parallel; the bytes do not depend on the
// thread count.
DisplacementField::Pointer SampleDisplacementField(const PointMap& map, const std::vector<Point3>& points,
                                                   double margin, double spacing);
// Refuses, before any work, the grid SampleDisplacementField would make when it does not fit the
// memory budget: throws std::runtime_error "<parameter> <spacing>: the displacement field would be …".
void CheckDisplacementFieldSize(const std::vector<Point3>& points, double margin, double spacing,
                                const std::string& parameter);

} // namespace mmrep
