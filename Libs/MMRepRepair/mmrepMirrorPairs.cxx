// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepMirrorPairs.h"

#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticPointLocator.h>

#include <limits>
#include <numeric>

namespace mmrep
{
namespace
{

// The stored map restricted to solid nodes, checked against the plane.
std::optional<std::vector<std::int32_t>> StoredPairs(const FEMesh& mesh, const NodeElements& adjacency,
                                                     const Plane& plane, const std::vector<std::uint8_t>& kind,
                                                     double tolerance)
{
  const std::size_t n = mesh.nodes.size();
  std::vector<std::int32_t> partner(n);
  std::iota(partner.begin(), partner.end(), 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!adjacency.InSolid(i))
      continue;
    const auto j = static_cast<std::size_t>(mesh.mirror[i]);
    if (!adjacency.InSolid(j) || kind[j] != kind[i] ||
        !((plane.Mirror(mesh.nodes[i]) - mesh.nodes[j]).squaredNorm() <= tolerance * tolerance))
      return std::nullopt; // not symmetric about this plane: nodes move one by one
    partner[i] = static_cast<std::int32_t>(j);
  }
  return partner;
}

std::optional<std::vector<std::int32_t>> GeometricPairs(const FEMesh& mesh, const NodeElements& adjacency,
                                                        const Plane& plane, const std::vector<std::uint8_t>& kind,
                                                        double tolerance)
{
  const std::size_t n = mesh.nodes.size();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::vector<std::size_t> ids;
  for (std::size_t i = 0; i < n; ++i)
    if (adjacency.InSolid(i))
    {
      points->InsertNextPoint(mesh.nodes[i].data());
      ids.push_back(i);
    }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  std::vector<std::int32_t> partner(n);
  std::iota(partner.begin(), partner.end(), 0);
  auto neighbourhood = [&](std::size_t i) {
    Point3 sum = Point3::Zero();
    int count = 0;
    for (std::size_t a = adjacency.offsets[i]; a < adjacency.offsets[i + 1]; ++a)
    {
      const Element& e = mesh.elements[adjacency.adjacent[a]];
      for (int k = 0; k < NodeCount(e.type); ++k, ++count)
        sum += mesh.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])];
    }
    return Point3(sum / std::max(count, 1));
  };
  vtkNew<vtkIdList> candidates;
  for (const std::size_t i : ids)
  {
    const Point3 mirror = plane.Mirror(mesh.nodes[i]);
    locator->FindPointsWithinRadius(tolerance, mirror.data(), candidates);
    std::size_t best = n;
    double bestMismatch = std::numeric_limits<double>::infinity();
    for (vtkIdType c = 0; c < candidates->GetNumberOfIds(); ++c)
    {
      const std::size_t j = ids[static_cast<std::size_t>(candidates->GetId(c))];
      if (kind[j] != kind[i])
        continue;
      const double mismatch =
        candidates->GetNumberOfIds() == 1 ? 0.0 : (plane.Mirror(neighbourhood(i)) - neighbourhood(j)).norm();
      if (mismatch < bestMismatch || (mismatch == bestMismatch && j < best))
      {
        best = j;
        bestMismatch = mismatch;
      }
    }
    if (best == n)
      return std::nullopt; // not symmetric: nodes move one by one
    partner[i] = static_cast<std::int32_t>(best);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (partner[partner[i]] != static_cast<std::int32_t>(i))
      return std::nullopt;
  return partner;
}

} // namespace

std::optional<std::vector<std::int32_t>> MirrorPairs(const FEMesh& mesh, const NodeElements& adjacency,
                                                     const Plane& plane, const std::vector<std::uint8_t>& kind,
                                                     double tolerance)
{
  return mesh.HasMirrorMap() ? StoredPairs(mesh, adjacency, plane, kind, tolerance)
                             : GeometricPairs(mesh, adjacency, plane, kind, tolerance);
}

} // namespace mmrep
