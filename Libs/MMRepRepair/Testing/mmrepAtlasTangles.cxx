// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepAtlasTangles.h"

#include "mmrepLipContact.h"
#include "mmrepSurfaceProjector.h"

#include "mmrepFEMeshIO.h"
#include "mmrepSurfaceIO.h"

#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStaticCellLocator.h>
#include <vtkStaticPointLocator.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mmrep::testing
{
namespace
{
enum Kind : char
{
  Inner = 0,
  Skin = 1,
  Skull = 2
};

constexpr int kHexEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

std::vector<char> Kinds(const FEMesh& mesh)
{
  std::vector<char> kind(mesh.nodes.size(), Inner);
  for (const auto& [name, k] : {std::pair{"skull", Skull}, std::pair{"skin", Skin}}) // skin wins, as in the repair
    if (const auto it = mesh.nodeSets.find(name); it != mesh.nodeSets.end())
      for (const auto id : it->second)
        kind[id] = k;
  return kind;
}

std::vector<char> Midsagittal(const FEMesh& mesh)
{
  std::vector<char> on(mesh.nodes.size(), 0);
  if (const auto it = mesh.nodeSets.find("midsagittal"); it != mesh.nodeSets.end())
    for (const auto id : it->second)
      on[id] = 1;
  return on;
}

Point3 Closest(vtkStaticCellLocator* locator, const Point3& p)
{
  double closest[3], d2;
  vtkIdType cell;
  int sub;
  locator->FindClosestPoint(p.data(), closest, cell, sub, d2);
  return Point3(closest[0], closest[1], closest[2]);
}

vtkSmartPointer<vtkStaticCellLocator> Locator(vtkPolyData* surface)
{
  if (surface == nullptr || surface->GetNumberOfCells() == 0)
    throw std::invalid_argument("atlas tangles: a reference surface is empty");
  auto locator = vtkSmartPointer<vtkStaticCellLocator>::New();
  locator->SetDataSet(surface);
  BuildLocatorSequentially(locator); // the same projections on every run (mmrepSurfaceProjector.h)
  return locator;
}

// Vertical direction in the plane (patient superior, LPS +z, made orthogonal to the normal).
Point3 Vertical(const Plane& plane)
{
  const Point3 z = Point3::UnitZ();
  return (z - z.dot(plane.normal) * plane.normal).normalized();
}
} // namespace

MeshTangleContext LoadTangleContext(const std::string& meshPath, const std::string& skinPath,
                                    const std::string& skullPath)
{
  return MakeTangleContext(ReadFEMesh(meshPath), ReadSurface(skinPath), ReadSurface(skullPath));
}

MeshTangleContext MakeTangleContext(FEMesh mesh, vtkSmartPointer<vtkPolyData> skin, vtkSmartPointer<vtkPolyData> skull)
{
  MeshTangleContext c;
  // Tangles of the fused lips: the mouth slit closed (its twins then belong to no element and are
  // dropped from the sets), so that the mirror partners are unique and the tangle moves both lips.
  const ClosedMouth closed = CloseMouth(mesh);
  for (const auto& [upper, lower] : closed.twins)
    for (auto& [name, ids] : mesh.nodeSets)
      ids.erase(std::remove(ids.begin(), ids.end(), lower), ids.end());
  for (const auto& set : {kUpperLipSet, kLowerLipSet})
    mesh.elementSets.erase(set);
  c.mesh = std::move(mesh);
  c.skin = skin;
  c.skull = skull;
  c.skinLocator = Locator(skin);
  c.skullLocator = Locator(skull);
  const FEMesh& m = c.mesh;
  const std::size_t n = m.nodes.size();
  Eigen::AlignedBox3d box;
  for (const Point3& p : m.nodes)
    box.extend(p);
  c.diagonal = box.diagonal().norm();

  // Edges: hexahedron edges, every node pair of other solids.
  std::vector<std::vector<std::int32_t>> nb(n);
  for (const Element& e : m.elements)
  {
    if (e.type == ElementType::Cable)
      continue;
    auto add = [&](std::int32_t a, std::int32_t b) {
      nb[a].push_back(b);
      nb[b].push_back(a);
    };
    if (e.type == ElementType::Hexahedron)
      for (const auto& edge : kHexEdges)
        add(e.nodes[edge[0]], e.nodes[edge[1]]);
    else
      for (int a = 0; a < NodeCount(e.type); ++a)
        for (int b = a + 1; b < NodeCount(e.type); ++b)
          add(e.nodes[a], e.nodes[b]);
  }
  c.neighbours = std::move(nb);
  // Depth through the layers: skin 0, skull / inner surface 1, the two inner levels by layer.
  const std::vector<char> kind = Kinds(m);
  std::vector<char> inEpidermis(n, 0), solid(n, 0);
  for (const Element& e : m.elements)
    for (int k = 0; k < NodeCount(e.type) && e.type != ElementType::Cable; ++k)
    {
      solid[e.nodes[k]] = 1;
      inEpidermis[e.nodes[k]] |= e.layer == TissueLayer::Epidermis ? 1 : 0;
    }
  c.depth.assign(n, 0);
  const auto inner = m.nodeSets.find("inner");
  std::vector<char> bottom(n, 0);
  if (inner != m.nodeSets.end())
    for (const auto id : inner->second)
      bottom[id] = 1;
  for (std::size_t i = 0; i < n; ++i)
    c.depth[i] = kind[i] == Skin ? 0.0 : (kind[i] == Skull || bottom[i]) ? 1.0 : inEpidermis[i] ? 1.0 / 3 : 2.0 / 3;

  // Element sizes: along the surfaces (edges to the same level) and through the thickness (the
  // shortest edge to another level, so that noise cannot swap levels of a thin layer by itself).
  c.size.assign(n, 0);
  c.layer.assign(n, 0);
  double total = 0;
  int counted = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    int same = 0;
    double thinnest = std::numeric_limits<double>::infinity();
    for (const auto j : c.neighbours[i])
    {
      const double length = (m.nodes[j] - m.nodes[i]).norm();
      if (c.depth[j] == c.depth[i])
      {
        c.size[i] += length;
        ++same;
      }
      else
        thinnest = std::min(thinnest, length);
    }
    if (same > 0)
    {
      c.size[i] /= same;
      total += c.size[i];
      ++counted;
    }
    c.layer[i] = std::isfinite(thinnest) ? thinnest : c.size[i];
  }
  c.meanSize = counted > 0 ? total / counted : 0;
  // Skin node of each node's through-thickness column: follow the edges to shallower levels.
  c.top.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i)
  {
    std::int32_t node = static_cast<std::int32_t>(i);
    for (int step = 0; step < 8 && node >= 0 && c.depth[node] > 0; ++step)
    {
      std::int32_t up = -1;
      for (const auto j : c.neighbours[node])
        if (c.depth[j] < c.depth[node] && (up < 0 || c.depth[j] > c.depth[up]))
          up = j;
      node = up;
    }
    if (node >= 0 && c.depth[node] == 0 && !c.neighbours[i].empty())
      c.top[i] = node;
  }

  // Plane of the mid-sagittal nodes (least squares).
  const auto mid = m.nodeSets.find("midsagittal");
  if (mid == m.nodeSets.end() || mid->second.size() < 3)
    throw std::runtime_error("atlas tangles: the mesh has no midsagittal node set");
  c.plane = FitPlaneToNodeSet(m, "midsagittal");

  // Mirror partners of the solid elements' nodes (mutual nearest mirror images within 1e-6 of the
  // diagonal); nodes of no solid element (embedded muscle points) are their own partners.
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::vector<std::size_t> ids;
  for (std::size_t i = 0; i < n; ++i)
    if (!c.neighbours[i].empty())
    {
      points->InsertNextPoint(m.nodes[i].data());
      ids.push_back(i);
    }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  std::vector<std::int32_t> partner(n);
  for (std::size_t i = 0; i < n; ++i)
    partner[i] = static_cast<std::int32_t>(i);
  bool symmetric = true;
  for (std::size_t k = 0; k < ids.size() && symmetric; ++k)
  {
    const Point3 q = c.plane.Mirror(m.nodes[ids[k]]);
    const vtkIdType j = locator->FindClosestPoint(q.data());
    symmetric = j >= 0 && (m.nodes[ids[j]] - q).norm() <= 1e-6 * c.diagonal;
    if (symmetric)
      partner[ids[k]] = static_cast<std::int32_t>(ids[j]);
  }
  for (std::size_t i = 0; i < n && symmetric; ++i)
    symmetric = partner[partner[i]] == static_cast<std::int32_t>(i);
  if (symmetric)
    c.partner = std::move(partner);

  // Local frame for the perturbations: outward skin normal at the closest skin point, distance
  // to the skin.
  c.normal.assign(n, Point3::Zero());
  c.skinDistance.assign(n, 0);
  vtkNew<vtkGenericCell> cell;
  for (std::size_t i = 0; i < n; ++i)
  {
    double closest[3], d2;
    vtkIdType id;
    int sub;
    c.skinLocator->FindClosestPoint(m.nodes[i].data(), closest, cell, id, sub, d2);
    c.skinDistance[i] = std::sqrt(d2);
    vtkPoints* corners = cell->GetPoints();
    Point3 a, b, e;
    corners->GetPoint(0, a.data());
    corners->GetPoint(1, b.data());
    corners->GetPoint(2, e.data());
    const Point3 normal = (b - a).cross(e - a);
    c.normal[i] = normal.norm() > 0 ? Point3(normal.normalized()) : Point3::Zero();
  }
  return c;
}

FEMesh TangleMesh(const MeshTangleContext& c, const TangleOptions& t)
{
  const FEMesh& atlas = c.mesh;
  const std::size_t n = atlas.nodes.size();
  if (t.symmetric && c.partner.empty())
    throw std::invalid_argument("atlas tangles: a symmetric tangle needs a symmetric mesh");
  const std::vector<char> kind = Kinds(atlas), onPlane = Midsagittal(atlas);
  Random random(t.seed);
  // In symmetric mode only the left half and the plane are drawn; the right half mirrors them.
  auto drawn = [&](std::size_t i) {
    return !t.symmetric || c.partner[i] == static_cast<std::int32_t>(i) || c.plane.SignedDistance(atlas.nodes[i]) > 0;
  };
  std::vector<Point3> d(n, Point3::Zero());

  // Noise: tangential to the skin of the element size, through the thickness of the node's
  // thinnest adjacent layer (so that noise alone does not swap the levels of a thin layer).
  for (std::size_t i = 0; i < n; ++i)
    if (drawn(i) && !c.neighbours[i].empty())
    {
      const Point3& nn = c.normal[i];
      const Point3 t1 = nn.unitOrthogonal(), t2 = nn.cross(t1);
      d[i] =
        t.noise * (c.size[i] * (random.Gaussian() * t1 + random.Gaussian() * t2) + c.layer[i] * random.Gaussian() * nn);
    }

  // Folds: a node pushed 1.3 to 1.7 times the way to one of its edge neighbours (a surface node
  // to a neighbour on the same surface, so that the projection back onto it keeps the fold).
  for (int f = 0; f < t.folds; ++f)
    for (int attempt = 0; attempt < 100; ++attempt)
    {
      const auto i = static_cast<std::size_t>(random.Integer(0, static_cast<int>(n) - 1));
      if (!drawn(i) || c.neighbours[i].empty())
        continue;
      std::vector<std::int32_t> candidates;
      for (const auto j : c.neighbours[i])
        if (kind[i] == Inner || kind[j] == kind[i])
          candidates.push_back(j);
      if (candidates.empty())
        continue;
      const auto j = candidates[random.Integer(0, static_cast<int>(candidates.size()) - 1)];
      d[i] += (1.3 + 0.4 * random.Uniform()) * (atlas.nodes[j] - atlas.nodes[i]);
      break;
    }

  // Warps of amplitude t.warp element sizes, tangential to the skin (a registration moves the
  // tissue along the surfaces; a normal component would only be projected away at the surfaces
  // and push the inner levels through them): a shear of the deep levels against the skin,
  // proportional to the depth under the skin (shear strain up to t.warp / 2; lateral, odd in the
  // lateral coordinate, and vertical, even in it), and two large Gaussian bumps (radius 3 to 6
  // element sizes) moving all levels alike.
  if (t.warp > 0)
  {
    const Point3 up = Vertical(c.plane);
    double lateral = 0, lo = 1e300, hi = -1e300;
    for (const Point3& p : atlas.nodes)
    {
      lateral = std::max(lateral, std::abs(c.plane.SignedDistance(p)));
      lo = std::min(lo, up.dot(p));
      hi = std::max(hi, up.dot(p));
    }
    const double a = 0.5 * t.warp * (2 * random.Uniform() - 1), b = 0.5 * t.warp * (2 * random.Uniform() - 1);
    struct Bump
    {
      Point3 centre, direction;
      double radius, amplitude;
    };
    std::vector<Bump> bumps;
    for (int k = 0; k < 2; ++k)
    {
      Bump bump;
      bump.centre = atlas.nodes[random.Integer(0, static_cast<int>(n) - 1)];
      bump.direction = Point3(random.Gaussian(), random.Gaussian(), random.Gaussian()).normalized();
      bump.radius = (3 + 3 * random.Uniform()) * c.meanSize;
      bump.amplitude = t.warp * c.meanSize * (0.5 + 0.5 * random.Uniform());
      bumps.push_back(bump);
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      if (!drawn(i) || c.neighbours[i].empty())
        continue;
      const Point3& p = atlas.nodes[i];
      const double u = c.plane.SignedDistance(p) / lateral, v = (up.dot(p) - lo) / (hi - lo);
      Point3 w = c.skinDistance[i] * (a * std::sin(M_PI * u) * std::sin(M_PI * v) * c.plane.normal +
                                      b * std::cos(0.5 * M_PI * u) * std::sin(2 * M_PI * v) * up);
      for (const Bump& bump : bumps)
        w += bump.amplitude * std::exp(-(p - bump.centre).squaredNorm() / (2 * bump.radius * bump.radius)) *
             bump.direction;
      d[i] += w - w.dot(c.normal[i]) * c.normal[i];
    }
  }

  FEMesh mesh = atlas;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!drawn(i) || c.neighbours[i].empty())
      continue;
    Point3 p = atlas.nodes[i] + d[i];
    vtkStaticCellLocator* surface = kind[i] == Skin    ? c.skinLocator.Get()
                                    : kind[i] == Skull ? c.skullLocator.Get()
                                                       : nullptr;
    if (surface != nullptr)
      p = Closest(surface, p);
    if (onPlane[i])
    {
      p = c.plane.Project(p);
      // On the plane's trace of the surface: alternate projections, ending on the plane.
      for (int k = 0; k < 100 && surface != nullptr; ++k)
      {
        const Point3 q = c.plane.Project(Closest(surface, p));
        const double step = (q - p).norm();
        p = q;
        if (step < 1e-12 * c.diagonal)
          break;
      }
    }
    mesh.nodes[i] = p;
  }
  if (t.symmetric)
    for (std::size_t i = 0; i < n; ++i)
      if (!drawn(i))
        mesh.nodes[i] = c.plane.Mirror(mesh.nodes[c.partner[i]]);
  return mesh;
}

FEMesh CropMesh(const FEMesh& mesh, const Plane& plane, double fraction)
{
  const Point3 up = Vertical(plane);
  std::vector<std::pair<double, std::size_t>> height;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
  {
    const Element& element = mesh.elements[e];
    if (element.type == ElementType::Cable)
      continue;
    Point3 centroid = Point3::Zero();
    for (int k = 0; k < NodeCount(element.type); ++k)
      centroid += mesh.nodes[element.nodes[k]];
    // Rounded to 1e-6 mm so that mirror images (equal to round-off) fall on the same side.
    height.emplace_back(std::round(1e6 * up.dot(centroid) / NodeCount(element.type)) / 1e6, e);
  }
  std::vector<double> sorted;
  for (const auto& [h, e] : height)
    sorted.push_back(h);
  std::sort(sorted.begin(), sorted.end());
  const double limit = sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(fraction * double(sorted.size())))];
  FEMesh out;
  std::vector<std::int32_t> index(mesh.nodes.size(), -1);
  std::vector<std::size_t> kept;
  for (const auto& [h, e] : height)
    if (h <= limit)
    {
      kept.push_back(e);
      for (int k = 0; k < NodeCount(mesh.elements[e].type); ++k)
        index[mesh.elements[e].nodes[k]] = 0;
    }
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    if (index[i] == 0)
    {
      index[i] = static_cast<std::int32_t>(out.nodes.size());
      out.nodes.push_back(mesh.nodes[i]);
    }
  std::sort(kept.begin(), kept.end());
  for (const std::size_t e : kept)
  {
    Element element = mesh.elements[e];
    for (int k = 0; k < NodeCount(element.type); ++k)
      element.nodes[k] = index[element.nodes[k]];
    out.elements.push_back(element);
  }
  for (const auto& [name, ids] : mesh.nodeSets)
  {
    auto& set = out.nodeSets[name];
    for (const auto id : ids)
      if (index[id] >= 0)
        set.push_back(index[id]);
  }
  out.UpdateLayerSets();
  return out;
}

double SymmetryError(const FEMesh& mesh, const MeshTangleContext& c)
{
  double worst = 0;
  for (std::size_t i = 0; i < mesh.nodes.size() && !c.partner.empty(); ++i)
    if (!c.neighbours[i].empty()) // nodes of solid elements (embedded muscle points follow them)
      worst = std::max(worst, (c.plane.Mirror(mesh.nodes[i]) - mesh.nodes[c.partner[i]]).norm());
  return worst / c.diagonal;
}

const MeshTangleContext& ShippedAtlasTangleContext()
{
  static const MeshTangleContext context = LoadTangleContext(MMREP_SOURCE_DIR "/Resources/Atlas/FaceAtlas.vtu",
                                                             MMREP_SOURCE_DIR "/Resources/Atlas/FaceAtlasSkin.vtp",
                                                             MMREP_SOURCE_DIR "/Resources/Atlas/FaceAtlasSkull.vtp");
  return context;
}

RepairOptions TangleRepairOptions(const MeshTangleContext& c)
{
  RepairOptions o;
  o.skinSurface = c.skin;
  o.skullSurface = c.skull;
  o.hasSymmetryPlane = true;
  o.symmetryPlane = c.plane;
  return o;
}

} // namespace mmrep::testing
