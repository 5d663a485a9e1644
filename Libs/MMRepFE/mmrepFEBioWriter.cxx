// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// FEBio input (.feb, format 3.0): the <Mesh> section only (nodes, element parts, node and element
// sets), to be completed with materials, MeshDomains and steps in FEBio Studio or a template.
// Parts: one per (tissue layer, solid type), named "<layer set>_<type>" (layer_epidermis_hex8, …),
// and one part "ECABLE" of line2 elements for all muscle cables. Ids are 1-based: node id = node
// index + 1, element id = element index + 1 across all parts. A half model adds its plane faces as a
// <Surface> and a "symmetry plane" constraint on it; a model with a mouth slit adds the lips' facing
// surfaces, their <SurfacePair> and a frictionless sliding-elastic <Contact>.
#include "mmrepFEExport.h"
#include "mmrepHalfModel.h"
#include "mmrepLipContact.h"

namespace mmrep::detail
{
namespace
{

const char* FEBioType(ElementType type)
{
  switch (type)
  {
    case ElementType::Hexahedron:
      return "hex8";
    case ElementType::Wedge:
      return "penta6";
    case ElementType::Tetrahedron:
      return "tet4";
    case ElementType::Cable:
      return "line2";
  }
  return "";
}

void WriteNodeSet(std::ostream& out, const std::string& name, const std::vector<std::int32_t>& ids)
{
  out << "    <NodeSet name=\"" << name << "\">\n";
  for (auto id : ids)
    out << "      <n id=\"" << id + 1 << "\"/>\n";
  out << "    </NodeSet>\n";
}

void WriteElementSet(std::ostream& out, const std::string& name, const std::vector<std::int32_t>& ids)
{
  out << "    <ElementSet name=\"" << name << "\">\n";
  for (auto id : ids)
    out << "      <e id=\"" << id + 1 << "\"/>\n";
  out << "    </ElementSet>\n";
}

} // namespace

void WriteFEBio(const FEMesh& mesh, std::ostream& out)
{
  const ExportNames names = MakeExportNames(mesh);
  // Part names share FEBio's element-set namespace: register every set name first.
  NameRegistry partNames;
  for (const char* reserved : {"EHEX", "EWEDGE", "ETET", "ECABLE", "ESOLID"})
    partNames.Add(reserved);
  for (const auto& name : names.elementSets)
    partNames.Add(name);
  for (const auto& name : names.layers)
    partNames.Add(name);
  for (const auto& name : names.muscles)
    partNames.Add(name);

  out << "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n";
  out << "<febio_spec version=\"3.0\">\n";
  out << "  <!-- MMRep FE face model: " << mesh.nodes.size() << " nodes, " << mesh.elements.size()
      << " elements; mm, LPS; ids are MMRep indices + 1 -->\n";
  out << "  <Module type=\"solid\"/>\n";
  out << "  <Mesh>\n";
  out << "    <Nodes name=\"NALL\">\n";
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
  {
    const auto& p = mesh.nodes[i];
    out << "      <node id=\"" << i + 1 << "\">" << FormatDouble(p.x()) << "," << FormatDouble(p.y()) << ","
        << FormatDouble(p.z()) << "</node>\n";
  }
  out << "    </Nodes>\n";

  auto writePart = [&](const std::string& name, ElementType type, const std::vector<std::size_t>& ids) {
    out << "    <Elements type=\"" << FEBioType(type) << "\" name=\"" << name << "\">\n";
    for (auto i : ids)
    {
      out << "      <elem id=\"" << i + 1 << "\">";
      const auto nodes = SolverNodeOrder(mesh.elements[i]);
      for (std::size_t k = 0; k < nodes.size(); ++k)
        out << (k ? "," : "") << nodes[k] + 1;
      out << "</elem>\n";
    }
    out << "    </Elements>\n";
  };
  for (auto layer : {TissueLayer::None, TissueLayer::Epidermis, TissueLayer::Dermis, TissueLayer::Hypodermis})
    for (auto type : {ElementType::Hexahedron, ElementType::Wedge, ElementType::Tetrahedron})
    {
      std::vector<std::size_t> ids;
      for (std::size_t i = 0; i < mesh.elements.size(); ++i)
        if (mesh.elements[i].type == type && mesh.elements[i].layer == layer)
          ids.push_back(i);
      if (!ids.empty())
        writePart(partNames.Add(names.layers[static_cast<int>(layer)] + "_" + FEBioType(type)), type, ids);
    }
  std::vector<std::size_t> cables;
  for (std::size_t i = 0; i < mesh.elements.size(); ++i)
    if (mesh.elements[i].type == ElementType::Cable)
      cables.push_back(i);
  if (!cables.empty())
    writePart("ECABLE", ElementType::Cable, cables);

  std::size_t k = 0;
  for (const auto& entry : mesh.nodeSets)
    WriteNodeSet(out, names.nodeSets[k++], entry.second);
  k = 0;
  for (const auto& entry : mesh.muscles)
    WriteNodeSet(out, names.muscleNodes[k++], entry.second.nodes);
  k = 0;
  for (const auto& entry : mesh.elementSets)
    WriteElementSet(out, names.elementSets[k++], entry.second);
  for (auto layer : {TissueLayer::None, TissueLayer::Epidermis, TissueLayer::Dermis, TissueLayer::Hypodermis})
  {
    const auto ids = mesh.SolidElementsOfLayer(layer);
    if (!ids.empty())
      WriteElementSet(out, names.layers[static_cast<int>(layer)], ids);
  }
  k = 0;
  for (const auto& entry : mesh.muscles)
    WriteElementSet(out, names.muscles[k++], entry.second.cables);
  // A half model: the plane faces as a surface carrying FEBio's "symmetry plane" constraint
  // (u·n = 0 on every node of the surface, augmented Lagrangian).
  std::string symmetrySurface;
  if (IsHalfModel(mesh))
  {
    symmetrySurface = partNames.Add(kSymmetryBoundarySet);
    out << "    <Surface name=\"" << symmetrySurface << "\">\n";
    int id = 0;
    for (const auto& face : SymmetryBoundaryFaces(mesh))
    {
      const char* type = face.size() == 4 ? "quad4" : "tri3";
      out << "      <" << type << " id=\"" << ++id << "\">";
      for (std::size_t j = 0; j < face.size(); ++j)
        out << (j ? "," : "") << face[j] + 1;
      out << "</" << type << ">\n";
    }
    out << "    </Surface>\n";
  }
  // The lips' facing surfaces as a surface pair for a sliding contact (FEBio: primary = upper lip).
  const auto upperFaces = LipContactFaces(mesh, true), lowerFaces = LipContactFaces(mesh, false);
  const bool lips = !upperFaces.empty() && !lowerFaces.empty();
  std::string upperName, lowerName;
  if (lips)
  {
    upperName = partNames.Add("upperLipContactFaces");
    lowerName = partNames.Add("lowerLipContactFaces");
    for (const auto* lip : {&upperFaces, &lowerFaces})
    {
      out << "    <Surface name=\"" << (lip == &upperFaces ? upperName : lowerName) << "\">\n";
      int id = 0;
      for (const auto& f : *lip)
        out << "      <quad4 id=\"" << ++id << "\">" << f.nodes[0] + 1 << "," << f.nodes[1] + 1 << "," << f.nodes[2] + 1
            << "," << f.nodes[3] + 1 << "</quad4>\n";
      out << "    </Surface>\n";
    }
    out << "    <SurfacePair name=\"lips\">\n      <primary>" << upperName << "</primary>\n      <secondary>"
        << lowerName << "</secondary>\n    </SurfacePair>\n";
  }
  out << "  </Mesh>\n";
  if (lips)
  {
    out << "  <Contact>\n    <contact type=\"sliding-elastic\" surface_pair=\"lips\">\n"
        << "      <penalty>1</penalty>\n      <auto_penalty>1</auto_penalty>\n      <two_pass>1</two_pass>\n"
        << "      <laugon>0</laugon>\n      <fric_coeff>0</fric_coeff>\n    </contact>\n  </Contact>\n";
  }
  if (!symmetrySurface.empty())
  {
    out << "  <Constraints>\n";
    out << "    <constraint type=\"symmetry plane\" surface=\"" << symmetrySurface << "\">\n";
    out << "      <laugon>1</laugon>\n      <penalty>1</penalty>\n      <tol>0.001</tol>\n"
        << "      <minaug>0</minaug>\n      <maxaug>50</maxaug>\n";
    out << "    </constraint>\n";
    out << "  </Constraints>\n";
  }
  out << "</febio_spec>\n";
}

} // namespace mmrep::detail
