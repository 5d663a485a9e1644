// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Pipeline object for the registration stage: atlas FE mesh (input 0, vtkUnstructuredGrid as
// mmrep::ToVTK makes it), subject skin (input 1) and skull (input 2) surfaces, control points ->
// the registered atlas R(atlas) (output). As the FaceModelPipeline module does: the subject's
// mid-sagittal plane is estimated on the skin, then RegisterAtlas fits R. The output carries the
// plane and the symmetry mode in its field data (mmrepPipelineSymmetry.h) for the refinement and
// the repair downstream; GetTransform() is R as an itk::Transform, refilled at each execution.
#pragma once

#include "mmrepAtlasRegistration.h"
#include "mmrepElasticItkTransform.h"
#include "mmrepFilterExecution.h"

#include <vtkUnstructuredGridAlgorithm.h>

#include <vector>

namespace mmrep
{

class AtlasRegistrationFilter : public vtkUnstructuredGridAlgorithm
{
public:
  static AtlasRegistrationFilter* New();
  vtkTypeMacro(AtlasRegistrationFilter, vtkUnstructuredGridAlgorithm);

  // The subject's control points (LPS mm), named as the atlas landmarks.
  void SetControlPoints(const std::vector<Landmark>& points);
  const std::vector<Landmark>& GetControlPoints() const { return controlPoints_; }

  // Every option of R and of the plane estimate; the main ones also one by one.
  void SetRegistrationOptions(const AtlasRegistrationOptions& options);
  const AtlasRegistrationOptions& GetRegistrationOptions() const { return options_; }
  void SetPlaneOptions(const SymmetryPlaneOptions& options);
  const SymmetryPlaneOptions& GetPlaneOptions() const { return planeOptions_; }
  MMREP_FILTER_OPTION(FinestLevel, int, options_.finestLevel)
  MMREP_FILTER_OPTION(MapSpacing, double, options_.mapSpacing)
  MMREP_FILTER_OPTION(ControlPointWeight, double, options_.controlPointWeight)
  MMREP_FILTER_OPTION(ElementQualityFloor, double, options_.elementQualityFloor)
  MMREP_FILTER_OPTION(TieWeight, double, options_.tieWeight)
  MMREP_FILTER_OPTION(HoldingWeight, double, options_.holdingWeight)
  // "half-face" (default), "averaged" or "full"; another name is refused (ErrorEvent, unchanged).
  void SetSymmetryMode(const std::string& mode);
  std::string GetSymmetryMode() const { return SymmetryModeName(options_); }

  // Results of the last execution.
  ElasticItkTransform* GetTransform() const { return transform_.GetPointer(); } // R, atlas -> subject
  const Plane& GetSubjectPlane() const { return plane_.plane; }
  double GetPlaneResidual() const { return plane_.rmsResidual; } // mm RMS of the mirrored skin
  const RegistrationReport& GetReport() const { return report_; }
  const FilterStatus& GetStatus() const { return status_; }

protected:
  AtlasRegistrationFilter();
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs) override;

private:
  AtlasRegistrationFilter(const AtlasRegistrationFilter&) = delete;
  void operator=(const AtlasRegistrationFilter&) = delete;
  std::vector<Landmark> controlPoints_;
  AtlasRegistrationOptions options_;
  SymmetryPlaneOptions planeOptions_;
  ElasticItkTransform::Pointer transform_ = ElasticItkTransform::New();
  SymmetryPlaneResult plane_;
  RegistrationReport report_;
  FilterStatus status_;
};

} // namespace mmrep
