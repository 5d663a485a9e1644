// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Internal helpers shared by the solver-format writers (.inp, .feb, .msh): set-name sanitizing,
// node-order conversion from VTK and locale-independent number formatting. Not installed.
#pragma once

#include "mmrepFEMesh.h"

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace mmrep::detail
{

// Names of every exported set, identical in all three formats so a user finds the same groups.
// Rules (documented in README.md): characters outside [A-Za-z0-9_] become '_'; a name that is empty
// or does not start with a letter gets the prefix "set_"; names are cut at 64 characters; names that
// then collide case-insensitively (Abaqus ignores case) get "_2", "_3", … in map order.
// Node-type and element-type names are made unique separately (Abaqus keeps them apart); the fixed
// names NALL, EHEX, EWEDGE, ETET, ECABLE, ESOLID are reserved for the per-type groups.
struct ExportNames
{
  std::vector<std::string> nodeSets;    // in mesh.nodeSets order
  std::vector<std::string> muscleNodes; // "muscle_<name>": the track nodes of each muscle
  std::vector<std::string> elementSets; // in mesh.elementSets order
  std::array<std::string, 4> layers;    // "layer_epidermis", …, indexed by TissueLayer
  std::vector<std::string> muscles;     // "muscle_<name>": the cables of each muscle
};
ExportNames MakeExportNames(const FEMesh& mesh);

// Makes names unique (case-insensitively) against everything registered so far.
class NameRegistry
{
public:
  std::string Add(const std::string& rawName);

private:
  std::vector<std::string> upperNames_;
};
std::string SanitizeName(const std::string& rawName);

// Node order of an element in the convention shared by Abaqus, FEBio and Gmsh, where the first
// triangle of a wedge winds counter-clockwise seen from the opposite triangle. A valid VTK wedge
// winds the other way (vtkCellValidator checks that its faces point outwards), so wedges swap
// nodes 1<->2 and 4<->5; hexahedra, tetrahedra and lines keep VTK's order.
std::vector<std::int32_t> SolverNodeOrder(const Element& element);

// Shortest decimal text that reads back to the same double (std::to_chars), never locale-dependent.
std::string FormatDouble(double value);

// Throws std::runtime_error naming the path when the mesh is empty or invalid.
void CheckWritable(const FEMesh& mesh, const std::string& path);

// Writers to an open stream (the caller opens the file and reports stream errors).
void WriteAbaqus(const FEMesh& mesh, std::ostream& out);
void WriteFEBio(const FEMesh& mesh, std::ostream& out);
void WriteGmsh(const FEMesh& mesh, std::ostream& out);

} // namespace mmrep::detail
