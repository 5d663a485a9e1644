// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFaceMuscles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace mmrep
{
namespace
{
// A point `lateral` mm towards the patient's left and `up` mm upwards of a skin landmark, as ray
// angles (arc lengths on the face divided by the local radii).
MuscleControlPoint Offset(const FacePoint& base, const Eigen::Vector3d& centre, double lateral, double up, double depth)
{
  const double rho = std::hypot(base.local.x(), base.local.y() - centre.y());
  const double radius = (base.local - centre).norm();
  return {base.theta + lateral / rho, base.phi + up / radius, depth};
}

MuscleControlPoint Between(const MuscleControlPoint& a, const MuscleControlPoint& b, double f, double depth)
{
  return {a.theta + f * (b.theta - a.theta), a.phi + f * (b.phi - a.phi), depth};
}
} // namespace

double FaceMuscleMaximumForce(const std::string& name)
{
  constexpr double newtonsPerPound = 4.4482216152605;
  if (name == "ZygomaticusMajor")
    return 0.730 * newtonsPerPound; // smile, direct probe at the commissure (Neely & Pomerantz 2002)
  if (name.rfind("OrbicularisOris", 0) == 0)
    return 0.387 * newtonsPerPound / 4; // pucker at the commissure, shared by the side's four tracks
  return MuscleTrack::kDefaultMaximumForce;
}

std::vector<MuscleRule> FaceMuscleRules(const FaceLandmarkSet& lm, const Eigen::Vector3d& c)
{
  const FacePoint& corner = lm.lipCorner;
  const double cornerLateral = corner.local.x(); // mm from the plane
  auto at = [&](const FacePoint& base, double lateral, double up, double depth) {
    return Offset(base, c, lateral, up, depth);
  };
  // Point at the corner's height, `fraction` of its lateral offset from the midline, `up` mm above `base`'s level.
  auto fractionOfCorner = [&](const FacePoint& base, double fraction, double up, double depth) {
    MuscleControlPoint p = at(corner, -(1 - fraction) * cornerLateral, 0, depth);
    p.phi = at(base, 0, up, depth).phi;
    return p;
  };
  const MuscleControlPoint modiolus = at(corner, 8, 0, 0.6);
  std::vector<MuscleRule> rules;
  auto ring = [&](const std::string& name, const FacePoint& a, const FacePoint& b, double end, double arch,
                  const MuscleControlPoint& to, double depth) {
    MuscleControlPoint start{0, 0.5 * (a.phi + b.phi), depth};
    MuscleControlPoint tip = to;
    tip.depth = depth;
    MuscleControlPoint mid = Between(start, tip, 0.5, depth);
    mid.phi += arch / (corner.local - c).norm();
    (void)end;
    rules.push_back({name, {start, mid, tip}, true});
  };
  ring("OrbicularisOrisPeripheralisUpper", lm.subnasale, lm.upperLip, 0, 2.0, modiolus, 0.75);
  ring("OrbicularisOrisPeripheralisLower", lm.lowerLip, lm.labiomental, 0, -2.0, modiolus, 0.75);
  {
    const MuscleControlPoint start = at(lm.stomion, 0, 1.5, 0.55);
    MuscleControlPoint tip = at(corner, 0, 0, 0.55);
    MuscleControlPoint mid = Between({0, start.phi, 0.55}, tip, 0.5, 0.55);
    mid.phi += 1.0 / (corner.local - c).norm();
    rules.push_back({"OrbicularisOrisMarginalisUpper", {{0, start.phi, 0.55}, mid, tip}, true});
  }
  {
    const MuscleControlPoint start = at(lm.stomion, 0, -1.5, 0.55);
    MuscleControlPoint tip = at(corner, 0, 0, 0.55);
    MuscleControlPoint mid = Between({0, start.phi, 0.55}, tip, 0.5, 0.55);
    mid.phi -= 1.0 / (corner.local - c).norm();
    rules.push_back({"OrbicularisOrisMarginalisLower", {{0, start.phi, 0.55}, mid, tip}, true});
  }
  // Inserts into the skin above the corner (a cutaneous muscle): with its end in the hypodermis at the
  // modiolus the skin corner followed the muscle's end by less than half (Resources/Atlas/README.md).
  rules.push_back({"ZygomaticusMajor", {at(lm.eyeOuter, 10, -22, 0.95), at(corner, 4, 2, 0.3)}, false});
  rules.push_back({"Risorius", {at(corner, 40, 0, 0.6), at(corner, 8, 0, 0.55)}, false});
  {
    MuscleControlPoint origin = Between({lm.eyeInner.theta, 0, 0}, {lm.eyeOuter.theta, 0, 0}, 0.5, 0.95);
    origin.phi = lm.orbitBottomPhi - 6.0 / (lm.orbitCentre.local - c).norm();
    rules.push_back({"LevatorLabiiSuperioris", {origin, fractionOfCorner(lm.upperLip, 0.45, 3, 0.6)}, false});
  }
  {
    MuscleControlPoint end = at(lm.subnasale, 10, 0, 0.6);
    rules.push_back({"LevatorLabiiSuperiorisAlaequeNasi", {at(lm.eyeInner, -3, -4, 0.95), end}, false});
  }
  rules.push_back({"LevatorAnguliOris", {fractionOfCorner(lm.subnasale, 0.8, 8, 0.95), at(corner, 6, 3, 0.6)}, false});
  {
    MuscleControlPoint origin = at(corner, 12, 0, 0.95);
    origin.phi = at(lm.pogonion, 0, -6, 0.95).phi;
    rules.push_back({"DepressorAnguliOris", {origin, at(corner, 6, -2, 0.6)}, false});
  }
  rules.push_back({"DepressorLabiiInferioris",
                   {fractionOfCorner(lm.pogonion, 0.6, -4, 0.95), fractionOfCorner(lm.lowerLip, 0.35, -2, 0.6)},
                   false});
  rules.push_back({"Mentalis", {at(lm.labiomental, 5, -3, 0.95), at(lm.pogonion, 7, -4, 0.35)}, false});
  rules.push_back({"Buccinator", {at(corner, 35, 0, 0.95), at(corner, 8, 0, 0.7)}, false});
  for (auto& rule : rules)
    rule.maximumForce = FaceMuscleMaximumForce(rule.name);
  return rules;
}

void AddFaceMuscles(FEMesh& mesh, const FaceGrid& grid, const FaceFrame& frame, const std::vector<MuscleRule>& rules,
                    double spacing)
{
  auto& midsagittal = mesh.nodeSets["midsagittal"];
  // Tracks that meet at one point (the modiolus at the mouth corner) share its node: FE programs
  // (Gmsh's check among them) refuse coincident nodes.
  std::map<std::array<double, 3>, std::int32_t> muscleNodeAt;
  for (const auto& rule : rules)
  {
    // Dense samples of the control polyline in (theta, phi, depth), then equal arc-length points.
    std::vector<MuscleControlPoint> dense;
    for (std::size_t s = 0; s + 1 < rule.points.size(); ++s)
      for (int k = 0; k < 100; ++k)
        dense.push_back(Between(rule.points[s], rule.points[s + 1], k / 100.0,
                                rule.points[s].depth + k / 100.0 * (rule.points[s + 1].depth - rule.points[s].depth)));
    dense.push_back(rule.points.back());
    std::vector<double> arc{0};
    Eigen::Vector3d prev = grid.Position(grid.Locate(dense[0].theta, dense[0].phi, dense[0].depth));
    for (std::size_t k = 1; k < dense.size(); ++k)
    {
      const Eigen::Vector3d p = grid.Position(grid.Locate(dense[k].theta, dense[k].phi, dense[k].depth));
      arc.push_back(arc.back() + (p - prev).norm());
      prev = p;
    }
    const int segments = std::max(2, static_cast<int>(std::lround(arc.back() / spacing)));
    std::vector<MuscleControlPoint> track;
    for (int n = 0; n <= segments; ++n)
    {
      const double target = arc.back() * n / segments;
      std::size_t k = std::upper_bound(arc.begin(), arc.end(), target) - arc.begin();
      k = std::clamp<std::size_t>(k, 1, arc.size() - 1);
      const double f = arc[k] > arc[k - 1] ? (target - arc[k - 1]) / (arc[k] - arc[k - 1]) : 0;
      track.push_back(
        Between(dense[k - 1], dense[k], f, dense[k - 1].depth + f * (dense[k].depth - dense[k - 1].depth)));
    }
    if (rule.startsOnMidline)
      track.front().theta = 0;

    std::int32_t sharedFirst = -1;
    for (int side = 0; side < 2; ++side)
    {
      MuscleTrack muscle;
      muscle.maximumForce = rule.maximumForce;
      const std::string name = rule.name + (side == 0 ? "_L" : "_R");
      auto& cables = mesh.elementSets[name];
      for (std::size_t n = 0; n < track.size(); ++n)
      {
        const auto location = grid.Locate(track[n].theta, track[n].phi, track[n].depth);
        const bool onPlane = track[n].theta == 0;
        std::int32_t node;
        if (onPlane && side == 1)
          node = sharedFirst;
        else
        {
          Eigen::Vector3d local = grid.Position(location);
          if (onPlane)
            local.x() = 0;
          if (side == 1)
            local.x() = -local.x();
          const Eigen::Vector3d world = frame.ToWorld(local);
          const auto [at, added] = muscleNodeAt.emplace(std::array<double, 3>{world.x(), world.y(), world.z()},
                                                        static_cast<std::int32_t>(mesh.nodes.size()));
          node = at->second;
          if (added)
            mesh.nodes.push_back(world);
          if (onPlane)
          {
            sharedFirst = node;
            if (added)
              midsagittal.push_back(node);
          }
        }
        muscle.nodes.push_back(node);
        muscle.embedding.push_back(grid.Embed(location, side));
        if (n > 0)
        {
          Element cable;
          cable.type = ElementType::Cable;
          cable.nodes[0] = muscle.nodes[n - 1];
          cable.nodes[1] = node;
          muscle.cables.push_back(static_cast<std::int32_t>(mesh.elements.size()));
          cables.push_back(muscle.cables.back());
          mesh.elements.push_back(cable);
        }
      }
      mesh.muscles[name] = muscle;
    }
    // Point n of the left track mirrors point n of the right one (shared on the plane).
    const auto& left = mesh.muscles[rule.name + "_L"].nodes;
    const auto& right = mesh.muscles[rule.name + "_R"].nodes;
    for (std::size_t n = 0; n < left.size(); ++n)
      mesh.SetMirrorPartners(left[n], right[n]);
  }
}

} // namespace mmrep
