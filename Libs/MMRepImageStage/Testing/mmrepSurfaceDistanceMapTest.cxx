// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Surface distance map vs exact distances to the triangles computed by VTK's cell locator.
#include "mmrepSurfaceDistanceMap.h"

#include <Eigen/Core>
#include <gtest/gtest.h>
#include <itkLinearInterpolateImageFunction.h>
#include <itkMultiThreaderBase.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkSphereSource.h>
#include <vtkStaticCellLocator.h>

#include <cmath>
#include <cstring>
#include <random>

namespace
{
vtkSmartPointer<vtkPolyData> Sphere(double radius, int resolution)
{
  vtkNew<vtkSphereSource> s;
  s->SetRadius(radius);
  s->SetCenter(3.3, -7.1, 12.4);
  s->SetThetaResolution(resolution);
  s->SetPhiResolution(resolution);
  s->Update();
  return s->GetOutput();
}

struct Exact
{
  explicit Exact(vtkPolyData* s)
  {
    locator->SetDataSet(s);
    locator->BuildLocator();
  }
  double operator()(const double p[3])
  {
    double closest[3], d2;
    vtkIdType cell;
    int sub;
    locator->FindClosestPoint(p, closest, cell, sub, d2);
    return std::sqrt(d2);
  }
  vtkNew<vtkStaticCellLocator> locator;
};

struct Errors
{
  double bandMax = 0, farMaxOver = 0, farMinUnder = 0;
  std::size_t band = 0, far = 0;
};

Errors Compare(vtkPolyData* surface, const mmrep::FloatImage* map, double bandWidth)
{
  Exact exact(surface);
  Errors e;
  const auto size = map->GetBufferedRegion().GetSize();
  // Every 3rd voxel along each axis keeps the test quick while covering band and far field.
  for (itk::IndexValueType k = 0; k < static_cast<itk::IndexValueType>(size[2]); k += 3)
    for (itk::IndexValueType j = 0; j < static_cast<itk::IndexValueType>(size[1]); j += 3)
      for (itk::IndexValueType i = 0; i < static_cast<itk::IndexValueType>(size[0]); i += 3)
      {
        mmrep::FloatImage::IndexType idx{{i, j, k}};
        mmrep::FloatImage::PointType p;
        map->TransformIndexToPhysicalPoint(idx, p);
        const double truth = exact(p.GetDataPointer());
        const double value = map->GetPixel(idx);
        if (truth <= bandWidth * 0.999)
        {
          e.bandMax = std::max(e.bandMax, std::abs(value - truth));
          ++e.band;
        }
        else if (truth > bandWidth * 1.001)
        {
          e.farMaxOver = std::max(e.farMaxOver, value - truth);
          e.farMinUnder = std::min(e.farMinUnder, value - truth);
          ++e.far;
        }
      }
  return e;
}
} // namespace

TEST(ImageStageDistanceMap, SphereExactInBandBoundedOutside)
{
  auto sphere = Sphere(20, 60);
  mmrep::SurfaceDistanceMapOptions o;
  o.spacing = 1.5;
  o.margin = 12;
  auto map = mmrep::ComputeSurfaceDistanceMap(sphere, o);
  const auto e = Compare(sphere, map, o.exactBand * o.spacing);
  EXPECT_GT(e.band, 200u);
  EXPECT_GT(e.far, 1000u);
  EXPECT_LT(e.bandMax, 1e-5 * 40); // float storage of values up to ~40 mm
  EXPECT_GE(e.farMinUnder, -1e-4); // |p-q| + d(q) never underestimates
  EXPECT_LE(e.farMaxOver, o.spacing);
  std::cout << "sphere: band max error " << e.bandMax << " mm, far overestimate max " << e.farMaxOver << " mm\n";
}

TEST(ImageStageDistanceMap, InterpolatedNearSurfaceAccuracy)
{
  // The registration samples the map by trilinear interpolation at mesh nodes close to the surface.
  auto surface = Sphere(30, 90);
  for (double spacing : {1.5, 0.5})
  {
    mmrep::SurfaceDistanceMapOptions o;
    o.spacing = spacing;
    o.margin = 5;
    auto map = mmrep::ComputeSurfaceDistanceMap(surface, o);
    auto interp = itk::LinearInterpolateImageFunction<mmrep::FloatImage, double>::New();
    interp->SetInputImage(map);
    Exact exact(surface);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    double sum = 0, maxErr = 0;
    const int samples = 4000;
    for (int s = 0; s < samples; ++s)
    {
      // Random point within one voxel of a random surface vertex.
      double p[3];
      surface->GetPoint(rng() % surface->GetNumberOfPoints(), p);
      for (double& c : p)
        c += u(rng) * spacing;
      itk::Point<double, 3> q(p);
      const double err = std::abs(interp->Evaluate(q) - exact(p));
      sum += err;
      maxErr = std::max(maxErr, err);
    }
    std::cout << "spacing " << spacing << " mm: interpolated error within one voxel of the surface: mean "
              << sum / samples << " mm, max " << maxErr << " mm\n";
    // Trilinear interpolation of an unsigned distance rounds off the V at the surface.
    EXPECT_LT(sum / samples, 0.15 * spacing);
    EXPECT_LT(maxErr, 0.9 * spacing); // at worst half the voxel diagonal
  }
}

TEST(ImageStageDistanceMap, SameBytesWhateverTheThreadCount)
{
  auto sphere = Sphere(15, 40);
  mmrep::SurfaceDistanceMapOptions o;
  o.spacing = 1.0;
  auto global = itk::MultiThreaderBase::GetGlobalDefaultNumberOfThreads();
  itk::MultiThreaderBase::SetGlobalDefaultNumberOfThreads(1);
  auto one = mmrep::ComputeSurfaceDistanceMap(sphere, o);
  itk::MultiThreaderBase::SetGlobalDefaultNumberOfThreads(4);
  auto four = mmrep::ComputeSurfaceDistanceMap(sphere, o);
  itk::MultiThreaderBase::SetGlobalDefaultNumberOfThreads(global);
  const auto n = one->GetBufferedRegion().GetNumberOfPixels();
  ASSERT_EQ(n, four->GetBufferedRegion().GetNumberOfPixels());
  EXPECT_EQ(0, std::memcmp(one->GetBufferPointer(), four->GetBufferPointer(), n * sizeof(float)));
}

TEST(ImageStageDistanceMap, GridCoversRegionPlusMargin)
{
  auto sphere = Sphere(10, 20);
  mmrep::SurfaceDistanceMapOptions o;
  o.spacing = 0.5;
  o.margin = 2;
  o.region = {8, 12, -8, -6, 10, 13}; // reaches the sphere (x = 13.3) through the margin
  auto map = mmrep::ComputeSurfaceDistanceMap(sphere, o);
  EXPECT_DOUBLE_EQ(map->GetOrigin()[0], 6);
  EXPECT_DOUBLE_EQ(map->GetOrigin()[1], -10);
  EXPECT_DOUBLE_EQ(map->GetOrigin()[2], 8);
  const auto size = map->GetBufferedRegion().GetSize();
  EXPECT_EQ(size[0], 17u); // (4 + 2*2) / 0.5 + 1
  EXPECT_EQ(size[1], 13u);
  EXPECT_EQ(size[2], 15u);
}

TEST(ImageStageDistanceMap, RejectsEmptySurface)
{
  vtkNew<vtkPolyData> empty;
  EXPECT_THROW(mmrep::ComputeSurfaceDistanceMap(empty, {}), std::runtime_error);
}

TEST(ImageStageDistanceMap, SignedSphereNegativeInsideExactInBand)
{
  auto sphere = Sphere(20, 60);
  mmrep::SurfaceDistanceMapOptions o;
  o.spacing = 1.5;
  o.margin = 8;
  o.signedDistance = true;
  auto map = mmrep::ComputeSurfaceDistanceMap(sphere, o);
  Exact exact(sphere);
  const Eigen::Vector3d centre(3.3, -7.1, 12.4);
  const auto size = map->GetBufferedRegion().GetSize();
  std::size_t wrongSign = 0, band = 0;
  double bandMax = 0;
  for (itk::IndexValueType k = 0; k < static_cast<itk::IndexValueType>(size[2]); k += 2)
    for (itk::IndexValueType j = 0; j < static_cast<itk::IndexValueType>(size[1]); j += 2)
      for (itk::IndexValueType i = 0; i < static_cast<itk::IndexValueType>(size[0]); i += 2)
      {
        mmrep::FloatImage::IndexType idx{{i, j, k}};
        mmrep::FloatImage::PointType p;
        map->TransformIndexToPhysicalPoint(idx, p);
        const double d = exact(p.GetDataPointer());
        // Inside the polygonal sphere: farther from the centre than... use the triangles' own
        // inside test: a point is inside when its distance to the centre is below the radius minus
        // the faceting error, outside when above the radius; skip the thin faceting shell.
        const double r = (Eigen::Vector3d(p[0], p[1], p[2]) - centre).norm();
        const float value = map->GetPixel(idx);
        if (r < 19.7)
          wrongSign += value >= 0;
        else if (r > 20.0)
          wrongSign += value <= 0;
        if (d <= 2.9)
        {
          bandMax = std::max(bandMax, std::abs(std::abs(value) - d));
          ++band;
        }
      }
  EXPECT_EQ(wrongSign, 0u);
  EXPECT_GT(band, 100u);
  EXPECT_LT(bandMax, 1e-4);
}

TEST(ImageStageDistanceMap, SignedNeedsAClosedSurface)
{
  vtkNew<vtkSphereSource> s;
  s->SetStartTheta(0);
  s->SetEndTheta(180); // half a sphere: open
  s->Update();
  mmrep::SurfaceDistanceMapOptions o;
  o.signedDistance = true;
  EXPECT_THROW(mmrep::ComputeSurfaceDistanceMap(s->GetOutput(), o), std::runtime_error);
}
