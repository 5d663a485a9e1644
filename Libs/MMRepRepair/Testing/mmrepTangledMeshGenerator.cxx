// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepTangledMeshGenerator.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>

#include <cmath>
#include <random>

namespace mmrep::testing
{
namespace
{
// Point on the ellipsoid with semi-axes `axes` in direction d (radial projection).
Point3 OnEllipsoid(const Eigen::Vector3d& axes, const Point3& d)
{
  const double s = std::sqrt((d.array() / axes.array()).square().sum());
  return d / s;
}

struct Grid
{
  int columns, rows;
  int Node(int i, int j, int k) const { return (k * (rows + 1) + j) * (columns + 1) + (i + columns / 2); }
};
} // namespace

const std::array<double, 4>& LayerDepths()
{
  static const std::array<double, 4> depths{0.0, 0.2, 0.5, 1.0}; // epidermis thin, hypodermis thick
  return depths;
}

Point3 ShellPoint(const ShellAtlasOptions& o, double theta, double phi, double depth)
{
  const double t = std::abs(theta);
  const Point3 d(std::sin(t) * std::cos(phi), -std::cos(t) * std::cos(phi), std::sin(phi)); // face is anterior (-y)
  const Eigen::Vector3d inner = o.skinAxes.array() - o.thickness;
  Point3 p = (1 - depth) * OnEllipsoid(o.skinAxes, d) + depth * OnEllipsoid(inner, d);
  if (theta < 0)
    p.x() = -p.x(); // exact mirror image
  return p;
}

ShellAtlas MakeShellAtlas(const ShellAtlasOptions& o)
{
  ShellAtlas atlas;
  atlas.options = o;
  const Grid g{o.columns, o.rows};
  const double dTheta = 2 * o.halfWidth / o.columns, dPhi = 2 * o.halfHeight / o.rows;
  FEMesh& mesh = atlas.mesh;
  const auto& depths = LayerDepths();
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j <= o.rows; ++j)
      for (int i = -o.columns / 2; i <= o.columns / 2; ++i)
      {
        mesh.nodes.push_back(ShellPoint(o, i * dTheta, -o.halfHeight + j * dPhi, depths[k]));
        atlas.grid.emplace_back(i, j, k);
      }
  // Hex (i, j, k): bottom face at elevation row j, nodes 0-1 along azimuth, 0-3 along depth,
  // 0-4 upwards, which makes every corner Jacobian positive.
  const TissueLayer layers[3] = {TissueLayer::Epidermis, TissueLayer::Dermis, TissueLayer::Hypodermis};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < o.rows; ++j)
      for (int i = -o.columns / 2; i < o.columns / 2; ++i)
      {
        Element e;
        e.type = ElementType::Hexahedron;
        e.layer = layers[k];
        e.nodes = {g.Node(i, j, k),     g.Node(i + 1, j, k),     g.Node(i + 1, j, k + 1),     g.Node(i, j, k + 1),
                   g.Node(i, j + 1, k), g.Node(i + 1, j + 1, k), g.Node(i + 1, j + 1, k + 1), g.Node(i, j + 1, k + 1)};
        mesh.elements.push_back(e);
      }
  mesh.UpdateLayerSets();
  for (std::size_t n = 0; n < atlas.grid.size(); ++n)
  {
    const Eigen::Vector3i c = atlas.grid[n];
    const auto id = static_cast<std::int32_t>(n);
    if (c.z() == 0)
      mesh.nodeSets["skin"].push_back(id);
    if (c.z() == 3)
      mesh.nodeSets["skull"].push_back(id);
    if (c.z() == 0 && std::abs(c.x()) <= o.columns / 8 && c.y() >= o.rows / 5 && c.y() <= o.rows / 3)
      mesh.nodeSets["lips"].push_back(id);
    if (c.x() == 0)
      mesh.nodeSets["midsagittal"].push_back(id);
  }

  // Surfaces: the exact ellipsoids sampled on a finer, wider azimuth/elevation grid whose every
  // `refinement`-th vertex is a mesh node; quads split along mirrored diagonals (symmetric).
  const int r = o.surfaceRefinement, margin = 2 * r;
  const int half = o.columns / 2 * r + margin, rows = o.rows * r + 2 * margin;
  const double st = dTheta / r, sp = dPhi / r;
  for (const double depth : {0.0, 1.0})
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (int j = 0; j <= rows; ++j)
      for (int i = -half; i <= half; ++i)
        points->InsertNextPoint(ShellPoint(o, i * st, -o.halfHeight + (j - margin) * sp, depth).data());
    vtkNew<vtkCellArray> triangles;
    const auto V = [&](int i, int j) -> vtkIdType { return j * (2 * half + 1) + (i + half); };
    for (int j = 0; j < rows; ++j)
      for (int i = -half; i < half; ++i)
      {
        const vtkIdType a = V(i, j), b = V(i + 1, j), c = V(i + 1, j + 1), d = V(i, j + 1);
        const vtkIdType t1[2][3] = {{a, b, c}, {a, c, d}}, t2[2][3] = {{a, b, d}, {b, c, d}};
        const auto& t = i >= 0 ? t1 : t2;
        triangles->InsertNextCell(3, t[0]);
        triangles->InsertNextCell(3, t[1]);
      }
    auto surface = vtkSmartPointer<vtkPolyData>::New();
    surface->SetPoints(points);
    surface->SetPolys(triangles);
    (depth == 0 ? atlas.skin : atlas.skull) = surface;
  }
  return atlas;
}

FEMesh Tangle(const ShellAtlas& atlas, const TangleOptions& t)
{
  const ShellAtlasOptions& o = atlas.options;
  const Grid g{o.columns, o.rows};
  const double dTheta = 2 * o.halfWidth / o.columns, dPhi = 2 * o.halfHeight / o.rows;
  const auto& depths = LayerDepths();
  const std::size_t n = atlas.grid.size();
  // Parametric displacement per node, in element units (columns, rows, depth levels).
  std::vector<Eigen::Vector3d> delta(n, Eigen::Vector3d::Zero());
  Random random(t.seed);
  const int half = o.columns / 2;

  // Noise; in symmetric mode drawn for x >= 0 and mirrored.
  for (std::size_t id = 0; id < n; ++id)
  {
    const Eigen::Vector3i c = atlas.grid[id];
    if (t.symmetric && c.x() < 0)
      continue;
    delta[id] = t.noise * Eigen::Vector3d(random.Gaussian(), random.Gaussian(), random.Gaussian());
  }
  // Folds: a node pushed beyond its neighbour along one parametric direction.
  for (int f = 0; f < t.folds; ++f)
  {
    const int i = random.Integer(t.symmetric ? 0 : -half + 1, half - 1);
    const int j = random.Integer(1, o.rows - 1), k = random.Integer(0, 3);
    const int axis = (k == 0 || k == 3) ? random.Integer(0, 1) : random.Integer(0, 2);
    const double sign = random.Uniform() < 0.5 ? -1.0 : 1.0;
    Eigen::Vector3d push = Eigen::Vector3d::Zero();
    push[axis] = sign * (1.3 + 0.4 * random.Uniform());
    delta[g.Node(i, j, k)] += push;
  }
  // Smooth warps: a left-right shear growing with depth, a vertical wave, a depth wave.
  const double a = t.warp * (random.Uniform() - 0.5) * 2, b = t.warp * (random.Uniform() - 0.5) * 2,
               cw = t.warp * (random.Uniform() - 0.5);
  for (std::size_t id = 0; id < n; ++id)
  {
    const Eigen::Vector3i c = atlas.grid[id];
    const double u = double(c.x()) / half, v = double(c.y()) / o.rows, w = depths[c.z()];
    delta[id] += Eigen::Vector3d(a * w * std::sin(M_PI * u) * std::sin(M_PI * v),
                                 b * w * std::cos(0.5 * M_PI * u) * std::sin(2 * M_PI * v),
                                 cw * std::cos(0.5 * M_PI * u) * std::sin(M_PI * v) * 3 * w * (1 - w));
  }

  FEMesh mesh = atlas.mesh;
  for (std::size_t id = 0; id < n; ++id)
  {
    const Eigen::Vector3i c = atlas.grid[id];
    Eigen::Vector3d d = delta[id];
    if (t.symmetric)
    {
      if (c.x() < 0)
      {
        d = delta[g.Node(-c.x(), c.y(), c.z())];
        d.x() = -d.x();
      }
      else if (c.x() == 0)
        d.x() = 0; // stays on x = 0
    }
    // Depth steps: the thinner adjacent layer; skin and skull nodes stay on their ellipsoids.
    double depth = depths[c.z()];
    if (c.z() != 0 && c.z() != 3)
      depth += d.z() * std::min(depths[c.z()] - depths[c.z() - 1], depths[c.z() + 1] - depths[c.z()]);
    const double theta = (c.x() + d.x()) * dTheta;
    const double phi = -o.halfHeight + (c.y() + d.y()) * dPhi;
    mesh.nodes[id] = ShellPoint(o, theta, phi, depth);
  }
  return mesh;
}

TangleOptions RandomTangle(std::uint32_t seed, double maximumNoise)
{
  Random random(seed * 2654435761u + 12345u);
  TangleOptions t;
  t.seed = seed;
  t.symmetric = seed % 2 == 0;
  t.noise = 0.03 + (maximumNoise - 0.03) * random.Uniform();
  t.folds = random.Integer(0, 4);
  t.warp = random.Uniform() < 0.5 ? 0 : 0.5 + 1.5 * random.Uniform(); // up to 2 element sizes of shear
  return t;
}

} // namespace mmrep::testing
