// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Planes, node-to-surface distances and control-point matching against known truths.
#include "mmrepControlPointMatch.h"
#include "mmrepPlane.h"
#include "mmrepSurfaceDistance.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>

#include <cmath>
#include <stdexcept>

using namespace mmrep;

TEST(CorePlane, FitPlaneFindsAKnownPlaneWithTheNormalToPatientLeft)
{
  // Points on the plane through (1, 2, 3) with normal -(1, 1, 0)/sqrt2: the fit must flip it to +x.
  const Eigen::Vector3d n = Eigen::Vector3d(-1, -1, 0).normalized();
  const Eigen::Vector3d u = Eigen::Vector3d(1, -1, 0).normalized(), w = Eigen::Vector3d::UnitZ();
  std::vector<Point3> points;
  for (int i = -3; i <= 3; ++i)
    for (int j = -2; j <= 2; ++j)
      points.push_back(Point3(1, 2, 3) + 0.7 * i * u + 1.3 * j * w);
  const Plane p = FitPlane(points);
  EXPECT_NEAR(p.normal.dot(-n), 1.0, 1e-12);
  EXPECT_GT(p.normal.x(), 0.0);
  EXPECT_NEAR(p.SignedDistance(Point3(1, 2, 3)), 0.0, 1e-12);
  EXPECT_NEAR((p.Mirror(Point3(1, 2, 3) + 2.0 * n) - (Point3(1, 2, 3) - 2.0 * n)).norm(), 0.0, 1e-12);

  FEMesh mesh;
  mesh.nodes = points;
  mesh.nodeSets["midsagittal"] = {0, 6, 17, 34};
  EXPECT_NEAR(FitPlaneToNodeSet(mesh, "midsagittal").normal.dot(-n), 1.0, 1e-12);
  EXPECT_THROW(FitPlane({Point3(0, 0, 0), Point3(1, 1, 1), Point3(2, 2, 2)}), std::invalid_argument);
  EXPECT_THROW(FitPlane({Point3(0, 0, 0), Point3(1, 1, 1)}), std::invalid_argument);
  EXPECT_THROW(FitPlaneToNodeSet(mesh, "absent"), std::invalid_argument);
}

TEST(CorePlane, SixNumbersGiveAUnitNormal)
{
  const Plane p = PlaneFromSixNumbers({1, 2, 3, 0, 3, 4}, "--plane");
  EXPECT_EQ(p.point, Eigen::Vector3d(1, 2, 3));
  EXPECT_NEAR((p.normal - Eigen::Vector3d(0, 0.6, 0.8)).norm(), 0.0, 1e-15);
  EXPECT_THROW(PlaneFromSixNumbers({1, 2, 3, 0, 0}, "--plane"), std::invalid_argument);
  EXPECT_THROW(PlaneFromSixNumbers({1, 2, 3, 0, 0, 0}, "--plane"), std::invalid_argument);
  EXPECT_THROW(PlaneFromSixNumbers({1, 2, NAN, 1, 0, 0}, "--plane"), std::invalid_argument);
  try
  {
    PlaneFromSixNumbers({1}, "--symmetryPlane");
    FAIL();
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("--symmetryPlane: ", 0), 0u) << e.what();
  }
}

TEST(CoreSurfaceDistance, NodesAboveASquareAtKnownHeights)
{
  // The square [-10, 10]^2 at z = 0 as two triangles; nodes above its inside and beside it.
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-10, -10, 0);
  points->InsertNextPoint(10, -10, 0);
  points->InsertNextPoint(10, 10, 0);
  points->InsertNextPoint(-10, 10, 0);
  vtkNew<vtkCellArray> triangles;
  const vtkIdType t1[3] = {0, 1, 2}, t2[3] = {0, 2, 3};
  triangles->InsertNextCell(3, t1);
  triangles->InsertNextCell(3, t2);
  vtkNew<vtkPolyData> square;
  square->SetPoints(points);
  square->SetPolys(triangles);
  FEMesh mesh;
  mesh.nodes = {{0, 0, 1}, {3, -2, 2}, {-1, 5, -3}, {13, 0, 4}}; // the last: 5 mm from the edge x = 10
  mesh.nodeSets["skin"] = {0, 1, 2, 3};
  const auto d = NodeSurfaceDistances(mesh.nodes, {3, 0}, square.GetPointer());
  ASSERT_EQ(d.size(), 2u);
  EXPECT_NEAR(d[0], 5.0, 1e-12);
  EXPECT_NEAR(d[1], 1.0, 1e-12);
  const SurfaceDistance s = MeasureSurfaceDistance(mesh, "skin", square.GetPointer());
  EXPECT_EQ(s.count, 4u);
  EXPECT_NEAR(s.mean, 11.0 / 4.0, 1e-12);
  EXPECT_NEAR(s.max, 5.0, 1e-12);
  EXPECT_NEAR(s.sigma, std::sqrt((1 + 4 + 9 + 25) / 4.0 - (11.0 / 4.0) * (11.0 / 4.0)), 1e-12);
  EXPECT_EQ(MeasureSurfaceDistance(mesh, "absent", square.GetPointer()).count, 0u);
  EXPECT_EQ(MeasureSurfaceDistance(mesh.nodes, {}, square.GetPointer()).count, 0u);
  vtkNew<vtkPolyData> empty;
  EXPECT_EQ(MeasureSurfaceDistance(mesh.nodes, {0}, empty.GetPointer()).count, 0u);
  EXPECT_THROW(MeasureSurfaceDistance(mesh, "skin", empty.GetPointer()), std::invalid_argument);
}

TEST(CoreControlPoints, MatchedByNameInTheLandmarksOrder)
{
  const std::vector<Landmark> atlas{{"A", Point3(0, 0, 0)}, {"B", Point3(1, 0, 0)}, {"C", Point3(2, 0, 0)}};
  const std::vector<Landmark> given{{"C", Point3(7, 7, 7)}, {"A", Point3(5, 5, 5)}, {"B", Point3(6, 6, 6)}};
  const auto targets = MatchControlPointsByName(atlas, given);
  ASSERT_EQ(targets.size(), 3u);
  EXPECT_EQ(targets[0], Point3(5, 5, 5));
  EXPECT_EQ(targets[1], Point3(6, 6, 6));
  EXPECT_EQ(targets[2], Point3(7, 7, 7));
  EXPECT_THROW(MatchControlPointsByName(atlas, {}), std::invalid_argument);
  EXPECT_THROW(MatchControlPointsByName({}, given), std::invalid_argument);
  EXPECT_THROW(MatchControlPointsByName(atlas, {given[0], given[1]}), std::invalid_argument); // B missing
  EXPECT_THROW(MatchControlPointsByName(atlas, {given[0], given[1], given[2], given[1]}),
               std::invalid_argument); // twice
  EXPECT_THROW(MatchControlPointsByName(atlas, {given[0], given[1], given[2], {"D", Point3(0, 0, 0)}}),
               std::invalid_argument); // not an atlas landmark
  EXPECT_THROW(MatchControlPointsByName(atlas, {given[0], given[1], given[2], {"", Point3(0, 0, 0)}}),
               std::invalid_argument); // unnamed
}
