#include "mmrepPlane.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <stdexcept>

namespace mmrep
{

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
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (auto id : ids)
    c += mesh.nodes[static_cast<std::size_t>(id)];
  c /= static_cast<double>(ids.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (auto id : ids)
  {
    const Eigen::Vector3d d = mesh.nodes[static_cast<std::size_t>(id)] - c;
    cov += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  if (!(eig.eigenvalues()(1) > 1e-12 * std::max(eig.eigenvalues()(2), 1e-300)))
    throw std::invalid_argument("plane fit: the nodes of set '" + set + "' are collinear");
  Plane p;
  p.point = c;
  p.normal = eig.eigenvectors().col(0).normalized();
  if (p.normal.x() < 0)
    p.normal = -p.normal;
  return p;
}

} // namespace mmrep
