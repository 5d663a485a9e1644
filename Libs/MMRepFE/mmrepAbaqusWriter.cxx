// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Abaqus / CalculiX input deck (.inp): mesh and sets only, no material or step, so the file can be
// *INCLUDEd from an analysis deck. Ids are 1-based: node id = node index + 1, element id =
// element index + 1 (solids and cables share one numbering, as Abaqus requires). A half model
// ends with its symmetry condition (local system on the plane nodes, normal DOF fixed).
#include "mmrepFEExport.h"
#include "mmrepLipContact.h"
#include "mmrepHalfModel.h"

#include <Eigen/Geometry>
#include <algorithm>

namespace mmrep::detail
{
namespace
{

// Abaqus allows at most 16 entries per data line of *NSET/*ELSET.
void WriteIdLines(std::ostream& out, const std::vector<std::int32_t>& ids)
{
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    out << ids[i] + 1;
    out << ((i % 16 == 15 || i + 1 == ids.size()) ? "\n" : ", ");
  }
}

void WriteSet(std::ostream& out, const char* keyword, const std::string& name, const std::string& origin,
              const std::vector<std::int32_t>& ids)
{
  std::string comment = origin; // raw user names: keep control characters out of the deck
  for (auto& c : comment)
    if (static_cast<unsigned char>(c) < 0x20)
      c = '?';
  if (ids.empty())
  {
    // Abaqus and CalculiX reject a set without members.
    out << "** empty " << comment << " omitted\n";
    return;
  }
  out << "** " << comment << "\n";
  out << "*" << keyword << ", " << keyword << "=" << name << "\n";
  WriteIdLines(out, ids);
}

struct TypeBlock
{
  ElementType type;
  const char* abaqusType;
  const char* setName;
};

} // namespace

void WriteAbaqus(const FEMesh& mesh, std::ostream& out)
{
  const ExportNames names = MakeExportNames(mesh);
  out << "** MMRep FE face model: " << mesh.nodes.size() << " nodes, " << mesh.elements.size()
      << " elements; coordinates in mm (LPS)\n";
  out << "** ids are 1-based: node/element id = MMRep index + 1\n";
  out << "*NODE, NSET=NALL\n";
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
  {
    const auto& p = mesh.nodes[i];
    out << i + 1 << ", " << FormatDouble(p.x()) << ", " << FormatDouble(p.y()) << ", " << FormatDouble(p.z()) << "\n";
  }

  // Fixed set names per element type; MakeExportNames reserves them so user sets never reuse them.
  const TypeBlock blocks[] = {{ElementType::Hexahedron, "C3D8", "EHEX"},
                              {ElementType::Wedge, "C3D6", "EWEDGE"},
                              {ElementType::Tetrahedron, "C3D4", "ETET"},
                              {ElementType::Cable, "T3D2", "ECABLE"}};
  std::vector<std::string> solidBlocks;
  for (const auto& block : blocks)
  {
    std::vector<std::size_t> ids;
    for (std::size_t i = 0; i < mesh.elements.size(); ++i)
      if (mesh.elements[i].type == block.type)
        ids.push_back(i);
    if (ids.empty())
      continue;
    out << "*ELEMENT, TYPE=" << block.abaqusType << ", ELSET=" << block.setName << "\n";
    for (auto i : ids)
    {
      out << i + 1;
      for (auto node : SolverNodeOrder(mesh.elements[i]))
        out << ", " << node + 1;
      out << "\n";
    }
    if (block.type != ElementType::Cable)
      solidBlocks.push_back(block.setName);
  }
  if (!solidBlocks.empty())
  {
    out << "** all solid elements\n*ELSET, ELSET=ESOLID\n";
    for (std::size_t k = 0; k < solidBlocks.size(); ++k)
      out << solidBlocks[k] << (k + 1 == solidBlocks.size() ? "\n" : ", ");
  }

  std::size_t k = 0;
  for (const auto& [name, ids] : mesh.nodeSets)
    WriteSet(out, "NSET", names.nodeSets[k++], "node set '" + name + "'", ids);
  k = 0;
  for (const auto& [name, ids] : mesh.elementSets)
    WriteSet(out, "ELSET", names.elementSets[k++], "element set '" + name + "'", ids);
  for (auto layer : {TissueLayer::None, TissueLayer::Epidermis, TissueLayer::Dermis, TissueLayer::Hypodermis})
  {
    const auto ids = mesh.SolidElementsOfLayer(layer);
    if (!ids.empty())
      WriteSet(out, "ELSET", names.layers[static_cast<int>(layer)],
               std::string("tissue layer ") + TissueLayerName(layer), ids);
  }
  k = 0;
  for (const auto& [name, muscle] : mesh.muscles)
  {
    WriteSet(out, "NSET", names.muscleNodes[k], "muscle '" + name + "' track nodes", muscle.nodes);
    WriteSet(out, "ELSET", names.muscles[k], "muscle '" + name + "' cables", muscle.cables);
    ++k;
  }

  // The lips' facing surfaces and their contact interaction (frictionless, linear penalty 1 N/mm³
  // of overclosure). The pair itself is written as a comment line to remove: contact makes every
  // analysis non-linear, and CalculiX then expands the T3D2 cables with mean-rotation constraints,
  // which a held muscle node breaks (SimulateMuscleActivation uses gap elements instead).
  const auto upperFaces = LipContactFaces(mesh, true), lowerFaces = LipContactFaces(mesh, false);
  if (!upperFaces.empty() && !lowerFaces.empty())
  {
    out << "** lips: the mouth slit's facing surfaces (closed at rest) and their contact pair\n";
    for (const auto* lip : {&upperFaces, &lowerFaces})
    {
      out << "*SURFACE, NAME=" << (lip == &upperFaces ? "S_UPPERLIP" : "S_LOWERLIP") << ", TYPE=ELEMENT\n";
      for (const auto& f : *lip)
        out << f.element + 1 << ", S" << f.face << "\n";
    }
    out << "*SURFACE INTERACTION, NAME=LIPS\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1., 1e-9\n";
    out << "** to keep the lips apart, remove '** ' from the next two lines (the analysis becomes non-linear):\n"
        << "** *CONTACT PAIR, INTERACTION=LIPS, TYPE=SURFACE TO SURFACE\n** S_LOWERLIP, S_UPPERLIP\n";
  }

  // A half model: its plane nodes move within the plane. Local x axis = plane normal (point a of
  // *TRANSFORM, TYPE=R), b any in-plane direction; *BOUNDARY on local DOF 1.
  if (IsHalfModel(mesh))
  {
    const Plane plane = SymmetryPlaneOf(mesh);
    const Eigen::Vector3d& n = plane.normal;
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    Eigen::Index least = 0;
    n.cwiseAbs().minCoeff(&least);
    axis[least] = 1;
    const Eigen::Vector3d b = n.cross(axis).normalized();
    const auto set = std::distance(mesh.nodeSets.begin(), mesh.nodeSets.find(kSymmetryBoundarySet));
    const std::string& name = names.nodeSets[static_cast<std::size_t>(set)];
    out << "** symmetry boundary of this half model: normal displacement 0 on the mid-sagittal plane (point "
        << FormatDouble(plane.point.x()) << ", " << FormatDouble(plane.point.y()) << ", "
        << FormatDouble(plane.point.z()) << ")\n";
    out << "*TRANSFORM, NSET=" << name << ", TYPE=R\n"
        << FormatDouble(n.x()) << ", " << FormatDouble(n.y()) << ", " << FormatDouble(n.z()) << ", "
        << FormatDouble(b.x()) << ", " << FormatDouble(b.y()) << ", " << FormatDouble(b.z()) << "\n";
    out << "*BOUNDARY\n" << name << ", 1, 1\n";
  }
}

} // namespace mmrep::detail
