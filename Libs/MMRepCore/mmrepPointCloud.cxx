// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepPointCloud.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>

namespace mmrep
{

vtkSmartPointer<vtkPolyData> PointCloud(const std::vector<Point3>& positions)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& p : positions)
  {
    const vtkIdType id = points->InsertNextPoint(p.data());
    verts->InsertNextCell(1, &id);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  return poly;
}

} // namespace mmrep
