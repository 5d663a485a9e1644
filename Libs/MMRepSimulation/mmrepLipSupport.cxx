// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The lip-support nodes (see the header).
#include "mmrepLipSupport.h"

#include "mmrepBoundaryFaces.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <map>

namespace mmrep::simulation
{

std::map<std::int32_t, Point3> SurfaceNodeNormals(const FEMesh& mesh, const std::string& nodeSet)
{
  std::map<std::int32_t, Point3> normals;
  if (!mesh.nodeSets.count(nodeSet))
    return normals;
  const std::vector<char> mask = NodeSetMask(mesh, nodeSet);
  for (const BoundaryFace& face : BoundaryFaces(mesh, &mask))
  {
    if (mesh.elements[static_cast<std::size_t>(face.element)].type != ElementType::Hexahedron)
      continue;
    const auto& id = face.nodes;
    const Point3 a = mesh.nodes[static_cast<std::size_t>(id[2])] - mesh.nodes[static_cast<std::size_t>(id[0])];
    const Point3 b = mesh.nodes[static_cast<std::size_t>(id[3])] - mesh.nodes[static_cast<std::size_t>(id[1])];
    const Point3 n = 0.5 * a.cross(b); // area-weighted
    for (auto v : id)
    {
      auto [it, fresh] = normals.emplace(v, Point3::Zero());
      // Orientation is irrelevant for n·u = 0; keep the accumulated normals consistent.
      it->second += (it->second.dot(n) < 0 ? -n : n);
    }
  }
  for (auto it = normals.begin(); it != normals.end();)
    if (it->second.norm() > 0)
    {
      it->second.normalize();
      ++it;
    }
    else
      it = normals.erase(it);
  return normals;
}

std::vector<SlidingNode> LipSupportNodes(const FEMesh& mesh, double margin)
{
  const auto inner = mesh.nodeSets.find("inner");
  const auto lips = mesh.nodeSets.find("lips");
  if (inner == mesh.nodeSets.end() || lips == mesh.nodeSets.end() || lips->second.empty())
    return {};
  double xmin = 1e300, xmax = -1e300, zmin = 1e300, zmax = -1e300;
  for (auto n : lips->second)
  {
    const Point3& p = mesh.nodes[static_cast<std::size_t>(n)];
    xmin = std::min(xmin, p.x());
    xmax = std::max(xmax, p.x());
    zmin = std::min(zmin, p.z());
    zmax = std::max(zmax, p.z());
  }
  const auto normals = SurfaceNodeNormals(mesh, "inner");
  std::vector<SlidingNode> out;
  for (const auto& [node, n] : normals)
  {
    const Point3& p = mesh.nodes[static_cast<std::size_t>(node)];
    if (p.x() < xmin - margin || p.x() > xmax + margin || p.z() < zmin - margin || p.z() > zmax + margin)
      continue;
    out.push_back({node, n});
  }
  return out;
}

} // namespace mmrep::simulation
