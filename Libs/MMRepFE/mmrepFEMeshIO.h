// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Reading and writing FE face models.
//   .vtu  VTK XML unstructured grid: read and write, exact round trip of nodes, elements, layers,
//         node/element sets, muscles (with embedding) and landmarks (field data is authoritative;
//         point/cell masks are added for viewing in Slicer/ParaView).
//   .vtk  legacy VTK unstructured grid: read and write, same content.
//   .inp  Abaqus/CalculiX: write (C3D8, C3D6, C3D4, T3D2; *NSET/*ELSET for every set, layer and muscle).
//   .feb  FEBio format 3.0: write.
//   .msh  Gmsh 4.1 ASCII: write, with physical groups for layers, sets and muscles.
// A half model (mmrepHalfModel.h) also carries its symmetry condition in .inp (*TRANSFORM +
// *BOUNDARY) and .feb (symmetry-plane constraint on the plane's faces).
// Errors (missing file, unknown extension, unreadable content, empty mesh) throw std::runtime_error
// with one line naming the file.
#pragma once

#include "mmrepFEMesh.h"

#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <string>
#include <vector>

namespace mmrep
{

FEMesh ReadFEMesh(const std::string& path);
void WriteFEMesh(const FEMesh& mesh, const std::string& path); // format chosen by extension
// Same, with the format named explicitly ("vtu", "vtk", "inp", "feb", "msh"): lets callers write
// to a temporary file name whose extension differs.
void WriteFEMesh(const FEMesh& mesh, const std::string& path, const std::string& format);

std::vector<std::string> ReadableFEMeshExtensions(); // {".vtu", ".vtk"}
std::vector<std::string> WritableFEMeshExtensions(); // {".vtu", ".vtk", ".inp", ".feb", ".msh"}

// Conversion to and from VTK (cell data "Layer", field data for sets, muscles and landmarks).
vtkSmartPointer<vtkUnstructuredGrid> ToVTK(const FEMesh& mesh);
FEMesh FromVTK(vtkUnstructuredGrid* grid);

} // namespace mmrep
