// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// What a repair did, for its users: the scaled Jacobians for a histogram, the accuracy of the
// surface node sets before and after, the JSON report and the one-line failure message of the
// MeshReparation module.
#pragma once

#include "mmrepMeshRepair.h"
#include "mmrepSurfaceDistance.h"

#include <vtkPolyData.h>

#include <string>
#include <vector>

namespace mmrep
{

// Scaled Jacobian of every solid element, degenerate ones (Verdict's flag) as -infinity.
std::vector<double> ScaledJacobianValues(const FEMesh& mesh);

// Accuracy of a node set against a given surface: `skin` and `lips` against the skin, `skull`
// against the skull (only for the surfaces given).
struct SurfaceAccuracy
{
  std::string set, surfaceName; // surfaceName: the parameter the surface came from
  vtkPolyData* surface = nullptr;
  SurfaceDistance before, after;
};
std::vector<SurfaceAccuracy> SurfaceAccuracySets(vtkPolyData* skin, vtkPolyData* skull);
// Fills `before` (after = false) or `after` of each entry from the mesh.
void MeasureSurfaceAccuracy(const FEMesh& mesh, std::vector<SurfaceAccuracy>& accuracy, bool after);

// The JSON report (pretty-printed): input, output (null unless the repair succeeded), threshold,
// quality before and after, surface accuracy, moved nodes, failed elements with their layers.
std::string RepairReportJson(const RepairReport& report, const FEMesh& repaired,
                             const std::vector<SurfaceAccuracy>& accuracy, const std::string& input,
                             const std::string& output, double threshold);

// "<n> elements stay below the scaled Jacobian threshold <t> (worst: element <e>, <value>)".
std::string RepairFailureMessage(const RepairReport& report, double threshold);

} // namespace mmrep
