// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Triangle surfaces through VTK: .vtp, .vtk (legacy polydata), .stl, .ply, .obj, read and write.
#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>

namespace mmrep
{

// Throws std::runtime_error naming the path (missing, unknown extension, unreadable, no points).
vtkSmartPointer<vtkPolyData> ReadSurface(const std::string& path);
void WriteSurface(vtkPolyData* surface, const std::string& path); // format chosen by extension
void WriteSurface(vtkPolyData* surface, const std::string& path, const std::string& format);

} // namespace mmrep
