// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Slicer's SPACE tag in mesh files (see mmrepCoordinateSpace.h).
#include "mmrepCoordinateSpace.h"

#include <vtkDataObject.h>
#include <vtkFieldData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>

namespace mmrep
{
namespace
{
constexpr const char* kTag = "SPACE"; // Slicer follows NRRD's name

FileSpace Parse(const std::string& value)
{
  if (value == "LPS")
    return FileSpace::LPS;
  if (value == "RAS")
    return FileSpace::RAS;
  return FileSpace::Untagged;
}
} // namespace

FileSpace SpaceFromHeader(const char* header)
{
  if (header == nullptr)
    return FileSpace::Untagged;
  const std::string text = header;
  const auto at = text.find(std::string(kTag) + "=");
  return at == std::string::npos ? FileSpace::Untagged : Parse(text.substr(at + 6, 3));
}

FileSpace SpaceFromFieldData(vtkDataObject* data)
{
  vtkFieldData* field = data ? data->GetFieldData() : nullptr;
  auto* array = field ? vtkStringArray::SafeDownCast(field->GetAbstractArray(kTag)) : nullptr;
  return array && array->GetNumberOfValues() > 0 ? Parse(array->GetValue(0)) : FileSpace::Untagged;
}

void RemoveSpaceTag(vtkDataObject* data)
{
  if (data && data->GetFieldData())
    data->GetFieldData()->RemoveArray(kTag);
}

void FlipRASToLPS(vtkPoints* points)
{
  if (points == nullptr)
    return;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, -p[0], -p[1], p[2]);
  }
  points->Modified();
}

} // namespace mmrep
