// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepSurfaceProjector.h"

#include <vtkSMPTools.h>

#include <Eigen/Geometry>
#include <vtkPoints.h>

#include <stdexcept>

namespace mmrep
{

SurfaceProjector::SurfaceProjector(vtkPolyData* surface)
{
  if (surface == nullptr || surface->GetNumberOfCells() == 0)
    throw std::invalid_argument("surface to project onto has no cells");
  surface_ = surface;
  locator_ = vtkSmartPointer<vtkStaticCellLocator>::New();
  locator_->SetDataSet(surface_);
  BuildLocatorSequentially(locator_);
  cell_ = vtkSmartPointer<vtkGenericCell>::New();
}

Point3 SurfaceProjector::Project(const Point3& p) const
{
  vtkIdType cellId = -1;
  return Closest(p, cellId);
}

Point3 SurfaceProjector::Closest(const Point3& p, vtkIdType& cellId) const
{
  double closest[3];
  int subId = 0;
  double dist2 = 0;
  locator_->FindClosestPoint(p.data(), closest, cell_, cellId, subId, dist2);
  return Point3(closest[0], closest[1], closest[2]);
}

double SurfaceProjector::Distance(const Point3& p) const
{
  return (Project(p) - p).norm();
}

Point3 SurfaceProjector::Normal(const Point3& p) const
{
  vtkIdType cellId = -1;
  Closest(p, cellId); // fills cell_
  vtkPoints* points = cell_->GetPoints();
  if (cellId < 0 || points->GetNumberOfPoints() < 3)
    return Point3::Zero();
  Point3 a, b, c;
  points->GetPoint(0, a.data());
  points->GetPoint(1, b.data());
  points->GetPoint(2, c.data());
  const Point3 n = (b - a).cross(c - a);
  return n.norm() > 0 ? Point3(n.normalized()) : Point3::Zero();
}

void BuildLocatorSequentially(vtkAbstractCellLocator* locator)
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{std::string("Sequential")}, [&] { locator->BuildLocator(); });
}

} // namespace mmrep
