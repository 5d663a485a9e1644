// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The subject's symmetry as it flows down the pipeline objects: the registration estimates the
// mid-sagittal plane and fits in one symmetry mode ("half-face", "averaged", "full"); the refinement
// and the repair need both. They travel in the mesh's field data (arrays "SymmetryPlane": point
// then normal, LPS mm; "SymmetryMode": the mode's name), as VTK metadata does, so that one Update()
// at the end of the pipeline runs every stage with the plane the registration found.
#pragma once

#include "mmrepPlane.h"

#include <string>

class vtkDataObject;

namespace mmrep
{

struct PipelineSymmetry
{
  Plane plane;
  std::string mode = "half-face";
};

void StoreSymmetry(const PipelineSymmetry& symmetry, vtkDataObject* data);
// Throws std::invalid_argument naming `what` when the arrays are missing or malformed.
PipelineSymmetry ReadSymmetry(vtkDataObject* data, const std::string& what);

} // namespace mmrep
