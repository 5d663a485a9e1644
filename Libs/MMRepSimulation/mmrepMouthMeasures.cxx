// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Mouth width, lip aperture, protrusion and lip gap of a simulated gesture.
#include "mmrepMouthMeasures.h"

#include "mmrepHalfModel.h"
#include "mmrepLipContact.h"
#include "mmrepPlane.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mmrep::simulation
{

MouthMeasures MeasureMouth(const FEMesh& mesh, const ActivationResult& result)
{
  MouthMeasures m;
  const bool half = IsHalfModel(mesh);
  Plane plane = FitPlaneToNodeSet(mesh, half ? kSymmetryBoundarySet : "midsagittal");
  if (plane.normal.x() < 0)
    plane.normal = -plane.normal;
  const Point3 anterior = plane.normal.cross(Point3::UnitZ()).normalized();
  auto landmark = [&](const std::string& name) -> const LandmarkMotion* {
    for (const auto& l : result.landmarks)
      if (l.name == name)
        return &l;
    return nullptr;
  };
  const auto* upper = landmark("UpperLipCenter");
  const auto* lower = landmark("LowerLipCenter");
  m.upperProtrusion = upper ? upper->displacement.dot(anterior) : std::numeric_limits<double>::quiet_NaN();
  m.lowerProtrusion = lower ? lower->displacement.dot(anterior) : std::numeric_limits<double>::quiet_NaN();
  if (const auto* corner = landmark("LeftLipCorner"))
  {
    m.hasCorners = true;
    m.leftCorner = corner->displacement;
    const Point3 rightRest = plane.Mirror(corner->rest);
    // Mirror of a displacement: reflect its normal component.
    const Point3 mirrored = corner->displacement - 2 * corner->displacement.dot(plane.normal) * plane.normal;
    m.rightCorner = half ? mirrored : InterpolateDisplacement(mesh, result.displacements, rightRest).displacement;
    m.restWidth = (corner->rest - rightRest).norm();
    m.width = (corner->rest + m.leftCorner - rightRest - m.rightCorner).norm();
  }
  if (HasMouthSlit(mesh))
  {
    m.hasSlit = true;
    const auto& skin = mesh.nodeSets.count("skin") ? mesh.nodeSets.at("skin") : std::vector<std::int32_t>{};
    auto onSkin = [&](std::int32_t n) { return std::binary_search(skin.begin(), skin.end(), n); };
    auto at = [&](std::int32_t n) {
      return Point3(mesh.nodes[static_cast<std::size_t>(n)] + result.displacements[static_cast<std::size_t>(n)]);
    };
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& [u, l] : MouthTwins(mesh))
    {
      if (!onSkin(u))
        continue;
      const double separation = (at(u) - at(l)).norm();
      const double offset = plane.SignedDistance(mesh.nodes[static_cast<std::size_t>(u)]);
      if (std::abs(offset) < 1e-3)
        m.apertureHeight = std::max(m.apertureHeight, separation);
      if (separation > 1.0) // parted
      {
        lo = std::min(lo, offset);
        hi = std::max(hi, offset);
      }
    }
    if (hi >= lo)
      m.apertureWidth = half ? 2 * std::max(std::abs(lo), std::abs(hi)) : hi - lo;
    const LipGap gap = MeasureLipGap(mesh, result.displacements);
    m.minimumLipGap = gap.minimum;
    m.meanLipGap = gap.mean;
  }
  return m;
}

} // namespace mmrep::simulation
