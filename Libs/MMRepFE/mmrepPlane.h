// A plane (the mid-sagittal plane of a head or of a symmetric FE model) and its least-squares fit
// to a node set of an FE mesh.
#pragma once

#include "mmrepFEMesh.h"

#include <Eigen/Core>

#include <string>

namespace mmrep
{

struct Plane
{
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // a point on the plane (LPS mm)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX(); // unit normal, pointing to the patient's left (+x side)

  double SignedDistance(const Eigen::Vector3d& p) const { return normal.dot(p - point); }
  Eigen::Vector3d Mirror(const Eigen::Vector3d& p) const { return p - 2.0 * SignedDistance(p) * normal; }
  Eigen::Vector3d Project(const Eigen::Vector3d& p) const { return p - SignedDistance(p) * normal; }
};

// Least-squares plane through a node set (e.g. the atlas's `midsagittal` nodes), normal towards
// +x (patient left). Throws std::invalid_argument when the set is missing, has < 3 nodes, refers to
// a missing node or its nodes are collinear.
Plane FitPlaneToNodeSet(const FEMesh& mesh, const std::string& set);

} // namespace mmrep
