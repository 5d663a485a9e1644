// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Jaw: the mandible's rigid rotation about the condylar axis.
#include "mmrepJaw.h"

#include "mmrepHalfModel.h"

#include <cmath>
#include <stdexcept>

namespace mmrep
{
namespace
{

const std::vector<std::int32_t>* NonEmpty(const FEMesh& mesh, const std::string& name)
{
  const auto it = mesh.nodeSets.find(name);
  return it == mesh.nodeSets.end() || it->second.empty() ? nullptr : &it->second;
}

Point3 Centroid(const FEMesh& mesh, const std::vector<std::int32_t>& ids)
{
  Point3 c = Point3::Zero();
  for (const auto n : ids)
    c += mesh.nodes[static_cast<std::size_t>(n)];
  return c / static_cast<double>(ids.size());
}

} // namespace

bool HasJaw(const FEMesh& mesh)
{
  const auto* axis = NonEmpty(mesh, kJawAxisSet);
  return NonEmpty(mesh, kMandibleSet) && NonEmpty(mesh, kMaxillaSet) && axis &&
         (axis->size() == 2 || (axis->size() == 1 && IsHalfModel(mesh)));
}

Eigen::Isometry3d JawRotation(const FEMesh& mesh, double degrees)
{
  if (!HasJaw(mesh))
    throw std::invalid_argument("the model has no jaw (node sets 'mandible', 'maxilla' and a two-node 'jawAxis'): "
                                "rebuild it from the current atlas");
  const auto& axisNodes = mesh.nodeSets.at(kJawAxisSet);
  const Point3 left = mesh.nodes[static_cast<std::size_t>(axisNodes[0])];
  // On a half model the right condyle is the left one's mirror image: the axis is the plane normal.
  const Point3 axis = axisNodes.size() == 2
                        ? Point3((left - mesh.nodes[static_cast<std::size_t>(axisNodes[1])]).normalized())
                        : SymmetryPlaneOf(mesh).normal;
  const Point3 mandible = Centroid(mesh, mesh.nodeSets.at(kMandibleSet));
  const Point3 maxilla = Centroid(mesh, mesh.nodeSets.at(kMaxillaSet));
  const double angle = degrees * M_PI / 180.0;
  auto about = [&](double a) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translate(left).rotate(Eigen::AngleAxisd(a, axis)).translate(-left);
    return t;
  };
  // Opening moves the mandible away from the maxilla: test with a small angle.
  const double probe = 0.05;
  const bool forward = ((about(probe) * mandible) - maxilla).norm() >= (mandible - maxilla).norm();
  return about(forward ? angle : -angle);
}

} // namespace mmrep
