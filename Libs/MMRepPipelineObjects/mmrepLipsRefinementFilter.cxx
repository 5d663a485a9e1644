// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// RefineLocally as a vtkUnstructuredGridAlgorithm (see the header).
#include "mmrepLipsRefinementFilter.h"
#include "mmrepFaceModelPipeline.h"
#include "mmrepFEMeshIO.h"
#include "mmrepPipelineSymmetry.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

namespace mmrep
{

vtkStandardNewMacro(LipsRefinementFilter);

LipsRefinementFilter::LipsRefinementFilter()
{
  this->SetNumberOfInputPorts(2);
}

int LipsRefinementFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

void LipsRefinementFilter::SetRefinementOptions(const LocalRefinementOptions& options)
{
  options_ = options;
  this->Modified();
}

int LipsRefinementFilter::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs)
{
  auto* output = vtkUnstructuredGrid::GetData(outputs, 0);
  return ExecuteFilter(this, status_, [&](const FilterProgress& progress) {
    auto* input = RequiredInput(this, 0, "registered mesh");
    const FEMesh registered = FromVTK(vtkUnstructuredGrid::SafeDownCast(input));
    auto* skin = vtkPolyData::SafeDownCast(RequiredInput(this, 1, "subject skin"));
    const auto symmetry = ReadSymmetry(input, "registered mesh");
    FaceModelOptions pipeline;
    pipeline.refinement = options_;
    mmrep::SetSymmetryMode(pipeline.registration, symmetry.mode);
    auto options = RefinementOptionsFor(pipeline, symmetry.plane);
    options.progress = progress;
    auto q = RefineLocally(registered, skin, options);
    transform_->SetElasticTransforms({std::move(q.transform)});
    output->ShallowCopy(ToVTK(q.mesh));
    StoreSymmetry(symmetry, output);
  });
}

} // namespace mmrep
