// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Points as a VTK vertex cloud (landmarks, node sets in pictures).
#pragma once

#include "mmrepFEMesh.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace mmrep
{

// One vertex cell per point, in order.
vtkSmartPointer<vtkPolyData> PointCloud(const std::vector<Point3>& positions);

} // namespace mmrep
