// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Solver formats checked by the real tools: CalculiX solves the .inp, Gmsh loads and converts the
// .msh, and the .feb is parsed as XML and its element orientation checked.
#include "mmrepFEMeshIO.h"
#include "mmrepFETestMesh.h"
#include "mmrepFETestUtilities.h"

#include <vtkCellData.h>
#include <vtkCellValidator.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>

using namespace mmrep;
using mmrep::testing::MakeTestMesh;
namespace fs = std::filesystem;

namespace
{

std::vector<std::string> Lines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::vector<long> Numbers(const std::string& line)
{
  std::vector<long> values;
  std::string s = line;
  for (auto& c : s)
    if (c == ',')
      c = ' ';
  std::istringstream in(s);
  for (long v; in >> v;)
    values.push_back(v);
  return values;
}

// Reads *NSET/*ELSET blocks of an .inp: upper-cased set name -> 1-based ids (set names resolved).
std::map<std::string, std::vector<long>> InpSets(const std::string& text, const std::string& keyword)
{
  std::map<std::string, std::vector<long>> sets;
  std::vector<long>* current = nullptr;
  for (const auto& line : Lines(text))
  {
    if (line.rfind("**", 0) == 0)
      continue;
    if (line.rfind("*", 0) == 0)
    {
      current = nullptr;
      const std::regex header("\\*" + keyword + ", *" + keyword.substr(1) + "=([A-Za-z0-9_]+)", std::regex::icase);
      std::smatch m;
      if (std::regex_search(line, m, header))
      {
        std::string name = m[1];
        for (auto& c : name)
          c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        current = &sets[name];
      }
      continue;
    }
    if (current)
      for (auto v : Numbers(line))
        current->push_back(v);
  }
  return sets;
}

std::vector<long> PlusOne(const std::vector<std::int32_t>& ids)
{
  std::vector<long> out;
  for (auto id : ids)
    out.push_back(id + 1);
  return out;
}

// Material, sections, boundary conditions and a static step around the written mesh: the skull
// is clamped, the skin pulled 0.1 mm along z, the muscle nodes (not attached to solids) fixed.
const char* kAnalysis = R"(*MATERIAL, NAME=TISSUE
*ELASTIC
0.02, 0.45
*SOLID SECTION, ELSET=ESOLID, MATERIAL=TISSUE
*MATERIAL, NAME=FIBRE
*ELASTIC
0.5, 0.3
*SOLID SECTION, ELSET=ECABLE, MATERIAL=FIBRE
0.25
*BOUNDARY
skull, 1, 3
muscle_orbicularis_oris, 1, 3
muscle_levator_labii_50_, 1, 3
*STEP
*STATIC
*BOUNDARY
skin, 3, 3, 0.1
*NODE PRINT, NSET=NALL
U
*END STEP
)";

mmrep::testing::CommandResult RunCalculiX(const FEMesh& mesh, const fs::path& dir)
{
  WriteFEMesh(mesh, (dir / "mesh.inp").string());
  std::ofstream(dir / "job.inp") << mmrep::testing::ReadText(dir / "mesh.inp") << kAnalysis;
  return mmrep::testing::Run("cd '" + dir.string() + "' && OMP_NUM_THREADS=1 ccx -i job", dir);
}

// Signed volume of the first corner tetrahedron in the solver convention (first face winding
// counter-clockwise seen from the rest of the element): positive for a correctly ordered element.
double CornerVolume(const std::vector<Point3>& p, int nodeCount)
{
  const int third = nodeCount == 8 ? 3 : 2; // hex: 0-1-3 spans the bottom face
  const int top = nodeCount == 4 ? 3 : (nodeCount == 6 ? 3 : 4);
  return (p[1] - p[0]).cross(p[third] - p[0]).dot(p[top] - p[0]);
}

} // namespace

TEST(FEMeshIO, AbaqusIdsTypesAndSets)
{
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  const FEMesh mesh = MakeTestMesh();
  WriteFEMesh(mesh, (dir / "mesh.inp").string());
  const std::string text = mmrep::testing::ReadText(dir / "mesh.inp");
  // Nodes: 1-based, coordinates read back exactly.
  std::size_t nodes = 0;
  bool inNodes = false;
  std::map<std::string, std::vector<std::vector<long>>> elements; // TYPE -> rows
  std::string type;
  for (const auto& line : Lines(text))
  {
    if (line.rfind("**", 0) == 0)
      continue;
    if (line.rfind("*", 0) == 0)
    {
      inNodes = line.rfind("*NODE", 0) == 0;
      std::smatch m;
      type = std::regex_search(line, m, std::regex("^\\*ELEMENT, TYPE=([A-Z0-9]+)")) ? std::string(m[1]) : "";
      continue;
    }
    if (inNodes)
    {
      std::istringstream in(line);
      long id;
      char comma;
      double x, y, z;
      in >> id >> comma >> x >> comma >> y >> comma >> z;
      ASSERT_EQ(id, static_cast<long>(nodes + 1));
      EXPECT_TRUE(mmrep::testing::SameBits(mesh.nodes[nodes], Point3(x, y, z))) << line;
      ++nodes;
    }
    else if (!type.empty())
      elements[type].push_back(Numbers(line));
  }
  EXPECT_EQ(nodes, mesh.nodes.size());
  EXPECT_EQ(elements["C3D8"].size(), 6u);
  EXPECT_EQ(elements["C3D6"].size(), 1u);
  EXPECT_EQ(elements["C3D4"].size(), 1u);
  EXPECT_EQ(elements["T3D2"].size(), 3u);
  // Element id = index + 1; hexahedra, tetrahedra and cables keep VTK order, the wedge is mirrored.
  for (const auto& [abaqusType, rows] : elements)
    for (const auto& row : rows)
    {
      const auto& e = mesh.elements.at(static_cast<std::size_t>(row[0] - 1));
      ASSERT_EQ(static_cast<int>(row.size()), NodeCount(e.type) + 1);
      const int wedgeOrder[6] = {0, 2, 1, 3, 5, 4};
      for (int k = 0; k < NodeCount(e.type); ++k)
        EXPECT_EQ(row[k + 1], e.nodes[e.type == ElementType::Wedge ? wedgeOrder[k] : k] + 1) << abaqusType;
    }
  // Sets under their sanitized names, 1-based.
  auto nsets = InpSets(text, "*NSET");
  auto elsets = InpSets(text, "*ELSET");
  EXPECT_EQ(nsets["SKIN"], PlusOne(mesh.nodeSets.at("skin")));
  EXPECT_EQ(nsets["LIPS__UPPER_"], PlusOne(mesh.nodeSets.at("lips (upper)")));
  EXPECT_EQ(nsets.count("EMPTY"), 0u); // empty sets cannot be written
  EXPECT_EQ(nsets["MUSCLE_ORBICULARIS_ORIS"], PlusOne(mesh.muscles.at("orbicularis oris").nodes));
  EXPECT_EQ(elsets["MUSCLE_LEVATOR_LABII_50_"], PlusOne(mesh.muscles.at("levator.labii 50%").cables));
  EXPECT_EQ(elsets["ORBICULARIS_ORIS"], PlusOne(mesh.elementSets.at("orbicularis oris")));
  EXPECT_EQ(elsets["MIXED__"], (std::vector<long>{8, 10, 1}));
  EXPECT_EQ(elsets["LAYER_EPIDERMIS"], (std::vector<long>{5, 6, 7}));
  EXPECT_EQ(elsets["LAYER_DERMIS"], (std::vector<long>{3, 4}));
  EXPECT_EQ(elsets["LAYER_HYPODERMIS"], (std::vector<long>{1, 2, 8}));
  EXPECT_EQ(elsets["EPIDERMIS"], (std::vector<long>{5, 6, 7}));
}

TEST(FEMeshIO, NamesAreSanitizedAndUnique)
{
  FEMesh mesh = MakeTestMesh();
  mesh.nodeSets["A b"] = {1};
  mesh.nodeSets["a_b"] = {2};
  mesh.nodeSets["9lives"] = {3};
  mesh.nodeSets["NALL"] = {4}; // reserved for all nodes
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  WriteFEMesh(mesh, (dir / "mesh.inp").string());
  auto nsets = InpSets(mmrep::testing::ReadText(dir / "mesh.inp"), "*NSET");
  EXPECT_EQ(nsets["A_B"], (std::vector<long>{2}));   // "A b" sorts first and keeps the name
  EXPECT_EQ(nsets["A_B_2"], (std::vector<long>{3})); // "a_b" collides case-insensitively
  EXPECT_EQ(nsets["SET_9LIVES"], (std::vector<long>{4}));
  EXPECT_EQ(nsets["NALL_2"], (std::vector<long>{5}));
  EXPECT_NE(mmrep::testing::ReadText(dir / "mesh.inp").find("*NODE, NSET=NALL\n"), std::string::npos);
}

TEST(FEMeshIO, CalculiXSolvesTheAbaqusDeck)
{
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  const FEMesh mesh = MakeTestMesh();
  const auto result = RunCalculiX(mesh, dir);
  const std::string log = result.out + result.err;
  ASSERT_EQ(result.status, 0) << log;
  EXPECT_EQ(log.find("ERROR"), std::string::npos) << log;
  EXPECT_EQ(log.find("jacobian"), std::string::npos) << log;
  EXPECT_NE(log.find("Job finished"), std::string::npos) << log;
  // The displacement table lists every node; the free hex nodes between clamped skull (z = 0) and
  // pulled skin (z = 0.1) move upward by a fraction of the pull.
  std::map<long, Point3> u;
  bool inTable = false;
  for (const auto& line : Lines(mmrep::testing::ReadText(dir / "job.dat")))
  {
    if (line.find("displacements") != std::string::npos)
      inTable = true;
    std::istringstream in(line);
    long id;
    double x, y, z;
    if (inTable && in >> id >> x >> y >> z)
      u[id] = Point3(x, y, z);
  }
  ASSERT_EQ(u.size(), mesh.nodes.size());
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_NEAR(u[mmrep::testing::GridNode(i, j, 0) + 1].z(), 0.0, 1e-12);
      EXPECT_NEAR(u[mmrep::testing::GridNode(i, j, 3) + 1].z(), 0.1, 1e-12);
      for (int k : {1, 2})
      {
        const double z = u[mmrep::testing::GridNode(i, j, k) + 1].z();
        EXPECT_GT(z, 0.0);
        EXPECT_LT(z, 0.1);
      }
    }
}

TEST(FEMeshIO, CalculiXDetectsAWrongWedgeOrder)
{
  // Negative control: a wedge written in VTK's own order (i.e. not converted) must be refused by
  // CalculiX, which proves the previous test would notice a wrong conversion.
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  FEMesh mesh = MakeTestMesh();
  auto& wedge = mesh.elements[6];
  ASSERT_EQ(wedge.type, ElementType::Wedge);
  std::swap(wedge.nodes[1], wedge.nodes[2]); // the writer swaps them back: VTK order in the deck
  std::swap(wedge.nodes[4], wedge.nodes[5]);
  const auto result = RunCalculiX(mesh, dir);
  const std::string log = result.out + result.err;
  EXPECT_NE(log.find("nonpositive jacobian"), std::string::npos) << log;
}

TEST(FEMeshIO, GmshLoadsTheMeshWithItsGroups)
{
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  const FEMesh mesh = MakeTestMesh();
  const auto msh = dir / "mesh.msh";
  WriteFEMesh(mesh, msh.string());
  const std::string head = mmrep::testing::ReadText(msh).substr(0, 30);
  EXPECT_EQ(head.rfind("$MeshFormat\n4.1 0 8\n", 0), 0u) << head;

  // 1. gmsh -check parses the file and reports the element count (solids, cables and one point
  //    element per node-set node: the 15 distinct nodes of skin, skull and lips).
  auto check = mmrep::testing::Run("gmsh -check '" + msh.string() + "'", dir);
  ASSERT_EQ(check.status, 0) << check.out << check.err;
  EXPECT_EQ((check.out + check.err).find("Error"), std::string::npos) << check.out << check.err;
  std::set<std::int32_t> setNodes;
  for (const auto& [name, ids] : mesh.nodeSets)
    setNodes.insert(ids.begin(), ids.end());
  std::smatch m;
  const std::string report = check.out + check.err;
  ASSERT_TRUE(std::regex_search(report, m, std::regex("Info +: ([0-9]+) nodes\n"))) << report;
  EXPECT_EQ(std::stoul(m[1]), mesh.nodes.size());
  ASSERT_TRUE(std::regex_search(report, m, std::regex("Info +: ([0-9]+) elements\n"))) << report;
  EXPECT_EQ(std::stoul(m[1]), mesh.elements.size() + setNodes.size());

  // 2. Gmsh's own conversion to VTK gives back our cells, each valid (correctly oriented) in VTK.
  const auto vtk = dir / "gmsh.vtk";
  auto convert = mmrep::testing::Run("gmsh '" + msh.string() + "' -0 -format vtk -o '" + vtk.string() + "'", dir);
  ASSERT_EQ(convert.status, 0) << convert.out << convert.err;
  vtkNew<vtkUnstructuredGridReader> reader;
  reader->SetFileName(vtk.string().c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  std::map<int, int> counts;
  // Cells as their corner coordinates in micrometres (Gmsh's VTK export rounds the last digits).
  std::multiset<std::vector<long long>> gmshCells, ourCells;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    ++counts[grid->GetCellType(c)];
    if (grid->GetCellType(c) == VTK_VERTEX)
      continue;
    std::vector<long long> corners;
    vtkNew<vtkIdList> ids;
    grid->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      for (int d = 0; d < 3; ++d)
        corners.push_back(std::llround(grid->GetPoint(ids->GetId(k))[d] * 1e3));
    gmshCells.insert(corners);
  }
  for (const auto& e : mesh.elements)
  {
    std::vector<long long> corners;
    for (int k = 0; k < NodeCount(e.type); ++k)
      for (int d = 0; d < 3; ++d)
        corners.push_back(std::llround(mesh.nodes[e.nodes[k]][d] * 1e3));
    ourCells.insert(corners);
  }
  EXPECT_EQ(counts[VTK_HEXAHEDRON], 6);
  EXPECT_EQ(counts[VTK_WEDGE], 1);
  EXPECT_EQ(counts[VTK_TETRA], 1);
  EXPECT_EQ(counts[VTK_LINE], 3);
  EXPECT_EQ(counts[VTK_VERTEX], static_cast<int>(setNodes.size()));
  EXPECT_EQ(gmshCells, ourCells); // same corners in the same (VTK) order
  vtkNew<vtkCellValidator> validator;
  validator->SetInputData(grid);
  validator->Update();
  auto* state = validator->GetOutput()->GetCellData()->GetArray("ValidityState");
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    EXPECT_EQ(state->GetTuple1(c), 0) << "gmsh cell " << c << " type " << grid->GetCellType(c);

  // 3. Physical groups as Gmsh understands them: in MSH 2 every element is listed once per group.
  const auto msh2 = dir / "gmsh2.msh";
  auto save2 = mmrep::testing::Run("gmsh '" + msh.string() + "' -0 -format msh2 -o '" + msh2.string() + "'", dir);
  ASSERT_EQ(save2.status, 0) << save2.out << save2.err;
  std::map<long, std::string> groupNames;
  std::map<std::string, std::multiset<long>> members; // group name -> element ids (or node ids for points)
  std::map<std::vector<long>, long> elementByNodes;
  for (std::size_t i = 0; i < mesh.elements.size(); ++i)
  {
    std::vector<long> nodes;
    for (int k = 0; k < NodeCount(mesh.elements[i].type); ++k)
      nodes.push_back(mesh.elements[i].nodes[k] + 1);
    std::sort(nodes.begin(), nodes.end());
    elementByNodes[nodes] = static_cast<long>(i);
  }
  const auto lines = Lines(mmrep::testing::ReadText(msh2));
  std::string section;
  for (const auto& line : lines)
  {
    if (!line.empty() && line[0] == '$')
    {
      section = line;
      continue;
    }
    if (section == "$PhysicalNames")
    {
      std::smatch g;
      if (std::regex_search(line, g, std::regex("^[0-9]+ ([0-9]+) \"(.*)\"")))
        groupNames[std::stol(g[1])] = g[2];
    }
    else if (section == "$Elements")
    {
      const auto v = Numbers(line);
      if (v.size() < 4)
        continue;
      // Gmsh renumbers elements: identify ours by their (sorted, 1-based) node ids.
      const long type = v[1], ntags = v[2], physical = v[3];
      std::vector<long> nodes(v.begin() + 3 + ntags, v.end());
      std::sort(nodes.begin(), nodes.end());
      members[groupNames[physical]].insert(type == 15 ? nodes[0] - 1 : elementByNodes.at(nodes));
    }
  }
  auto asSet = [](const std::vector<std::int32_t>& ids) { return std::multiset<long>(ids.begin(), ids.end()); };
  EXPECT_EQ(members["skin"], asSet(mesh.nodeSets.at("skin")));
  EXPECT_EQ(members["lips__upper_"], asSet(mesh.nodeSets.at("lips (upper)")));
  EXPECT_EQ(members["layer_epidermis"], asSet(mesh.elementSets.at("epidermis")));
  EXPECT_EQ(members["layer_hypodermis"], asSet(mesh.elementSets.at("hypodermis")));
  EXPECT_EQ(members["muscle_orbicularis_oris"], asSet(mesh.muscles.at("orbicularis oris").cables));
  EXPECT_EQ(members["muscle_levator_labii_50_"], asSet(mesh.muscles.at("levator.labii 50%").cables));
  EXPECT_EQ(members["mixed__"], asSet(mesh.elementSets.at("mixed\xC3\xA9"))); // solid and cable parts
}

TEST(FEMeshIO, FEBioFileParsesWithMatchingCountsAndOrientation)
{
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  const FEMesh mesh = MakeTestMesh();
  const auto feb = (dir / "mesh.feb").string();
  WriteFEMesh(mesh, feb);
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(vtkXMLUtilities::ReadElementFromFile(feb.c_str()));
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->GetName(), "febio_spec");
  EXPECT_STREQ(root->GetAttribute("version"), "3.0");
  vtkXMLDataElement* meshElement = root->FindNestedElementWithName("Mesh");
  ASSERT_NE(meshElement, nullptr);

  std::vector<Point3> nodes;
  std::map<std::string, int> typeCounts;
  std::map<std::string, std::vector<long>> parts, nodeSets, elementSets;
  std::set<long> elementIds;
  for (int c = 0; c < meshElement->GetNumberOfNestedElements(); ++c)
  {
    vtkXMLDataElement* child = meshElement->GetNestedElement(c);
    const std::string tag = child->GetName();
    const std::string name = child->GetAttribute("name") ? child->GetAttribute("name") : "";
    for (int k = 0; k < child->GetNumberOfNestedElements(); ++k)
    {
      vtkXMLDataElement* item = child->GetNestedElement(k);
      const long id = std::stol(item->GetAttribute("id"));
      if (tag == "Nodes")
      {
        std::string text = item->GetCharacterData();
        for (auto& ch : text)
          if (ch == ',')
            ch = ' ';
        std::istringstream in(text);
        Point3 p;
        in >> p.x() >> p.y() >> p.z();
        EXPECT_EQ(id, static_cast<long>(nodes.size() + 1));
        nodes.push_back(p);
      }
      else if (tag == "Elements")
      {
        const std::string type = child->GetAttribute("type");
        ++typeCounts[type];
        EXPECT_TRUE(elementIds.insert(id).second) << "duplicate element id " << id;
        parts[name].push_back(id);
        const auto conn = Numbers(item->GetCharacterData());
        std::vector<Point3> p;
        for (auto n : conn)
          p.push_back(nodes.at(static_cast<std::size_t>(n - 1)));
        if (type != "line2")
          EXPECT_GT(CornerVolume(p, static_cast<int>(p.size())), 0.0) << type << " element " << id;
      }
      else if (tag == "NodeSet")
        nodeSets[name].push_back(id);
      else if (tag == "ElementSet")
        elementSets[name].push_back(id);
    }
  }
  ASSERT_EQ(nodes.size(), mesh.nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i)
    EXPECT_TRUE(mmrep::testing::SameBits(nodes[i], mesh.nodes[i])) << i;
  EXPECT_EQ(typeCounts["hex8"], 6);
  EXPECT_EQ(typeCounts["penta6"], 1);
  EXPECT_EQ(typeCounts["tet4"], 1);
  EXPECT_EQ(typeCounts["line2"], 3);
  EXPECT_EQ(elementIds.size(), mesh.elements.size());
  EXPECT_EQ(parts["layer_epidermis_hex8"], (std::vector<long>{5, 6}));
  EXPECT_EQ(parts["layer_epidermis_penta6"], (std::vector<long>{7}));
  EXPECT_EQ(parts["layer_hypodermis_tet4"], (std::vector<long>{8}));
  EXPECT_EQ(parts["ECABLE"], (std::vector<long>{9, 10, 11}));
  EXPECT_EQ(nodeSets["skin"], PlusOne(mesh.nodeSets.at("skin")));
  EXPECT_EQ(nodeSets["muscle_orbicularis_oris"], PlusOne(mesh.muscles.at("orbicularis oris").nodes));
  EXPECT_EQ(elementSets["mixed__"], PlusOne(mesh.elementSets.at("mixed\xC3\xA9")));
  EXPECT_EQ(elementSets["layer_dermis"], PlusOne(mesh.elementSets.at("dermis")));
  EXPECT_EQ(elementSets["muscle_levator_labii_50_"], PlusOne(mesh.muscles.at("levator.labii 50%").cables));
  // The same check on a deliberately mis-ordered wedge fails, so the orientation test has teeth.
  FEMesh flipped = mesh;
  std::swap(flipped.elements[6].nodes[1], flipped.elements[6].nodes[2]);
  std::swap(flipped.elements[6].nodes[4], flipped.elements[6].nodes[5]);
  std::vector<Point3> p;
  for (auto n : {0, 2, 1, 3, 5, 4})
    p.push_back(flipped.nodes[flipped.elements[6].nodes[n]]);
  EXPECT_LT(CornerVolume(p, 6), 0.0);
}
