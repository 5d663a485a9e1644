// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The grids of an atlas registration, sized before the work: the subject's distance maps and the
// grid its transform is sampled on for output (a displacement field).
#pragma once

#include "mmrepAtlasRegistration.h"

#include <itkImage.h>

#include <string>
#include <vector>

namespace mmrep
{

// Refuses (std::runtime_error naming `parameter`) a map spacing whose distance maps of the
// subject's skin or skull (their bounds plus `margin`) would not fit in memory.
void CheckSubjectMapGrids(const SubjectData& subject, double margin, double spacing, const std::string& parameter);

// The points' bounding box grown by `margin` mm on every side, in voxels of `spacing` mm.
struct TransformGrid
{
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::vector<double> counts; // voxels per axis
  double spacing = 1;
  itk::Image<float, 3>::Pointer Image() const; // an unallocated image with this geometry
};
TransformGrid TransformGridAround(const std::vector<Point3>& points, double margin, double spacing);

} // namespace mmrep
