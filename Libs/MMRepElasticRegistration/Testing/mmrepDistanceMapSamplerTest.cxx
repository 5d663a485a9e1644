// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Trilinear sampling of a distance map: exact on linear fields (any direction matrix), gradient
// equal to the analytic one, and the continuation outside the map's box.
#include "mmrepDistanceMapSampler.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <itkImageRegionIteratorWithIndex.h>

#include <random>

using namespace mmrep;

namespace
{
// A 10×12×14 map, spacing (1, 1.5, 2), rotated direction, holding f(x) = a·x + c.
FloatImage::Pointer LinearMap(const Eigen::Vector3d& a, double c, Eigen::Matrix3d* direction)
{
  auto map = FloatImage::New();
  FloatImage::RegionType region;
  region.SetSize({{10, 12, 14}});
  map->SetRegions(region);
  const double spacing[3] = {1.0, 1.5, 2.0};
  map->SetSpacing(spacing);
  const double origin[3] = {-3.0, 2.0, 5.0};
  map->SetOrigin(origin);
  *direction = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 2).normalized()).toRotationMatrix();
  FloatImage::DirectionType d;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k)
      d(r, k) = (*direction)(r, k);
  map->SetDirection(d);
  map->Allocate();
  itk::ImageRegionIteratorWithIndex<FloatImage> it(map, region);
  for (; !it.IsAtEnd(); ++it)
  {
    FloatImage::PointType p;
    map->TransformIndexToPhysicalPoint(it.GetIndex(), p);
    it.Set(static_cast<float>(a.dot(Eigen::Vector3d(p[0], p[1], p[2])) + c));
  }
  return map;
}
} // namespace

TEST(ElasticDistanceMapSampler, ReproducesLinearFieldsAndContinuesOutside)
{
  const Eigen::Vector3d a(0.3, -0.2, 0.5);
  Eigen::Matrix3d direction;
  const auto map = LinearMap(a, 40.0, &direction);
  const DistanceMapSampler sampler(map);
  const Eigen::Vector3d origin(-3, 2, 5), extent(9 * 1.0, 11 * 1.5, 13 * 2.0);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 1000; ++k)
  {
    const Eigen::Vector3d local(u(rng) * extent.x(), u(rng) * extent.y(), u(rng) * extent.z());
    const Eigen::Vector3d x = origin + direction * local;
    Eigen::Vector3d g;
    const double v = sampler.Value(x, &g);
    EXPECT_NEAR(v, a.dot(x) + 40.0, 1e-4); // float storage
    EXPECT_NEAR((g - a).norm(), 0.0, 1e-4);
  }
  // Outside: border value + distance to the box, gradient along the outward offset.
  const Eigen::Vector3d corner = origin + direction * extent;
  const Eigen::Vector3d out = direction * Eigen::Vector3d(3, 0, 0);
  Eigen::Vector3d g;
  const double v = sampler.Value(corner + out, &g);
  EXPECT_NEAR(v, a.dot(corner) + 40.0 + 3.0, 1e-4);
  EXPECT_NEAR((g - out.normalized()).norm(), 0.0, 1e-9);
}
