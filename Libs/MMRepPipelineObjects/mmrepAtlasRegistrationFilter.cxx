// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// RegisterAtlas as a vtkUnstructuredGridAlgorithm (see the header).
#include "mmrepAtlasRegistrationFilter.h"
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

vtkStandardNewMacro(AtlasRegistrationFilter);

AtlasRegistrationFilter::AtlasRegistrationFilter()
{
  this->SetNumberOfInputPorts(3);
}

int AtlasRegistrationFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

void AtlasRegistrationFilter::SetControlPoints(const std::vector<Landmark>& points)
{
  controlPoints_ = points;
  this->Modified();
}

void AtlasRegistrationFilter::SetRegistrationOptions(const AtlasRegistrationOptions& options)
{
  options_ = options;
  this->Modified();
}

void AtlasRegistrationFilter::SetPlaneOptions(const SymmetryPlaneOptions& options)
{
  planeOptions_ = options;
  this->Modified();
}

void AtlasRegistrationFilter::SetSymmetryMode(const std::string& mode)
{
  try
  {
    auto options = options_;
    mmrep::SetSymmetryMode(options, mode);
    SetRegistrationOptions(options);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
  }
}

int AtlasRegistrationFilter::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs)
{
  auto* output = vtkUnstructuredGrid::GetData(outputs, 0);
  return ExecuteFilter(this, status_, [&](const FilterProgress& progress) {
    const FEMesh atlas = FromVTK(vtkUnstructuredGrid::SafeDownCast(RequiredInput(this, 0, "atlas mesh")));
    SubjectData subject;
    subject.skin = vtkPolyData::SafeDownCast(RequiredInput(this, 1, "subject skin"));
    subject.skull = vtkPolyData::SafeDownCast(RequiredInput(this, 2, "subject skull"));
    std::vector<std::string> names;
    const auto targets = MatchControlPoints(nullptr, controlPoints_, atlas, names);
    for (std::size_t i = 0; i < names.size(); ++i)
      subject.controlPoints.push_back({names[i], targets[i]});
    FaceModelOptions planeOptions;
    planeOptions.plane = planeOptions_;
    plane_ = EstimateSubjectPlane(subject.skin, planeOptions);
    subject.plane = plane_.plane;
    progress(0.15);
    auto options = options_;
    options.progress = [&](double f) { progress(0.15 + 0.85 * f); };
    auto r = RegisterAtlas(atlas, FitPlaneToNodeSet(atlas, "midsagittal"), subject, options);
    transform_->SetElasticTransforms({std::move(r.transform)});
    report_ = std::move(r.report);
    output->ShallowCopy(ToVTK(r.mesh));
    StoreSymmetry({plane_.plane, SymmetryModeName(options_)}, output);
  });
}

} // namespace mmrep
