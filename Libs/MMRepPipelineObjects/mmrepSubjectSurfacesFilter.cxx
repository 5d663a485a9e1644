// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// CT -> skin and skull surfaces as a VTK source (see the header).
#include "mmrepSubjectSurfacesFilter.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <stdexcept>

namespace mmrep
{

vtkStandardNewMacro(SubjectSurfacesFilter);

SubjectSurfacesFilter::SubjectSurfacesFilter()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

void SubjectSurfacesFilter::SetInput(CTImage* image)
{
  if (image_ == image)
    return;
  image_ = image;
  this->Modified();
}

int SubjectSurfacesFilter::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs)
{
  auto* skin = vtkPolyData::GetData(outputs, 0);
  auto* skull = vtkPolyData::GetData(outputs, 1);
  return ExecuteFilter(this, status_, [&](const FilterProgress& progress) {
    if (!image_)
      throw std::invalid_argument("no CT image (SetInput)");
    image_->Update(); // runs the image's ITK pipeline (reader errors surface here)
    progress(0.05);
    const auto s = ExtractSubjectSurfaces(image_, options_, [&](double f) { progress(0.05 + 0.95 * f); });
    thresholds_ = s.thresholds;
    skin->ShallowCopy(s.skin);
    skull->ShallowCopy(s.skull);
  });
}

} // namespace mmrep
