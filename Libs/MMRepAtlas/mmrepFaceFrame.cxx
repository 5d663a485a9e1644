// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFaceFrame.h"

#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <Eigen/Geometry>

#include <stdexcept>

namespace mmrep
{

vtkSmartPointer<vtkPolyData> TransformSurface(vtkPolyData* surface, const double matrix[16])
{
  auto t = vtkSmartPointer<vtkTransform>::New();
  t->SetMatrix(matrix);
  auto f = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  f->SetInputData(surface);
  f->SetTransform(t);
  f->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  f->Update();
  vtkSmartPointer<vtkPolyData> out = f->GetOutput();
  return out;
}

FaceFrame FaceFrame::FromPlane(const Plane& plane, const Eigen::Vector3d& centre)
{
  FaceFrame f;
  const Eigen::Vector3d left = plane.normal.normalized();
  Eigen::Vector3d anterior = left.cross(Eigen::Vector3d::UnitZ());
  if (anterior.norm() < 1e-6)
    throw std::invalid_argument("face frame: the symmetry plane is horizontal");
  anterior.normalize();
  const Eigen::Vector3d superior = anterior.cross(left).normalized();
  f.axes.col(0) = left;
  f.axes.col(1) = anterior;
  f.axes.col(2) = superior;
  f.origin = plane.Project(centre);
  return f;
}

void FaceFrame::WorldToLocalMatrix(double m[16]) const
{
  const Eigen::Matrix3d r = axes.transpose();
  const Eigen::Vector3d t = -(r * origin);
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
      m[4 * i + j] = r(i, j);
    m[4 * i + 3] = t(i);
  }
  m[12] = m[13] = m[14] = 0;
  m[15] = 1;
}

void FaceFrame::LocalToWorldMatrix(double m[16]) const
{
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
      m[4 * i + j] = axes(i, j);
    m[4 * i + 3] = origin(i);
  }
  m[12] = m[13] = m[14] = 0;
  m[15] = 1;
}

SurfaceRays::SurfaceRays(vtkPolyData* localSurface) : surface_(localSurface)
{
  tree_ = vtkSmartPointer<vtkOBBTree>::New();
  tree_->SetDataSet(surface_);
  tree_->SetTolerance(1e-9);
  tree_->BuildLocator();
}

namespace
{
// All crossings of the segment, as distances from a (sorted, deterministic).
std::vector<double> Crossings(vtkOBBTree* tree, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto cells = vtkSmartPointer<vtkIdList>::New();
  double p0[3] = {a.x(), a.y(), a.z()}, p1[3] = {b.x(), b.y(), b.z()};
  tree->IntersectWithLine(p0, p1, points, cells);
  const Eigen::Vector3d dir = (b - a).normalized();
  std::vector<double> t;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    t.push_back((Eigen::Vector3d(p[0], p[1], p[2]) - a).dot(dir));
  }
  std::sort(t.begin(), t.end());
  return t;
}
} // namespace

std::optional<Eigen::Vector3d> SurfaceRays::Last(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const
{
  const auto t = Crossings(tree_, a, b);
  if (t.empty())
    return std::nullopt;
  return a + t.back() * (b - a).normalized();
}

std::optional<Eigen::Vector3d> SurfaceRays::First(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double skip) const
{
  for (double t : Crossings(tree_, a, b))
    if (t >= skip)
      return a + t * (b - a).normalized();
  return std::nullopt;
}

} // namespace mmrep
