// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Symmetry plane and mode in field data (see the header).
#include "mmrepPipelineSymmetry.h"

#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>

#include <stdexcept>

namespace mmrep
{

void StoreSymmetry(const PipelineSymmetry& symmetry, vtkDataObject* data)
{
  vtkNew<vtkDoubleArray> plane;
  plane->SetName("SymmetryPlane");
  plane->SetNumberOfComponents(6);
  const double values[6] = {symmetry.plane.point.x(),  symmetry.plane.point.y(),  symmetry.plane.point.z(),
                            symmetry.plane.normal.x(), symmetry.plane.normal.y(), symmetry.plane.normal.z()};
  plane->InsertNextTuple(values);
  vtkNew<vtkStringArray> mode;
  mode->SetName("SymmetryMode");
  mode->InsertNextValue(symmetry.mode);
  data->GetFieldData()->AddArray(plane);
  data->GetFieldData()->AddArray(mode);
}

PipelineSymmetry ReadSymmetry(vtkDataObject* data, const std::string& what)
{
  vtkFieldData* field = data ? data->GetFieldData() : nullptr;
  auto* plane = field ? vtkDoubleArray::SafeDownCast(field->GetAbstractArray("SymmetryPlane")) : nullptr;
  auto* mode = field ? vtkStringArray::SafeDownCast(field->GetAbstractArray("SymmetryMode")) : nullptr;
  if (!plane || plane->GetNumberOfComponents() != 6 || plane->GetNumberOfTuples() != 1 || !mode ||
      mode->GetNumberOfValues() != 1)
    throw std::invalid_argument(what + ": no symmetry plane and mode in its field data (arrays SymmetryPlane, "
                                       "SymmetryMode: connect it to an AtlasRegistrationFilter's output)");
  PipelineSymmetry s;
  const double* v = plane->GetTuple(0);
  s.plane.point = Eigen::Vector3d(v[0], v[1], v[2]);
  s.plane.normal = Eigen::Vector3d(v[3], v[4], v[5]);
  s.mode = mode->GetValue(0);
  return s;
}

} // namespace mmrep
