// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Subject surfaces of a head CT for the registration benchmark and the sample control points:
// the image stage and the symmetry plane exactly as FaceModelPipeline and BuildFaceAtlas make them.
#pragma once

#include "mmrepFaceModelPipeline.h"

#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <limits>
#include <string>

namespace mmrep::bench
{

struct SubjectSurfaces
{
  vtkSmartPointer<vtkPolyData> skin, skull;
  CTThresholds thresholds;
  SymmetryPlaneResult symmetry;
};

inline SubjectSurfaces SubjectSurfacesFromCT(const CTImage* ct, bool estimatePlane = true)
{
  vtkSMPTools::SetBackend("Sequential"); // sequential VTK locators, as BuildFaceAtlas
  const FaceModelOptions pipeline;       // the pipeline's image stage and plane, as BuildFaceAtlas
  const auto surfaces = ExtractSubjectSurfaces(ct, pipeline);
  SubjectSurfaces s;
  s.thresholds = surfaces.thresholds;
  s.skin = surfaces.skin;
  s.skull = surfaces.skull;
  if (estimatePlane)
    s.symmetry = EstimateSubjectPlane(s.skin, pipeline);
  return s;
}

} // namespace mmrep::bench
