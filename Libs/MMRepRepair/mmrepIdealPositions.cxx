// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepIdealPositions.h"

#include <Eigen/Geometry>

#include <cmath>

namespace mmrep
{
namespace
{
// Hex corner (r,s,t) bits of VTK's node order, for the trilinear "ideal corner" position.
constexpr int kHexBits[8] = {0b000, 0b001, 0b011, 0b010, 0b100, 0b101, 0b111, 0b110}; // bit0=r, bit1=s, bit2=t
int HexNodeOfBits(int bits)
{
  for (int i = 0; i < 8; ++i)
    if (kHexBits[i] == bits)
      return i;
  return -1;
}
} // namespace

std::pair<Point3, Point3> IdealPositions(const FEMesh& mesh, const NodeElements& adjacency, std::size_t node,
                                         std::vector<Point3>& each)
{
  each.clear();
  Point3 ideal = Point3::Zero(), centroids = Point3::Zero();
  int idealCount = 0, count = 0;
  const auto P = [&](const Element& e, int k) -> const Point3& { return mesh.nodes[e.nodes[k]]; };
  for (std::size_t k = adjacency.offsets[node]; k < adjacency.offsets[node + 1]; ++k)
  {
    const Element& e = mesh.elements[adjacency.adjacent[k]];
    const int n = NodeCount(e.type);
    Point3 centroid = Point3::Zero();
    int local = -1;
    for (int i = 0; i < n; ++i)
    {
      centroid += P(e, i);
      if (static_cast<std::size_t>(e.nodes[i]) == node)
        local = i;
    }
    centroids += centroid / n;
    ++count;
    if (e.type == ElementType::Hexahedron)
    {
      // Trilinear map without twist: x_c = sum over the 7 other corners of (-1)^(flips+1) x.
      Point3 x = Point3::Zero();
      for (int flip = 1; flip < 8; ++flip)
      {
        const int flips = __builtin_popcount(flip);
        x += (flips % 2 == 1 ? 1.0 : -1.0) * P(e, HexNodeOfBits(kHexBits[local] ^ flip));
      }
      ideal += x;
      each.push_back(x);
      ++idealCount;
    }
    else if (e.type == ElementType::Wedge)
    {
      // Straight prism: same offset to the other triangle as the mean of the two other edges.
      const int other = local < 3 ? local + 3 : local - 3;
      const int base = local < 3 ? 0 : 3, otherBase = 3 - base;
      Point3 offset = Point3::Zero();
      for (int i = 0; i < 3; ++i)
        if (base + i != local)
          offset += P(e, base + i) - P(e, otherBase + i);
      ideal += P(e, other) + offset / 2;
      each.push_back(P(e, other) + offset / 2);
      ++idealCount;
    }
    else if (e.type == ElementType::Tetrahedron)
    {
      // Regular-tet apex over the opposite face, on the side that gives a positive volume.
      int face[3], f = 0;
      for (int i = 0; i < 4; ++i)
        if (i != local)
          face[f++] = i;
      const Point3 a = P(e, face[0]), b = P(e, face[1]), c = P(e, face[2]);
      Point3 normal = (b - a).cross(c - a);
      const double area2 = normal.norm();
      if (area2 > 0)
      {
        const double edge = ((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3;
        normal /= area2;
        // In a valid VTK tet the faces (0,2,3) and (0,1,2) opposite nodes 1 and 3 face their node,
        // while (1,2,3) and (0,1,3) opposite nodes 0 and 2 face away.
        const double sign = (local == 1 || local == 3) ? 1.0 : -1.0;
        each.push_back((a + b + c) / 3 + sign * std::sqrt(2.0 / 3.0) * edge * normal);
        ideal += each.back();
        ++idealCount;
      }
    }
  }
  const Point3 p = mesh.nodes[node];
  return {idealCount > 0 ? Point3(ideal / idealCount) : p, count > 0 ? Point3(centroids / count) : p};
}

} // namespace mmrep
