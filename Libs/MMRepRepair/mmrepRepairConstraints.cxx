// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepRepairConstraints.h"

#include "mmrepMirrorPairs.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace mmrep
{
namespace
{
// Mirror partners lie within this fraction of the mesh size of each other's mirror image.
constexpr double kMirrorTolerance = 1e-7;
// Mid-sagittal nodes within this fraction of the mesh size of their fitted plane are coplanar.
constexpr double kCoplanarTolerance = 1e-6;

// A node next to the plane keeps this fraction of its neighbours' mean distance from it.
constexpr double kSideMargin = 0.01;

const std::vector<std::int32_t>* Set(const FEMesh& mesh, const char* name)
{
  const auto it = mesh.nodeSets.find(name);
  return it == mesh.nodeSets.end() ? nullptr : &it->second;
}
} // namespace

RepairConstraints::RepairConstraints(const FEMesh& mesh, const NodeElements& adjacency, const RepairOptions& options)
    : mesh_(mesh)
{
  const std::size_t n = mesh_.nodes.size();
  surface_.assign(n, SurfaceKind::None);
  onPlane_.assign(n, 0);
  partner_.resize(n);
  std::iota(partner_.begin(), partner_.end(), 0);

  // Skull first, then skin: a node in both sets follows the skin.
  for (const auto& [name, kind] : {std::pair{"skull", SurfaceKind::Skull}, std::pair{"skin", SurfaceKind::Skin}})
    if (const auto* set = Set(mesh_, name))
      for (const std::int32_t id : *set)
        surface_[id] = kind;
  auto projector = [&](vtkPolyData* given, SurfaceKind kind) -> std::unique_ptr<SurfaceProjector> {
    if (std::none_of(surface_.begin(), surface_.end(), [&](SurfaceKind k) { return k == kind; }))
      return nullptr;
    if (given != nullptr)
      return std::make_unique<SurfaceProjector>(given);
    // No surface given: the input mesh's own boundary faces made of the set's nodes (or all of them).
    std::vector<char> mask(n, 0);
    for (std::size_t i = 0; i < n; ++i)
      mask[i] = surface_[i] == kind;
    vtkSmartPointer<vtkPolyData> boundary = BoundarySurface(mesh_, &mask);
    if (boundary->GetNumberOfCells() == 0)
      boundary = BoundarySurface(mesh_);
    ownSurfaces_.push_back(boundary);
    return boundary->GetNumberOfCells() > 0 ? std::make_unique<SurfaceProjector>(boundary) : nullptr;
  };
  skin_ = projector(options.skinSurface, SurfaceKind::Skin);
  skull_ = projector(options.skullSurface, SurfaceKind::Skull);
  for (std::size_t i = 0; i < n; ++i) // a surface set without any surface face: keep its nodes fixed
    if ((surface_[i] == SurfaceKind::Skin && !skin_) || (surface_[i] == SurfaceKind::Skull && !skull_))
      fixed_.push_back(i);

  const auto* midsagittal = Set(mesh_, "midsagittal");
  if (options.hasSymmetryPlane)
  {
    plane_ = options.symmetryPlane;
    if (!(plane_.normal.norm() > 0) || !plane_.normal.allFinite() || !plane_.point.allFinite())
      throw std::invalid_argument("symmetry plane has no valid normal");
    plane_.normal.normalize();
    hasPlane_ = true;
    std::vector<std::uint8_t> kind(n);
    for (std::size_t i = 0; i < n; ++i)
      kind[i] = static_cast<std::uint8_t>(surface_[i]);
    if (auto pairs =
          mmrep::MirrorPairs(mesh_, adjacency, plane_, kind, kMirrorTolerance * std::max(Diagonal(), 1e-300)))
    {
      partner_ = std::move(*pairs);
      pairs_ = true;
      for (std::size_t i = 0; i < n; ++i)
        if (adjacency.InSolid(i) && partner_[i] == static_cast<std::int32_t>(i))
          onPlane_[i] = 1; // its own mirror: must stay on the plane to stay symmetric
    }
  }
  else if (midsagittal != nullptr && midsagittal->size() >= 3)
    FitPlane(*midsagittal);
  if (hasPlane_ && midsagittal != nullptr)
    for (const std::int32_t id : *midsagittal)
      onPlane_[id] = 1;
  if (hasPlane_ && options.keepPlaneSides)
    FindSides(adjacency);
  std::sort(fixed_.begin(), fixed_.end());
}

// The nodes of elements with a face on the plane (3 or more plane nodes) take the side where the
// other nodes of their elements lie, those not next to the plane themselves (fewer of them have
// been pushed across by whatever tangled the mesh).
void RepairConstraints::FindSides(const NodeElements& adjacency)
{
  const std::size_t n = mesh_.nodes.size();
  std::vector<char> next(n, 0);
  for (const Element& element : mesh_.elements)
  {
    const int count = NodeCount(element.type);
    int onPlane = 0;
    for (int k = 0; k < count; ++k)
      onPlane += onPlane_[element.nodes[k]];
    if (element.type != ElementType::Cable && onPlane >= 3)
      for (int k = 0; k < count; ++k)
        next[element.nodes[k]] = !onPlane_[element.nodes[k]];
  }
  side_.assign(n, 0);
  sideMargin_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!next[i])
      continue;
    double sum = 0;
    int count = 0;
    for (std::size_t k = adjacency.offsets[i]; k < adjacency.offsets[i + 1]; ++k)
    {
      const Element& element = mesh_.elements[adjacency.adjacent[k]];
      for (int j = 0; j < NodeCount(element.type); ++j)
        if (const auto m = static_cast<std::size_t>(element.nodes[j]); !onPlane_[m] && !next[m])
          sum += plane_.SignedDistance(mesh_.nodes[m]), ++count;
    }
    if (count > 0 && sum != 0)
    {
      side_[i] = sum > 0 ? 1 : -1;
      sideMargin_[i] = kSideMargin * std::abs(sum) / count;
    }
  }
}

bool RepairConstraints::OnItsSide(std::size_t node, const Point3& p) const
{
  return Side(node) == 0 || Side(node) * plane_.SignedDistance(p) >= sideMargin_[node];
}

double RepairConstraints::Diagonal() const
{
  Eigen::AlignedBox3d box;
  for (const Point3& p : mesh_.nodes)
    box.extend(p);
  return box.diagonal().norm();
}

// Mid-sagittal nodes that are coplanar stay on their plane.
void RepairConstraints::FitPlane(const std::vector<std::int32_t>& ids)
{
  Point3 centre = Point3::Zero();
  for (const auto id : ids)
    centre += mesh_.nodes[id];
  centre /= static_cast<double>(ids.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto id : ids)
  {
    const Point3 d = mesh_.nodes[id] - centre;
    covariance += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  if (solver.info() != Eigen::Success || !(solver.eigenvalues()(1) > 0))
    return; // collinear or coincident: no plane
  Plane plane;
  plane.point = centre;
  plane.normal = solver.eigenvectors().col(0).normalized();
  double worst = 0;
  for (const auto id : ids)
    worst = std::max(worst, std::abs(plane.SignedDistance(mesh_.nodes[id])));
  if (worst <= kCoplanarTolerance * Diagonal())
  {
    plane_ = plane;
    hasPlane_ = true;
  }
}

// A proposed position made admissible: on the node's surface, then on the plane.
Point3 RepairConstraints::Constrain(std::size_t node, Point3 p) const
{
  const SurfaceProjector* surface = surface_[node] == SurfaceKind::Skin    ? skin_.get()
                                    : surface_[node] == SurfaceKind::Skull ? skull_.get()
                                                                           : nullptr;
  if (surface != nullptr)
    p = surface->Project(p);
  if (!onPlane_[node])
  {
    if (OnItsSide(node, p))
      return p;
    p += (Side(node) * sideMargin_[node] - plane_.SignedDistance(p)) * plane_.normal;
    return surface != nullptr ? surface->Project(p) : p;
  }
  p = plane_.Project(p);
  // On a surface and the plane: alternate projections onto their intersection curve (they
  // cross nearly at right angles, so this converges in a few steps), ending on the plane.
  for (int i = 0; i < 20 && surface != nullptr; ++i)
  {
    const Point3 q = plane_.Project(surface->Project(p));
    const double step = (q - p).norm();
    p = q;
    if (step <= 1e-13 * (1 + p.norm()))
      break;
  }
  return p;
}

// Unit directions spanning the node's admissible moves: 3D (axes and cube diagonals), a surface's
// tangent plane or the symmetry plane (axes and diagonals of a basis), or their intersection line.
std::vector<Point3> RepairConstraints::Directions(std::size_t node, const Point3& p) const
{
  std::vector<Point3> normals;
  if (surface_[node] == SurfaceKind::Skin)
    normals.push_back(skin_->Normal(p));
  else if (surface_[node] == SurfaceKind::Skull)
    normals.push_back(skull_->Normal(p));
  if (onPlane_[node])
    normals.push_back(plane_.normal);
  normals.erase(std::remove_if(normals.begin(), normals.end(), [](const Point3& n) { return !(n.norm() > 0.5); }),
                normals.end());
  std::vector<Point3> d;
  if (normals.empty())
  {
    for (int axis = 0; axis < 3; ++axis)
      for (const double s : {1.0, -1.0})
        d.push_back(s * Point3::Unit(axis));
    for (int corner = 0; corner < 8; ++corner)
      d.push_back(Point3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1) / std::sqrt(3.0));
    return d;
  }
  if (normals.size() == 2)
  {
    const Point3 line = normals[0].cross(normals[1]);
    if (line.norm() > 1e-6)
      return {line.normalized(), -line.normalized()};
  }
  const Point3& n = normals[0];
  const Point3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  for (const Point3& t : {t1, t2, Point3((t1 + t2) / std::sqrt(2.0)), Point3((t1 - t2) / std::sqrt(2.0))})
  {
    d.push_back(t);
    d.push_back(-t);
  }
  return d;
}

bool RepairConstraints::IsFixed(std::size_t node) const
{
  return std::binary_search(fixed_.begin(), fixed_.end(), node);
}

} // namespace mmrep
