// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The structured hexahedral grid of the face atlas: rows i along phi (bottom to top), columns j
// along theta (j = 0 on the symmetry plane, the left half only), levels k through the thickness
// (0 skin, 1 epidermis/dermis, 2 dermis/hypodermis, 3 inner surface). The right half is the
// mirror image; its column 0 is the left half's (shared nodes on the plane).
//
// Node and element numbering (deterministic): left nodes (i, j, k) in row-major order, then the
// right nodes of columns j >= 1; left elements (i, j, layer), then their mirrors.
// Left hexahedra list the outer face as (i,j) (i+1,j) (i+1,j+1) (i,j+1), then the inner face, so
// the VTK parametric axes are r = along phi, s = along theta, t = outer -> inner (positive volume
// in LPS: up x left points outwards there, and the local frame is left-handed). Mirrored hexahedra
// swap the middle corners to stay positively oriented: r = along theta, s = along phi.
#pragma once

#include "mmrepFEMesh.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <vector>

namespace mmrep
{

struct FaceGrid
{
  std::vector<double> theta;                        // column angles, theta[0] = 0 (radians)
  std::vector<double> phi;                          // row angles, increasing (radians)
  std::array<double, 4> levels{0, 0.15, 0.45, 1.0}; // fraction of the thickness of each level
  std::vector<Eigen::Vector3d> local;               // left-half node positions (local frame), LeftNode order

  int Rows() const { return static_cast<int>(phi.size()); }
  int Cols() const { return static_cast<int>(theta.size()); }
  int LeftNodeCount() const { return Rows() * Cols() * 4; }
  int LeftElementCount() const { return (Rows() - 1) * (Cols() - 1) * 3; }
  int LeftNode(int i, int j, int k) const { return (i * Cols() + j) * 4 + k; }
  // side 0: left, 1: right (mirror).
  int Node(int i, int j, int k, int side) const
  {
    if (side == 0 || j == 0)
      return LeftNode(i, j, k);
    return LeftNodeCount() + (i * (Cols() - 1) + (j - 1)) * 4 + k;
  }
  // The grid's mirror map (FEMesh::mirror): node (i, j, k) of one side <-> the other side's.
  std::vector<std::int32_t> MirrorMap() const
  {
    std::vector<std::int32_t> mirror(static_cast<std::size_t>(LeftNodeCount() + Rows() * (Cols() - 1) * 4));
    for (int i = 0; i < Rows(); ++i)
      for (int j = 0; j < Cols(); ++j)
        for (int k = 0; k < 4; ++k)
        {
          const int left = Node(i, j, k, 0), right = Node(i, j, k, 1);
          mirror[static_cast<std::size_t>(left)] = right;
          mirror[static_cast<std::size_t>(right)] = left;
        }
    return mirror;
  }
  int Element(int i, int j, int layer, int side) const
  {
    return side * LeftElementCount() + (i * (Cols() - 1) + j) * 3 + layer;
  }
  // Hexahedron (VTK order) of cell (i, j), layer 0..2, side 0/1.
  std::array<std::int32_t, 8> Hexahedron(int i, int j, int layer, int side) const
  {
    const int a[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
    const int order[2][4] = {{0, 1, 2, 3}, {0, 3, 2, 1}};
    std::array<std::int32_t, 8> h{};
    for (int c = 0; c < 4; ++c)
    {
      const auto& q = a[order[side][c]];
      h[c] = Node(q[0], q[1], layer, side);
      h[c + 4] = Node(q[0], q[1], layer + 1, side);
    }
    return h;
  }

  // The cell and parametric coordinates of the point at angles (|theta|, phi) and thickness
  // fraction `depth` (0 skin, 1 inner surface); side chosen by the caller.
  struct Location
  {
    int i = 0, j = 0, layer = 0;
    double fPhi = 0, fTheta = 0, fDepth = 0;
  };
  Location Locate(double th, double ph, double depth) const
  {
    Location l;
    auto find = [](const std::vector<double>& a, double x, int& idx, double& f) {
      x = std::clamp(x, a.front(), a.back());
      idx = static_cast<int>(std::upper_bound(a.begin(), a.end(), x) - a.begin()) - 1;
      idx = std::clamp(idx, 0, static_cast<int>(a.size()) - 2);
      f = (x - a[idx]) / (a[idx + 1] - a[idx]);
    };
    find(phi, ph, l.i, l.fPhi);
    find(theta, std::abs(th), l.j, l.fTheta);
    depth = std::clamp(depth, 0.0, 1.0);
    l.layer = depth < levels[1] ? 0 : depth < levels[2] ? 1 : 2;
    l.fDepth = (depth - levels[l.layer]) / (levels[l.layer + 1] - levels[l.layer]);
    return l;
  }
  // Embedding of a location in the left (side 0) or mirrored (side 1) element.
  Embedding Embed(const Location& l, int side) const
  {
    Embedding e;
    e.element = Element(l.i, l.j, l.layer, side);
    e.pcoords =
      side == 0 ? std::array<double, 3>{l.fPhi, l.fTheta, l.fDepth} : std::array<double, 3>{l.fTheta, l.fPhi, l.fDepth};
    return e;
  }
  // Left-half local position of a location: trilinear map of the left hexahedron (VTK shape functions).
  Eigen::Vector3d Position(const Location& l) const
  {
    const auto h = Hexahedron(l.i, l.j, l.layer, 0);
    const double r = l.fPhi, s = l.fTheta, t = l.fDepth;
    const double w[8] = {(1 - r) * (1 - s) * (1 - t), r * (1 - s) * (1 - t), r * s * (1 - t), (1 - r) * s * (1 - t),
                         (1 - r) * (1 - s) * t,       r * (1 - s) * t,       r * s * t,       (1 - r) * s * t};
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int c = 0; c < 8; ++c)
      p += w[c] * local[h[c]];
    return p;
  }
};

} // namespace mmrep
