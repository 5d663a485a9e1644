// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepSurfaceDistance.h"

#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mmrep
{

std::vector<double> NodeSurfaceDistances(const std::vector<Point3>& nodes, const std::vector<std::int32_t>& ids,
                                         vtkPolyData* surface)
{
  std::vector<double> d;
  if (ids.empty() || surface == nullptr || surface->GetNumberOfCells() == 0)
    return d;
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  d.reserve(ids.size());
  for (const auto id : ids)
  {
    const Point3& p = nodes.at(static_cast<std::size_t>(id));
    double x[3] = {p.x(), p.y(), p.z()}, closest[3], d2 = 0;
    vtkIdType cellId = -1;
    int subId = 0;
    locator->FindClosestPoint(x, closest, cell, cellId, subId, d2);
    d.push_back(std::sqrt(d2));
  }
  return d;
}

SurfaceDistance MeasureSurfaceDistance(const std::vector<Point3>& nodes, const std::vector<std::int32_t>& ids,
                                       vtkPolyData* surface)
{
  SurfaceDistance s;
  const auto d = NodeSurfaceDistances(nodes, ids, surface);
  if (d.empty())
    return s;
  double sum = 0, sum2 = 0;
  for (const double v : d)
  {
    sum += v;
    sum2 += v * v;
    s.max = std::max(s.max, v);
  }
  s.count = d.size();
  s.mean = sum / static_cast<double>(s.count);
  s.sigma = std::sqrt(std::max(0.0, sum2 / static_cast<double>(s.count) - s.mean * s.mean));
  return s;
}

SurfaceDistance MeasureSurfaceDistance(const FEMesh& mesh, const std::string& nodeSet, vtkPolyData* surface)
{
  if (surface == nullptr || surface->GetNumberOfCells() == 0)
    throw std::invalid_argument("surface distance: the surface to measure against has no cells");
  const auto it = mesh.nodeSets.find(nodeSet);
  return it == mesh.nodeSets.end() ? SurfaceDistance{} : MeasureSurfaceDistance(mesh.nodes, it->second, surface);
}

} // namespace mmrep
