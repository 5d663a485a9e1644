// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Pipeline object for the muscle inference: the atlas (input 0) and the subject mesh with the
// atlas's topology (input 1, e.g. a MeshRepairFilter's output) -> the subject mesh with the atlas
// muscle tracks carried through an atlas -> subject itk::Transform and embedded again (output,
// input 1's field data kept). The transform is typically Q∘R: an itk::CompositeTransform of the
// registration's and the refinement's GetTransform(), which those filters refill when they run.
#pragma once

#include "mmrepFilterExecution.h"
#include "mmrepMuscleInference.h"

#include <itkTransform.h>
#include <vtkUnstructuredGridAlgorithm.h>

namespace mmrep
{

class MuscleInferenceFilter : public vtkUnstructuredGridAlgorithm
{
public:
  using Transform = itk::Transform<double, 3, 3>;
  static MuscleInferenceFilter* New();
  vtkTypeMacro(MuscleInferenceFilter, vtkUnstructuredGridAlgorithm);

  void SetAtlasToSubjectTransform(const Transform* transform);
  const Transform* GetAtlasToSubjectTransform() const { return transform_.GetPointer(); }

  const MuscleInferenceReport& GetReport() const { return report_; }
  const FilterStatus& GetStatus() const { return status_; }

protected:
  MuscleInferenceFilter();
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs) override;

private:
  MuscleInferenceFilter(const MuscleInferenceFilter&) = delete;
  void operator=(const MuscleInferenceFilter&) = delete;
  Transform::ConstPointer transform_;
  MuscleInferenceReport report_;
  FilterStatus status_;
};

} // namespace mmrep
