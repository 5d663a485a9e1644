// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Pipeline object for the lips refinement Q: registered mesh (input 0, an AtlasRegistrationFilter's
// output: its field data holds the subject plane and symmetry mode) and the subject skin (input 1)
// -> Q∘R(atlas) (output, same field data). Q's options as the FaceModelPipeline module sets them
// (RefinementOptionsFor: the registration's symmetry and plane); GetTransform() is Q.
#pragma once

#include "mmrepAtlasRegistration.h"
#include "mmrepElasticItkTransform.h"
#include "mmrepFilterExecution.h"

#include <vtkUnstructuredGridAlgorithm.h>

namespace mmrep
{

class LipsRefinementFilter : public vtkUnstructuredGridAlgorithm
{
public:
  static LipsRefinementFilter* New();
  vtkTypeMacro(LipsRefinementFilter, vtkUnstructuredGridAlgorithm);

  // Every option of Q (symmetric, halfFace, plane and progress are taken from the input); the main
  // ones also one by one.
  void SetRefinementOptions(const LocalRefinementOptions& options);
  const LocalRefinementOptions& GetRefinementOptions() const { return options_; }
  MMREP_FILTER_OPTION(Spacing, double, options_.spacing)
  MMREP_FILTER_OPTION(FinestLevel, int, options_.finestLevel)
  MMREP_FILTER_OPTION(ElementQualityFloor, double, options_.elementQualityFloor)
  MMREP_FILTER_OPTION(PinWeight, double, options_.pinWeight)

  ElasticItkTransform* GetTransform() const { return transform_.GetPointer(); } // Q, identity outside its box
  const FilterStatus& GetStatus() const { return status_; }

protected:
  LipsRefinementFilter();
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs) override;

private:
  LipsRefinementFilter(const LipsRefinementFilter&) = delete;
  void operator=(const LipsRefinementFilter&) = delete;
  LocalRefinementOptions options_;
  ElasticItkTransform::Pointer transform_ = ElasticItkTransform::New();
  FilterStatus status_;
};

} // namespace mmrep
