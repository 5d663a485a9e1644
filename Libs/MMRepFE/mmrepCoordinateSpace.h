// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Slicer's coordinate-system tag in mesh files (vtkMRMLModelStorageNode, Slicer >= 4.11): "SPACE=LPS"
// or "SPACE=RAS" in the header of legacy .vtk (and .stl) files, a one-value string array named
// "SPACE" in the field data of .vtp/.vtu files. Untagged files are LPS (Slicer's default since 4.11
// and this project's convention); RAS files are flipped to LPS when read. Legacy .vtk files we
// write say SPACE=LPS; .vtp/.vtu are written untagged (the shipped atlas files stay byte for byte).
#pragma once

#include <string>

class vtkDataObject;
class vtkPoints;

namespace mmrep
{

enum class FileSpace
{
  Untagged,
  LPS,
  RAS
};

FileSpace SpaceFromHeader(const char* header);     // legacy header / STL header
FileSpace SpaceFromFieldData(vtkDataObject* data); // .vtp / .vtu field data
void RemoveSpaceTag(vtkDataObject* data);          // the tag is file metadata, not data
void FlipRASToLPS(vtkPoints* points);              // (x, y, z) -> (-x, -y, z)
inline const char* LPSHeaderTag()
{
  return "SPACE=LPS";
} // what Slicer writes in legacy headers

} // namespace mmrep
