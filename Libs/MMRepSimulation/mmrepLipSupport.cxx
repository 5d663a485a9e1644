// The lip-support nodes (see the header).
#include "mmrepLipSupport.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <map>

namespace mmrep::simulation
{

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
  std::vector<char> isInner(mesh.nodes.size(), 0);
  for (auto n : inner->second)
    isInner[static_cast<std::size_t>(n)] = 1;
  // Boundary quads of the hexahedra whose four nodes are inner nodes: the inner surface.
  static const int faces[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  std::map<std::array<std::int32_t, 4>, std::pair<int, std::array<std::int32_t, 4>>> quads;
  for (const auto& e : mesh.elements)
  {
    if (e.type != ElementType::Hexahedron)
      continue;
    for (const auto& f : faces)
    {
      std::array<std::int32_t, 4> ids{e.nodes[static_cast<std::size_t>(f[0])], e.nodes[static_cast<std::size_t>(f[1])],
                                      e.nodes[static_cast<std::size_t>(f[2])], e.nodes[static_cast<std::size_t>(f[3])]};
      auto key = ids;
      std::sort(key.begin(), key.end());
      auto& q = quads[key];
      ++q.first;
      q.second = ids;
    }
  }
  std::map<std::int32_t, Point3> normals;
  for (const auto& [key, q] : quads)
  {
    if (q.first != 1 || !std::all_of(key.begin(), key.end(), [&](std::int32_t n) { return isInner[static_cast<std::size_t>(n)] != 0; }))
      continue;
    const auto& id = q.second;
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
  std::vector<SlidingNode> out;
  for (const auto& [node, n] : normals)
  {
    const Point3& p = mesh.nodes[static_cast<std::size_t>(node)];
    if (p.x() < xmin - margin || p.x() > xmax + margin || p.z() < zmin - margin || p.z() > zmax + margin || !(n.norm() > 0))
      continue;
    out.push_back({node, n.normalized()});
  }
  return out;
}

} // namespace mmrep::simulation
