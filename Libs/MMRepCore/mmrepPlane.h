// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// A plane (the mid-sagittal plane of a head or of a symmetric FE model), its least-squares fit to
// points or to a node set of an FE mesh, and its six-number form (point, normal) of the modules.
#pragma once

#include "mmrepFEMesh.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mmrep
{

struct Plane
{
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // a point on the plane (LPS mm)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX(); // unit normal, pointing to the patient's left (+x side)

  double SignedDistance(const Eigen::Vector3d& p) const { return normal.dot(p - point); }
  Eigen::Vector3d Mirror(const Eigen::Vector3d& p) const { return p - 2.0 * SignedDistance(p) * normal; }
  Eigen::Vector3d Project(const Eigen::Vector3d& p) const { return p - SignedDistance(p) * normal; }
};

// Least-squares plane through points (centroid, smallest principal axis), normal towards +x
// (patient left). Throws std::invalid_argument("<what>: ...") for fewer than 3 points or collinear ones.
Plane FitPlane(const std::vector<Point3>& points, const std::string& what = "plane fit");

// FitPlane of a node set (e.g. the atlas's `midsagittal` nodes). Throws std::invalid_argument when
// the set is missing, has < 3 nodes, refers to a missing node or its nodes are collinear.
Plane FitPlaneToNodeSet(const FEMesh& mesh, const std::string& set);

// The plane given as six numbers (point x,y,z, normal x,y,z), normal made unit length. Throws
// std::invalid_argument("<what>: ...") unless there are six finite numbers and a non-zero normal.
Plane PlaneFromSixNumbers(const std::vector<double>& values, const std::string& what);

} // namespace mmrep
