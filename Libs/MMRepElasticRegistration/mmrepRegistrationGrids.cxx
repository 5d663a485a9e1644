// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepRegistrationGrids.h"

#include "mmrepSurfaceDistanceMap.h"

#include <array>
#include <cmath>

namespace mmrep
{

void CheckSubjectMapGrids(const SubjectData& subject, double margin, double spacing, const std::string& parameter)
{
  for (vtkPolyData* surface : {subject.skin.Get(), subject.skull.Get()})
  {
    std::array<double, 6> bounds;
    surface->GetBounds(bounds.data());
    CheckDistanceMapGrid(bounds, margin, spacing, parameter);
  }
}

TransformGrid TransformGridAround(const std::vector<Point3>& points, double margin, double spacing)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& n : points)
  {
    lo = lo.cwiseMin(n);
    hi = hi.cwiseMax(n);
  }
  TransformGrid grid;
  grid.spacing = spacing;
  grid.origin = lo - Eigen::Vector3d::Constant(margin);
  for (unsigned a = 0; a < 3; ++a)
    grid.counts.push_back(std::ceil((hi[a] - lo[a] + 2 * margin) / spacing) + 1);
  return grid;
}

itk::Image<float, 3>::Pointer TransformGrid::Image() const
{
  auto image = itk::Image<float, 3>::New();
  itk::Image<float, 3>::RegionType region;
  itk::Image<float, 3>::PointType start;
  for (unsigned a = 0; a < 3; ++a)
  {
    start[a] = origin[a];
    region.SetSize(a, static_cast<itk::SizeValueType>(counts[a]));
  }
  image->SetRegions(region);
  image->SetOrigin(start);
  image->SetSpacing(spacing);
  return image;
}

} // namespace mmrep
