// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepPlane.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <stdexcept>

namespace mmrep
{

Plane FitPlane(const std::vector<Point3>& points, const std::string& what)
{
  if (points.size() < 3)
    throw std::invalid_argument(what + ": fewer than 3 points");
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : points)
    c += p;
  c /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : points)
  {
    const Eigen::Vector3d d = p - c;
    cov += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  if (!(eig.eigenvalues()(1) > 1e-12 * std::max(eig.eigenvalues()(2), 1e-300)))
    throw std::invalid_argument(what + ": the points are collinear");
  Plane p;
  p.point = c;
  p.normal = eig.eigenvectors().col(0).normalized();
  if (p.normal.x() < 0)
    p.normal = -p.normal;
  return p;
}

Plane FitPlaneToNodeSet(const FEMesh& mesh, const std::string& set)
{
  const auto it = mesh.nodeSets.find(set);
  if (it == mesh.nodeSets.end() || it->second.empty())
    throw std::invalid_argument("plane fit: the mesh has no node set '" + set + "' (or it is empty)");
  const auto& ids = it->second;
  for (auto id : ids)
    if (id < 0 || static_cast<std::size_t>(id) >= mesh.nodes.size())
      throw std::invalid_argument("plane fit: node set '" + set + "' refers to a missing node");
  if (ids.size() < 3)
    throw std::invalid_argument("plane fit: node set '" + set + "' has fewer than 3 nodes");
  std::vector<Point3> points;
  points.reserve(ids.size());
  for (auto id : ids)
    points.push_back(mesh.nodes[static_cast<std::size_t>(id)]);
  try
  {
    return FitPlane(points);
  }
  catch (const std::invalid_argument&)
  {
    throw std::invalid_argument("plane fit: the nodes of set '" + set + "' are collinear");
  }
}

Plane PlaneFromSixNumbers(const std::vector<double>& values, const std::string& what)
{
  if (values.size() != 6)
    throw std::invalid_argument(what + ": expected six numbers (point x,y,z and normal nx,ny,nz), got " +
                                std::to_string(values.size()));
  Plane p;
  p.point = Eigen::Vector3d(values[0], values[1], values[2]);
  p.normal = Eigen::Vector3d(values[3], values[4], values[5]);
  if (!p.point.allFinite() || !p.normal.allFinite() || !(p.normal.norm() > 1e-9))
    throw std::invalid_argument(what + ": the normal must be finite and non-zero");
  p.normal.normalize();
  return p;
}

} // namespace mmrep
