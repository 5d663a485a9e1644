// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Pipeline object for the image stage: the speaker's CT (an ITK image, typically an
// itk::ImageFileReader's output) -> skin surface (output 0) and skull surface (output 1), LPS mm,
// as ExtractSubjectSurfaces makes them for the FaceModelPipeline module.
//
//   auto reader = itk::ImageFileReader<mmrep::CTImage>::New(); reader->SetFileName("ct.nrrd");
//   vtkNew<mmrep::SubjectSurfacesFilter> surfaces; surfaces->SetInput(reader->GetOutput());
//   registration->SetInputConnection(1, surfaces->GetOutputPort(0)); // skin
//
// The image is updated (its ITK pipeline runs) each time this filter executes; call Modified()
// after the image or its source changed, as for any non-VTK input.
#pragma once

#include "mmrepFaceModelPipeline.h"
#include "mmrepFilterExecution.h"

#include <vtkPolyDataAlgorithm.h>

namespace mmrep
{

class SubjectSurfacesFilter : public vtkPolyDataAlgorithm
{
public:
  static SubjectSurfacesFilter* New();
  vtkTypeMacro(SubjectSurfacesFilter, vtkPolyDataAlgorithm);

  void SetInput(CTImage* image);
  CTImage* GetInput() const { return image_.GetPointer(); }

  // FaceModelOptions' image-stage fields (thresholds NaN: chosen by `ThresholdMode`).
  MMREP_FILTER_OPTION(ThresholdMode, ThresholdMode, options_.thresholdMode)
  MMREP_FILTER_OPTION(SkinThreshold, double, options_.skinThreshold)
  MMREP_FILTER_OPTION(BoneThreshold, double, options_.boneThreshold)
  MMREP_FILTER_OPTION(OpeningRadius, unsigned int, options_.openingRadius)
  MMREP_FILTER_OPTION(CloseSlits, double, options_.closeSlits)

  vtkPolyData* GetSkin() { return GetOutput(0); }
  vtkPolyData* GetSkull() { return GetOutput(1); }
  const CTThresholds& GetThresholds() const { return thresholds_; } // as chosen by the last run
  const FilterStatus& GetStatus() const { return status_; }

protected:
  SubjectSurfacesFilter();
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs) override;

private:
  SubjectSurfacesFilter(const SubjectSurfacesFilter&) = delete;
  void operator=(const SubjectSurfacesFilter&) = delete;
  CTImage::Pointer image_;
  FaceModelOptions options_;
  CTThresholds thresholds_;
  FilterStatus status_;
};

} // namespace mmrep
