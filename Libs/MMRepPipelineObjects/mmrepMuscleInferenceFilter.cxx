// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// InferMuscles as a vtkUnstructuredGridAlgorithm (see the header).
#include "mmrepMuscleInferenceFilter.h"
#include "mmrepFEMeshIO.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkUnstructuredGrid.h>

#include <stdexcept>

namespace mmrep
{

vtkStandardNewMacro(MuscleInferenceFilter);

MuscleInferenceFilter::MuscleInferenceFilter()
{
  this->SetNumberOfInputPorts(2);
}

int MuscleInferenceFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

void MuscleInferenceFilter::SetAtlasToSubjectTransform(const Transform* transform)
{
  if (transform_ == transform)
    return;
  transform_ = transform;
  this->Modified();
}

int MuscleInferenceFilter::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs)
{
  auto* output = vtkUnstructuredGrid::GetData(outputs, 0);
  return ExecuteFilter(this, status_, [&](const FilterProgress& progress) {
    if (!transform_)
      throw std::invalid_argument("no atlas -> subject transform (SetAtlasToSubjectTransform)");
    const FEMesh atlas = FromVTK(vtkUnstructuredGrid::SafeDownCast(RequiredInput(this, 0, "atlas mesh")));
    auto* input = RequiredInput(this, 1, "subject mesh");
    FEMesh subject = FromVTK(vtkUnstructuredGrid::SafeDownCast(input));
    progress(0.2);
    report_ = InferMuscles(
      atlas,
      [&](const Point3& x) {
        const auto y = transform_->TransformPoint(Transform::InputPointType(x.data()));
        return Point3(y[0], y[1], y[2]);
      },
      subject);
    output->ShallowCopy(ToVTK(subject));
    // The input's metadata (symmetry) travels on; ToVTK wrote the mesh's own arrays.
    vtkFieldData* field = input->GetFieldData();
    for (int i = 0; i < field->GetNumberOfArrays(); ++i)
      if (!output->GetFieldData()->GetAbstractArray(field->GetArrayName(i)))
        output->GetFieldData()->AddArray(field->GetAbstractArray(i));
  });
}

} // namespace mmrep
