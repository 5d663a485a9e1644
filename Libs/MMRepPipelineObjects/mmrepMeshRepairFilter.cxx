// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// RepairMesh as a vtkUnstructuredGridAlgorithm (see the header).
#include "mmrepMeshRepairFilter.h"
#include "mmrepFEMeshIO.h"
#include "mmrepPipelineSymmetry.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

namespace mmrep
{

vtkStandardNewMacro(MeshRepairFilter);

MeshRepairFilter::MeshRepairFilter()
{
  this->SetNumberOfInputPorts(3);
}

int MeshRepairFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  if (port > 0)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int MeshRepairFilter::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs)
{
  auto* output = vtkUnstructuredGrid::GetData(outputs, 0);
  return ExecuteFilter(this, status_, [&](const FilterProgress& progress) {
    auto* input = RequiredInput(this, 0, "mesh");
    FEMesh mesh = FromVTK(vtkUnstructuredGrid::SafeDownCast(input));
    RepairOptions options;
    options.scaledJacobianThreshold = threshold_;
    options.maximumSweeps = sweeps_;
    vtkSmartPointer<vtkPolyData> skin, skull;
    if (this->GetNumberOfInputConnections(1) > 0)
      options.skinSurface = skin =
        CropSurfaceAround(vtkPolyData::SafeDownCast(RequiredInput(this, 1, "skin")), mesh, margin_);
    if (this->GetNumberOfInputConnections(2) > 0)
      options.skullSurface = skull =
        CropSurfaceAround(vtkPolyData::SafeDownCast(RequiredInput(this, 2, "skull")), mesh, margin_);
    const bool hasSymmetry = input->GetFieldData()->GetAbstractArray("SymmetryPlane") != nullptr;
    PipelineSymmetry symmetry;
    if (hasSymmetry)
    {
      symmetry = ReadSymmetry(input, "mesh");
      options.hasSymmetryPlane = symmetry.mode != "full";
      options.symmetryPlane = symmetry.plane;
    }
    options.progress = progress;
    report_ = RepairMesh(mesh, options);
    output->ShallowCopy(ToVTK(mesh));
    if (hasSymmetry)
      StoreSymmetry(symmetry, output);
  });
}

} // namespace mmrep
