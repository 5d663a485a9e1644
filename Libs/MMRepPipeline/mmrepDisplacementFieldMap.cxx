// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepDisplacementFieldMap.h"
#include "mmrepElasticTransform.h"

#include <itkVectorLinearInterpolateImageFunction.h>

#include <sstream>
#include <stdexcept>

namespace mmrep
{

PointMap DisplacementFieldMap(const DisplacementField* field)
{
  if (field == nullptr || field->GetLargestPossibleRegion().GetNumberOfPixels() == 0)
    throw std::invalid_argument("displacement field: empty field");
  using Interpolator = itk::VectorLinearInterpolateImageFunction<DisplacementField, double>;
  auto interpolator = Interpolator::New();
  interpolator->SetInputImage(field);
  DisplacementField::ConstPointer keep = field;
  return [interpolator, keep](const Point3& x) -> Point3 {
    Interpolator::PointType p;
    for (unsigned a = 0; a < 3; ++a)
      p[a] = x[a];
    if (!interpolator->IsInsideBuffer(p))
    {
      std::ostringstream s;
      s << "displacement field: point (" << x.x() << ", " << x.y() << ", " << x.z()
        << ") lies outside the field's grid";
      throw std::out_of_range(s.str());
    }
    const auto u = interpolator->Evaluate(p);
    return {x.x() + u[0], x.y() + u[1], x.z() + u[2]};
  };
}

} // namespace mmrep

#include <itkImageRegionIteratorWithIndex.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>

#include "mmrepResourceBudget.h"

namespace mmrep
{

namespace
{
// Voxels per axis, in floating point so that a tiny spacing cannot wrap the count around.
std::vector<double> GridCounts(const Point3& lo, const Point3& hi, double margin, double spacing)
{
  std::vector<double> counts;
  for (unsigned a = 0; a < 3; ++a)
    counts.push_back(std::ceil((hi[a] - lo[a] + 2 * margin) / spacing) + 1);
  return counts;
}

void Bounds(const std::vector<Point3>& points, Point3& lo, Point3& hi)
{
  lo = points.front();
  hi = points.front();
  for (const auto& p : points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
}
} // namespace

void CheckDisplacementFieldSize(const std::vector<Point3>& points, double margin, double spacing,
                                const std::string& parameter)
{
  if (points.empty())
    return;
  Point3 lo, hi;
  Bounds(points, lo, hi);
  char what[128];
  std::snprintf(what, sizeof what, "%s %g: the displacement field would be", parameter.c_str(), spacing);
  CheckMemoryNeed(what, GridCounts(lo, hi, margin, spacing), sizeof(DisplacementField::PixelType));
}

DisplacementField::Pointer SampleDisplacementField(const PointMap& map, const std::vector<Point3>& points,
                                                   double margin, double spacing)
{
  if (points.empty() || !(spacing > 0) || !(margin >= 0))
    throw std::invalid_argument("displacement field: no points, or spacing <= 0 / margin < 0");
  Point3 lo, hi;
  Bounds(points, lo, hi);
  CheckMemoryNeed("displacement field", GridCounts(lo, hi, margin, spacing), sizeof(DisplacementField::PixelType));
  auto field = DisplacementField::New();
  DisplacementField::RegionType region;
  DisplacementField::PointType origin;
  for (unsigned a = 0; a < 3; ++a)
  {
    origin[a] = lo[a] - margin;
    region.SetSize(a, static_cast<itk::SizeValueType>(std::ceil((hi[a] - lo[a] + 2 * margin) / spacing)) + 1);
  }
  field->SetRegions(region);
  field->SetOrigin(origin);
  field->SetSpacing(spacing);
  field->Allocate();
  FillDisplacementField(field, map);
  return field;
}

} // namespace mmrep
