// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Gmsh mesh (.msh 4.1 ASCII). Gmsh attaches physical groups to model entities, not to elements, so
// elements are grouped into one entity per distinct membership: a volume per (layer, element sets)
// combination of solids, a curve per (muscles, element sets) combination of cables, and a point
// entity per combination of node sets holding point elements (type 15) for those nodes.
// Physical groups: dim 3 "layer_<layer>" and element sets (solid part), dim 1 "muscle_<name>" and
// element sets (cable part), dim 0 node sets, dim 2 the lips' facing surfaces (quadrangles, tags
// after the elements'). Empty groups are omitted (Gmsh cannot store them).
// Node tag = node index + 1, element tag = element index + 1; point elements follow.
// The mouth slit's lower-lip twins are written a hair (1e-6 of the model's size) inside their own
// lip: Gmsh has no notion of distinct coincident nodes and flags every pair within 1e-8 of the
// model's size as a duplicate (gmsh -check), whatever entity or group holds them.
#include "mmrepFEExport.h"
#include "mmrepLipContact.h"

#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <map>

namespace mmrep::detail
{
namespace
{

int GmshType(ElementType type)
{
  switch (type)
  {
    case ElementType::Cable:
      return 1;
    case ElementType::Tetrahedron:
      return 4;
    case ElementType::Hexahedron:
      return 5;
    case ElementType::Wedge:
      return 6;
  }
  return 0;
}

struct PhysicalGroup
{
  int dim;
  int tag;
  std::string name;
};

struct Entity
{
  int dim = 0;
  int tag = 0;
  std::vector<int> physicals;
  std::vector<std::int32_t> members; // element indices (dim 1, 3) or node indices (dim 0)
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
};

// Node positions as written: the slit's lower-lip twins moved by `kSlitGap` of the model's bounding-box
// diagonal towards the centre of the lower-lip elements that use them (so no element turns over).
constexpr double kSlitGap = 1e-6;

std::vector<Eigen::Vector3d> WrittenPositions(const FEMesh& mesh)
{
  std::vector<Eigen::Vector3d> positions(mesh.nodes.begin(), mesh.nodes.end());
  const auto twins = MouthTwins(mesh);
  const auto lowerLip = mesh.elementSets.find(kLowerLipSet);
  if (twins.empty() || lowerLip == mesh.elementSets.end() || positions.empty())
    return positions;
  Eigen::Vector3d lo = positions.front(), hi = positions.front();
  for (const auto& p : positions)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double gap = kSlitGap * (hi - lo).norm();
  std::vector<Eigen::Vector3d> inward(mesh.nodes.size(), Eigen::Vector3d::Zero());
  std::vector<char> lowerTwin(mesh.nodes.size(), 0);
  for (const auto& pair : twins)
    lowerTwin[static_cast<std::size_t>(pair.second)] = 1;
  for (auto e : lowerLip->second)
  {
    const Element& element = mesh.elements[static_cast<std::size_t>(e)];
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    const int n = NodeCount(element.type);
    for (int k = 0; k < n; ++k)
      centre += mesh.nodes[static_cast<std::size_t>(element.nodes[k])];
    centre /= n;
    for (int k = 0; k < n; ++k)
    {
      const auto node = static_cast<std::size_t>(element.nodes[k]);
      if (lowerTwin[node])
        inward[node] += (centre - mesh.nodes[node]).normalized();
    }
  }
  for (const auto& pair : twins)
  {
    const auto node = static_cast<std::size_t>(pair.second);
    if (inward[node].norm() > 0)
      positions[node] += gap * inward[node].normalized();
  }
  return positions;
}

} // namespace

void WriteGmsh(const FEMesh& mesh, std::ostream& out)
{
  const ExportNames names = MakeExportNames(mesh);
  const std::size_t elementCount = mesh.elements.size();

  // Physical groups and, per element / node, the sorted list of groups it belongs to.
  std::vector<PhysicalGroup> groups;
  std::vector<std::vector<int>> elementGroups(elementCount), nodeGroups(mesh.nodes.size());
  auto addElementGroup = [&](const std::string& name, int dim, const std::vector<std::int32_t>& ids) {
    const int tag = static_cast<int>(groups.size()) + 1;
    bool used = false;
    for (auto id : ids)
      if ((mesh.elements[id].type == ElementType::Cable) == (dim == 1) &&
          (elementGroups[id].empty() || elementGroups[id].back() != tag))
      {
        elementGroups[id].push_back(tag);
        used = true;
      }
    if (used)
      groups.push_back({dim, tag, name});
  };
  std::size_t k = 0;
  for (const auto& entry : mesh.nodeSets)
  {
    const int tag = static_cast<int>(groups.size()) + 1;
    for (auto id : entry.second)
      if (nodeGroups[id].empty() || nodeGroups[id].back() != tag)
        nodeGroups[id].push_back(tag);
    if (!entry.second.empty())
      groups.push_back({0, tag, names.nodeSets[k]});
    ++k;
  }
  for (auto layer : {TissueLayer::None, TissueLayer::Epidermis, TissueLayer::Dermis, TissueLayer::Hypodermis})
  {
    std::vector<std::int32_t> ids;
    for (std::size_t i = 0; i < elementCount; ++i)
      if (mesh.elements[i].layer == layer)
        ids.push_back(static_cast<std::int32_t>(i));
    addElementGroup(names.layers[static_cast<int>(layer)], 3, ids);
  }
  k = 0;
  for (const auto& entry : mesh.muscles)
    addElementGroup(names.muscles[k++], 1, entry.second.cables);
  k = 0;
  for (const auto& entry : mesh.elementSets)
  {
    addElementGroup(names.elementSets[k], 3, entry.second);
    addElementGroup(names.elementSets[k], 1, entry.second);
    ++k;
  }
  // Sets list members in any order: membership lists must be sorted to identify entities.
  for (auto* lists : {&elementGroups, &nodeGroups})
    for (auto& list : *lists)
      std::sort(list.begin(), list.end());

  // One entity per (dimension, membership), numbered in order of first appearance.
  std::vector<Entity> entities;
  std::map<std::pair<int, std::vector<int>>, std::size_t> entityIndex;
  auto entityFor = [&](int dim, const std::vector<int>& physicals) -> Entity& {
    auto [it, inserted] = entityIndex.emplace(std::make_pair(dim, physicals), entities.size());
    if (inserted)
    {
      int tag = 1;
      for (const auto& e : entities)
        tag += e.dim == dim;
      entities.push_back({dim, tag, physicals, {}});
    }
    return entities[it->second];
  };
  for (std::size_t i = 0; i < elementCount; ++i)
  {
    const auto& element = mesh.elements[i];
    Entity& entity = entityFor(element.type == ElementType::Cable ? 1 : 3, elementGroups[i]);
    entity.members.push_back(static_cast<std::int32_t>(i));
    for (int n = 0; n < NodeCount(element.type); ++n)
    {
      entity.lo = entity.lo.cwiseMin(mesh.nodes[element.nodes[n]]);
      entity.hi = entity.hi.cwiseMax(mesh.nodes[element.nodes[n]]);
    }
  }
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    if (!nodeGroups[i].empty())
    {
      Entity& entity = entityFor(0, nodeGroups[i]);
      if (entity.members.empty())
        entity.lo = entity.hi = mesh.nodes[i];
      entity.members.push_back(static_cast<std::int32_t>(i));
    }
  // The lips' facing surfaces (mmrepLipContact.h): one surface entity and physical group each, of
  // quadrangles (type 3) numbered after the elements, so that a solver can pair them for contact.
  std::vector<LipContactFace> faces;
  for (const bool upper : {true, false})
  {
    const auto lip = LipContactFaces(mesh, upper);
    if (lip.empty())
      continue;
    const int tag = static_cast<int>(groups.size()) + 1;
    groups.push_back({2, tag, upper ? "upperLipContactFaces" : "lowerLipContactFaces"});
    Entity& entity = entityFor(2, {tag});
    for (const auto& f : lip)
    {
      entity.members.push_back(static_cast<std::int32_t>(faces.size()));
      faces.push_back(f);
      for (auto n : f.nodes)
      {
        entity.lo = entity.lo.cwiseMin(mesh.nodes[static_cast<std::size_t>(n)]);
        entity.hi = entity.hi.cwiseMax(mesh.nodes[static_cast<std::size_t>(n)]);
      }
    }
  }
  std::stable_sort(entities.begin(), entities.end(), [](const Entity& a, const Entity& b) { return a.dim < b.dim; });

  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  out << "$PhysicalNames\n" << groups.size() << "\n";
  for (const auto& g : groups)
    out << g.dim << " " << g.tag << " \"" << g.name << "\"\n";
  out << "$EndPhysicalNames\n";

  std::size_t counts[4] = {0, 0, 0, 0};
  for (const auto& e : entities)
    ++counts[e.dim];
  out << "$Entities\n" << counts[0] << " " << counts[1] << " " << counts[2] << " " << counts[3] << "\n";
  auto writePoint = [&](const Eigen::Vector3d& p) {
    out << FormatDouble(p.x()) << " " << FormatDouble(p.y()) << " " << FormatDouble(p.z());
  };
  for (const auto& e : entities)
  {
    out << e.tag << " ";
    writePoint(e.lo);
    if (e.dim > 0)
    {
      out << " ";
      writePoint(e.hi);
    }
    out << " " << e.physicals.size();
    for (int p : e.physicals)
      out << " " << p;
    out << (e.dim > 0 ? " 0\n" : "\n"); // no bounding entities: the model is a bare mesh
  }
  out << "$EndEntities\n";

  // All nodes in one block, classified on the first volume (or curve) entity.
  const Entity* host = nullptr;
  for (const auto& e : entities)
    if (e.dim > 0 && (!host || e.dim > host->dim))
      host = &e;
  const std::size_t nodeCount = mesh.nodes.size();
  out << "$Nodes\n1 " << nodeCount << " 1 " << nodeCount << "\n";
  out << host->dim << " " << host->tag << " 0 " << nodeCount << "\n";
  for (std::size_t i = 0; i < nodeCount; ++i)
    out << i + 1 << "\n";
  for (const auto& p : WrittenPositions(mesh))
  {
    writePoint(p);
    out << "\n";
  }
  out << "$EndNodes\n";

  // Element blocks: one per (entity, element type).
  struct Block
  {
    const Entity* entity;
    int type;
    std::vector<std::int32_t> members;
  };
  std::vector<Block> blocks;
  std::size_t total = 0;
  for (const auto& e : entities)
  {
    if (e.dim == 0 || e.dim == 2)
    {
      blocks.push_back({&e, e.dim == 0 ? 15 : 3, e.members});
      total += e.members.size();
      continue;
    }
    for (auto type : {ElementType::Hexahedron, ElementType::Wedge, ElementType::Tetrahedron, ElementType::Cable})
    {
      Block block{&e, GmshType(type), {}};
      for (auto i : e.members)
        if (mesh.elements[i].type == type)
          block.members.push_back(i);
      if (!block.members.empty())
      {
        total += block.members.size();
        blocks.push_back(std::move(block));
      }
    }
  }
  out << "$Elements\n" << blocks.size() << " " << total << " 1 " << total << "\n";
  std::size_t pointTag = elementCount + faces.size();
  for (const auto& block : blocks)
  {
    out << block.entity->dim << " " << block.entity->tag << " " << block.type << " " << block.members.size() << "\n";
    for (auto i : block.members)
    {
      if (block.type == 15)
      {
        out << ++pointTag << " " << i + 1 << "\n";
        continue;
      }
      if (block.type == 3)
      {
        const auto& f = faces[static_cast<std::size_t>(i)];
        out << elementCount + static_cast<std::size_t>(i) + 1;
        for (auto n : f.nodes)
          out << " " << n + 1;
        out << "\n";
        continue;
      }
      out << i + 1;
      for (auto node : SolverNodeOrder(mesh.elements[i]))
        out << " " << node + 1;
      out << "\n";
    }
  }
  out << "$EndElements\n";
}

} // namespace mmrep::detail
