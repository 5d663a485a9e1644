// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Marching Cubes case table, derived at first use from the cube geometry rather than typed in, so that
// every rule it follows is visible here:
//  - a corner is "inside" when its value is >= the iso-value (VTK's convention);
//  - a face with two diagonal inside corners (ambiguous face) is always cut so that the inside corners are
//    separated. The rule depends only on the face's own four corners, so the two cubes sharing a face cut it
//    identically and the surface has no holes;
//  - the contour segments on the six faces are chained into closed loops, each loop becomes a triangle fan, and
//    loops are oriented so that triangle normals (right-hand rule) point from inside to outside, i.e. towards
//    decreasing values.
#ifndef itkMarchingCubesTables_h
#define itkMarchingCubesTables_h

#include <array>
#include <cstdint>

namespace itk
{
namespace MarchingCubesTables
{
// Cube corner v sits at (v & 1, (v >> 1) & 1, (v >> 2) & 1): bit v of a case code is corner v's class.
// Edges 0-3 run along x, 4-7 along y, 8-11 along z; each goes from its lower corner to its upper corner.
constexpr std::array<std::array<std::uint8_t, 2>, 12> EdgeCorners{{{{0, 1}},
                                                                   {{2, 3}},
                                                                   {{4, 5}},
                                                                   {{6, 7}},
                                                                   {{0, 2}},
                                                                   {{1, 3}},
                                                                   {{4, 6}},
                                                                   {{5, 7}},
                                                                   {{0, 4}},
                                                                   {{1, 5}},
                                                                   {{2, 6}},
                                                                   {{3, 7}}}};

// Up to 12 intersected edges, each loop of n edges gives n - 2 triangles: at most 10 triangles.
constexpr unsigned int MaximumNumberOfTriangles = 10;

struct Case
{
  std::uint8_t NumberOfTriangles = 0;
  std::uint16_t IntersectedEdges = 0;                             // bit e set: edge e is cut
  std::array<std::uint8_t, 3 * MaximumNumberOfTriangles> Edges{}; // 3 edge numbers per triangle
};

namespace Detail
{
inline int EdgeBetween(int a, int b)
{
  for (int e = 0; e < 12; ++e)
  {
    if ((EdgeCorners[e][0] == a && EdgeCorners[e][1] == b) || (EdgeCorners[e][0] == b && EdgeCorners[e][1] == a))
    {
      return e;
    }
  }
  return -1;
}

inline std::array<double, 3> Corner(int v)
{
  return {double(v & 1), double((v >> 1) & 1), double((v >> 2) & 1)};
}

inline std::array<double, 3> EdgeMidpoint(int e)
{
  const auto a = Corner(EdgeCorners[e][0]);
  const auto b = Corner(EdgeCorners[e][1]);
  return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
}

// True when edges a and b lie on a common cube face.
inline bool ShareFace(int a, int b)
{
  const auto pa = EdgeMidpoint(a);
  const auto pb = EdgeMidpoint(b);
  for (int d = 0; d < 3; ++d)
  {
    if ((pa[d] == 0.0 || pa[d] == 1.0) && pa[d] == pb[d])
    {
      return true;
    }
  }
  return false;
}

inline Case MakeCase(unsigned int code)
{
  const auto inside = [code](int v) { return ((code >> v) & 1U) != 0; };
  Case c;
  for (int e = 0; e < 12; ++e)
  {
    if (inside(EdgeCorners[e][0]) != inside(EdgeCorners[e][1]))
    {
      c.IntersectedEdges = static_cast<std::uint16_t>(c.IntersectedEdges | (1U << e));
    }
  }
  // next[e]: the edge that follows e along its loop (segment e -> next[e] on some face).
  std::array<int, 12> next;
  next.fill(-1);
  for (int axis = 0; axis < 3; ++axis)
  {
    const int u = (axis + 1) % 3;
    const int w = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side)
    {
      // Face corners in cyclic order.
      std::array<int, 4> q;
      const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int n = 0; n < 4; ++n)
      {
        q[n] = (side << axis) | (uv[n][0] << u) | (uv[n][1] << w);
      }
      std::array<int, 4> fe; // fe[n] joins q[n] and q[n+1]
      for (int n = 0; n < 4; ++n)
      {
        fe[n] = EdgeBetween(q[n], q[(n + 1) % 4]);
      }
      // Pair the cut edges of this face into segments.
      std::array<std::array<int, 2>, 2> seg;
      int numSeg = 0;
      std::array<int, 4> cut;
      int numCut = 0;
      for (int n = 0; n < 4; ++n)
      {
        if ((c.IntersectedEdges >> fe[n]) & 1U)
        {
          cut[numCut++] = n;
        }
      }
      if (numCut == 2)
      {
        seg[numSeg++] = {fe[cut[0]], fe[cut[1]]};
      }
      else if (numCut == 4)
      {
        // Ambiguous face: cut off each inside corner on its own (edges n-1 and n meet at corner q[n]).
        for (int n = 0; n < 4; ++n)
        {
          if (inside(q[n]))
          {
            seg[numSeg++] = {fe[(n + 3) % 4], fe[n]};
          }
        }
      }
      // Orient each segment A -> B so that (faceNormal x (B - A)) points towards the outside side of the face.
      std::array<double, 3> normal{0.0, 0.0, 0.0};
      normal[axis] = side ? 1.0 : -1.0;
      for (int s = 0; s < numSeg; ++s)
      {
        int a = seg[s][0];
        int b = seg[s][1];
        const auto pa = EdgeMidpoint(a);
        const auto pb = EdgeMidpoint(b);
        const auto cin = Corner(inside(EdgeCorners[a][0]) ? EdgeCorners[a][0] : EdgeCorners[a][1]);
        const std::array<double, 3> d{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
        const std::array<double, 3> nxd{normal[1] * d[2] - normal[2] * d[1], normal[2] * d[0] - normal[0] * d[2],
                                        normal[0] * d[1] - normal[1] * d[0]};
        const double side_ = nxd[0] * (cin[0] - pa[0]) + nxd[1] * (cin[1] - pa[1]) + nxd[2] * (cin[2] - pa[2]);
        if (side_ > 0.0)
        {
          const int t = a;
          a = b;
          b = t;
        }
        next[a] = b;
      }
    }
  }
  // Chain the segments into loops and triangulate each loop as a fan. The fan apex is chosen so that no
  // diagonal joins two edges of one cube face: such a diagonal would be shared with the neighbouring cube.
  std::array<bool, 12> used{};
  unsigned int numTriangles = 0;
  for (int start = 0; start < 12; ++start)
  {
    if (!((c.IntersectedEdges >> start) & 1U) || used[start])
    {
      continue;
    }
    std::array<int, 12> loop;
    int n = 0;
    for (int e = start; !used[e]; e = next[e])
    {
      used[e] = true;
      loop[n++] = e;
    }
    int bestApex = 0;
    int bestBad = 1 << 30;
    for (int apex = 0; apex < n; ++apex)
    {
      int bad = 0;
      for (int k = 2; k < n - 1; ++k)
      {
        bad += ShareFace(loop[apex], loop[(apex + k) % n]) ? 1 : 0;
      }
      if (bad < bestBad)
      {
        bestBad = bad;
        bestApex = apex;
      }
    }
    for (int k = 1; k + 1 < n; ++k)
    {
      c.Edges[3 * numTriangles + 0] = static_cast<std::uint8_t>(loop[bestApex]);
      c.Edges[3 * numTriangles + 1] = static_cast<std::uint8_t>(loop[(bestApex + k) % n]);
      c.Edges[3 * numTriangles + 2] = static_cast<std::uint8_t>(loop[(bestApex + k + 1) % n]);
      ++numTriangles;
    }
  }
  c.NumberOfTriangles = static_cast<std::uint8_t>(numTriangles);
  return c;
}
} // namespace Detail

// The 256 cases, built once (thread-safe static initialisation).
inline const std::array<Case, 256>& GetCases()
{
  static const std::array<Case, 256> cases = [] {
    std::array<Case, 256> t;
    for (unsigned int code = 0; code < 256; ++code)
    {
      t[code] = Detail::MakeCase(code);
    }
    return t;
  }();
  return cases;
}
} // namespace MarchingCubesTables
} // namespace itk

#endif
