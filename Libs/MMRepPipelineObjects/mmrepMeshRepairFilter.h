// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Pipeline object for the repair: FE mesh (input 0; its field data's symmetry plane, when the mode
// is symmetric, is kept as the FaceModelPipeline module keeps it), subject skin (input 1) and skull
// (input 2, both optional: without them the mesh's own boundary) -> the repaired mesh (output,
// same field data). The surfaces are cropped around the mesh as the module crops them.
// A mesh that cannot reach the threshold is not an error: GetReport().success says so.
#pragma once

#include "mmrepFaceModelPipeline.h"
#include "mmrepFilterExecution.h"
#include "mmrepMeshRepair.h"

#include <vtkUnstructuredGridAlgorithm.h>

namespace mmrep
{

class MeshRepairFilter : public vtkUnstructuredGridAlgorithm
{
public:
  static MeshRepairFilter* New();
  vtkTypeMacro(MeshRepairFilter, vtkUnstructuredGridAlgorithm);

  MMREP_FILTER_OPTION(ScaledJacobianThreshold, double, threshold_)
  MMREP_FILTER_OPTION(MaximumSweeps, int, sweeps_)
  MMREP_FILTER_OPTION(SurfaceMargin, double, margin_) // mm kept of the surfaces around the mesh

  const RepairReport& GetReport() const { return report_; }
  const FilterStatus& GetStatus() const { return status_; }

protected:
  MeshRepairFilter();
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs) override;

private:
  MeshRepairFilter(const MeshRepairFilter&) = delete;
  void operator=(const MeshRepairFilter&) = delete;
  // The module's defaults.
  double threshold_ = FaceModelOptions{}.repairThreshold;
  int sweeps_ = FaceModelOptions{}.repairSweeps;
  double margin_ = kRepairSurfaceMargin;
  RepairReport report_;
  FilterStatus status_;
};

} // namespace mmrep
