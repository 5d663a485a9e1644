// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The face frame of the atlas: an orthonormal frame attached to the symmetry plane, and the
// spherical (theta, phi) ray parameterisation of the face around a centre behind it.
//
// Local coordinates (u, v, w): u along the plane normal (patient's left), v anterior (in the plane),
// w superior (in the plane). The plane is u = 0, so mirroring is u -> -u, exactly.
// Ray (theta, phi) leaves the centre along cos(phi)(cos(theta) v + sin(theta) u) + sin(phi) w:
// theta = 0 is anterior in the plane, theta > 0 towards the patient's left, phi > 0 upwards.
#pragma once

#include "mmrepPlane.h"

#include <Eigen/Core>
#include <vtkOBBTree.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <optional>

namespace mmrep
{

struct FaceFrame
{
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();   // on the plane
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity(); // columns: left (plane normal), anterior, superior (LPS)

  // From the symmetry plane: left = plane normal, anterior = left x (0,0,1) normalised (LPS -y for
  // an upright head), superior = anterior x left; origin = projection of `centre` onto the plane.
  static FaceFrame FromPlane(const Plane& plane, const Eigen::Vector3d& centre);
  Eigen::Vector3d ToWorld(const Eigen::Vector3d& local) const { return origin + axes * local; }
  Eigen::Vector3d ToLocal(const Eigen::Vector3d& world) const { return axes.transpose() * (world - origin); }
  // 4x4 matrices (row-major, 16 values) for vtkTransform.
  void WorldToLocalMatrix(double m[16]) const;
  void LocalToWorldMatrix(double m[16]) const;
};

// A surface moved by a 4x4 matrix (row-major, as above), points in double precision.
vtkSmartPointer<vtkPolyData> TransformSurface(vtkPolyData* surface, const double matrix[16]);

inline Eigen::Vector3d RayDirection(double theta, double phi)
{
  return {std::cos(phi) * std::sin(theta), std::cos(phi) * std::cos(theta), std::sin(phi)};
}

// Exact ray/triangle intersections with a surface given in local coordinates (vtkOBBTree).
class SurfaceRays
{
public:
  explicit SurfaceRays(vtkPolyData* localSurface);
  // Farthest intersection of the segment a -> b from a (the outermost crossing when a is inside).
  std::optional<Eigen::Vector3d> Last(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // Nearest intersection of the segment a -> b from a, ignoring crossings closer than `skip` mm.
  std::optional<Eigen::Vector3d> First(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double skip = 0) const;
  vtkPolyData* Surface() const { return surface_; }

private:
  vtkSmartPointer<vtkPolyData> surface_;
  vtkSmartPointer<vtkOBBTree> tree_;
};

} // namespace mmrep
