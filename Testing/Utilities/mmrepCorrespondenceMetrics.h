// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Test and benchmark helper: how far a registered atlas is from the truth, node by node, on the
// fitted (left) half of the atlas: node groups (all, skin, lips, skull, muscle points, insertions),
// their errors against a truth map (mean / p95 / max), surface errors of the half or the whole,
// control-point errors and muscle waviness (deviation of each interior track point from the best
// similarity of its ±2 neighbours' atlas positions onto their registered positions).
#pragma once

#include "mmrepAtlasRegistration.h"
#include "mmrepFEMesh.h"
#include "mmrepSymmetryPlane.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mmrep::bench
{

struct Spread
{
  double mean = 0, p95 = 0, max = 0;
  std::size_t count = 0;
};

inline Spread SpreadOf(std::vector<double> v)
{
  Spread s;
  s.count = v.size();
  if (v.empty())
    return s;
  double sum = 0;
  for (double x : v)
    sum += x;
  s.mean = sum / static_cast<double>(v.size());
  std::sort(v.begin(), v.end());
  s.max = v.back();
  s.p95 = v[std::min(v.size() - 1, static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(v.size()))) - 1)];
  return s;
}

inline double PlaneAngleDegrees(const Plane& a, const Plane& b)
{
  return std::acos(std::min(1.0, std::abs(a.normal.normalized().dot(b.normal.normalized())))) * 180.0 / M_PI;
}

// Distance between the planes at the centroid of the points (projected on a).
inline double PlaneOffset(const Plane& a, const Plane& b, const std::vector<Landmark>& at)
{
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : at)
    c += p.position / static_cast<double>(at.size());
  return std::abs(b.SignedDistance(a.Project(c)));
}

class AtlasGroups
{
public:
  static constexpr double kPlaneTolerance = 1e-3; // mm: plane nodes belong to the fitted half

  AtlasGroups(const FEMesh& atlas, const Plane& atlasPlane) : atlas_(atlas)
  {
    std::vector<char> left(atlas.nodes.size(), 0);
    for (std::size_t i = 0; i < atlas.nodes.size(); ++i)
      left[i] = atlasPlane.SignedDistance(atlas.nodes[i]) >= -kPlaneTolerance;
    auto half = [&](const std::vector<std::int32_t>& ids) {
      std::vector<std::int32_t> out;
      for (auto id : ids)
        if (left[static_cast<std::size_t>(id)])
          out.push_back(id);
      return out;
    };
    std::vector<std::int32_t> all(atlas.nodes.size());
    for (std::size_t i = 0; i < all.size(); ++i)
      all[i] = static_cast<std::int32_t>(i);
    std::vector<std::int32_t> muscle, insertions;
    for (const auto& [name, track] : atlas.muscles)
    {
      muscle.insert(muscle.end(), track.nodes.begin(), track.nodes.end());
      insertions.push_back(track.nodes.front());
      insertions.push_back(track.nodes.back());
    }
    for (auto* v : {&muscle, &insertions})
    {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    whole_["all"] = all;
    whole_["muscle"] = muscle;
    whole_["insertions"] = insertions;
    for (const char* set : {"skin", "lips", "skull"})
      whole_[set] = atlas.nodeSets.at(set);
    for (const auto& [name, ids] : whole_)
      half_[name] = half(ids);
    for (const auto& [name, track] : atlas.muscles)
      if (left[static_cast<std::size_t>(track.nodes[track.nodes.size() / 2])])
        tracks_.push_back(&track);
  }

  std::size_t Size(const std::string& group) const { return half_.at(group).size(); }
  const std::vector<std::int32_t>& Half(const std::string& group) const { return half_.at(group); }

  // |mesh node − truth(node)| over the group's fitted-half nodes.
  Spread NodeError(const FEMesh& mesh, const std::string& group,
                   const std::function<Eigen::Vector3d(std::size_t)>& truth) const
  {
    std::vector<double> e;
    for (auto id : half_.at(group))
      e.push_back((mesh.nodes[static_cast<std::size_t>(id)] - truth(static_cast<std::size_t>(id))).norm());
    return SpreadOf(e);
  }

  SurfaceDistance SurfaceError(const FEMesh& mesh, const std::string& set, vtkPolyData* surface, bool half) const
  {
    return MeasureSurfaceDistance(mesh.nodes, half ? half_.at(set) : whole_.at(set), surface);
  }

  std::pair<double, double> ControlPointError(const FEMesh& mesh, const std::vector<Landmark>& targets) const
  {
    double sum = 0, worst = 0;
    std::size_t n = 0;
    for (const auto& l : mesh.landmarks)
      for (const auto& t : targets)
        if (t.name == l.name)
        {
          const double e = (l.position - t.position).norm();
          sum += e;
          worst = std::max(worst, e);
          ++n;
        }
    return {n ? sum / static_cast<double>(n) : 0.0, worst};
  }

  // Per fitted-half track, the largest deviation of an interior point from the similarity fitted to
  // its window of ±2 track points (atlas → mesh); spread over the tracks of those maxima.
  Spread Waviness(const FEMesh& mesh) const
  {
    std::vector<double> perTrack;
    for (const MuscleTrack* track : tracks_)
    {
      const auto& ids = track->nodes;
      double worst = 0;
      for (std::size_t i = 1; i + 1 < ids.size(); ++i)
      {
        const std::size_t lo = i >= 2 ? i - 2 : 0, hi = std::min(ids.size() - 1, i + 2);
        // Eigen's Umeyama directly: a straight window is collinear, where the rotation about the
        // line is free but the fitted points are still determined.
        const auto count = static_cast<Eigen::Index>(hi - lo + 1);
        Eigen::Matrix3Xd src(3, count), dst(3, count);
        for (std::size_t j = lo; j <= hi; ++j)
        {
          src.col(static_cast<Eigen::Index>(j - lo)) = atlas_.nodes[static_cast<std::size_t>(ids[j])];
          dst.col(static_cast<Eigen::Index>(j - lo)) = mesh.nodes[static_cast<std::size_t>(ids[j])];
        }
        const Eigen::Matrix4d t = Eigen::umeyama(src, dst, true);
        const Eigen::Vector3d a = atlas_.nodes[static_cast<std::size_t>(ids[i])];
        const Eigen::Vector3d mapped = t.topLeftCorner<3, 3>() * a + t.topRightCorner<3, 1>();
        worst = std::max(worst, (mapped - mesh.nodes[static_cast<std::size_t>(ids[i])]).norm());
      }
      perTrack.push_back(worst);
    }
    return SpreadOf(perTrack);
  }

private:
  const FEMesh& atlas_;
  std::map<std::string, std::vector<std::int32_t>> half_, whole_;
  std::vector<const MuscleTrack*> tracks_;
};

} // namespace mmrep::bench
