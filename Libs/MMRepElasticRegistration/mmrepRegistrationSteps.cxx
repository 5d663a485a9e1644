// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Steps shared by R and Q (see mmrepRegistrationSteps.h).
#include "mmrepRegistrationSteps.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mmrep::registration
{

void AddMeshGuard(const FEMesh& mesh, const std::vector<std::int32_t>& trackedNodes,
                  const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& toFrame, ElasticProblem& problem,
                  const std::function<int(std::size_t)>& innerMap)
{
  std::vector<int> pointOf(mesh.nodes.size(), -1);
  for (std::size_t k = 0; k < trackedNodes.size(); ++k)
    if (pointOf[static_cast<std::size_t>(trackedNodes[k])] < 0)
      pointOf[static_cast<std::size_t>(trackedNodes[k])] = static_cast<int>(k);
  for (const auto& e : mesh.elements)
  {
    if (e.type != ElementType::Hexahedron)
      continue;
    std::array<int, 8> h{};
    for (std::size_t c = 0; c < 8; ++c)
    {
      const auto v = static_cast<std::size_t>(e.nodes[c]);
      if (pointOf[v] < 0)
      {
        pointOf[v] = static_cast<int>(problem.points.size());
        problem.points.push_back(toFrame(mesh.nodes[v]));
        problem.pointMap.push_back(innerMap(v));
      }
      h[c] = pointOf[v];
    }
    problem.hexahedra.push_back(h);
  }
}

double Since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

void SetPlaneFrame(ElasticTransform& t, const Plane& plane)
{
  const Eigen::Vector3d e0 = plane.normal.normalized();
  Eigen::Vector3d ref = Eigen::Vector3d::UnitY();
  if (std::abs(e0.dot(ref)) > 0.9)
    ref = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d e1 = (ref - ref.dot(e0) * e0).normalized();
  const Eigen::Vector3d e2 = e0.cross(e1);
  t.frameRotation.row(0) = e0.transpose();
  t.frameRotation.row(1) = e1.transpose();
  t.frameRotation.row(2) = e2.transpose();
  t.frameOrigin = plane.point;
}

void CheckPlane(const Plane& p, const std::string& what)
{
  if (!p.point.allFinite() || !p.normal.allFinite() || !(p.normal.norm() > 1e-12))
    throw std::invalid_argument(what + ": the plane needs a finite point and a non-zero normal");
}

const std::vector<std::int32_t>& NodeSet(const FEMesh& mesh, const std::string& name, const std::string& what)
{
  const auto it = mesh.nodeSets.find(name);
  if (it == mesh.nodeSets.end() || it->second.empty())
    throw std::invalid_argument(what + ": the mesh has no node set '" + name + "' (or it is empty)");
  for (auto id : it->second)
    if (id < 0 || static_cast<std::size_t>(id) >= mesh.nodes.size())
      throw std::invalid_argument(what + ": node set '" + name + "' refers to a missing node");
  return it->second;
}

void CheckSurface(vtkPolyData* s, const std::string& what)
{
  if (s == nullptr || s->GetNumberOfPoints() == 0 || s->GetNumberOfPolys() + s->GetNumberOfStrips() == 0)
    throw std::runtime_error(what + " surface is empty (no triangles)");
}

std::vector<std::int32_t> Intersection(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b)
{
  std::vector<std::int32_t> x(a), y(b), r;
  std::sort(x.begin(), x.end());
  std::sort(y.begin(), y.end());
  std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(r));
  return r;
}

int AutomaticLevel(double smallestExtent, double spacing, double cellsPerSpacing)
{
  const double ratio = smallestExtent / (cellsPerSpacing * spacing);
  return std::clamp(static_cast<int>(std::floor(std::log2(std::max(ratio, 1.0)))), 1, 8);
}

FloatImage::Pointer DistanceMap(vtkPolyData* surface, SurfaceDistanceMapOptions o, bool trySigned,
                                const std::function<void(double)>& progress)
{
  if (trySigned)
  {
    o.signedDistance = true;
    try
    {
      return ComputeSurfaceDistanceMap(surface, o, progress);
    }
    catch (const std::runtime_error&)
    {
    }
  }
  o.signedDistance = false;
  return ComputeSurfaceDistanceMap(surface, o, progress);
}

void SymmetricInX(bool symmetric, Eigen::Vector3d& lo, Eigen::Vector3d& hi)
{
  if (!symmetric)
    return;
  const double x = std::max(std::abs(lo.x()), std::abs(hi.x()));
  lo.x() = -x;
  hi.x() = x;
}

} // namespace mmrep::registration
