// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The local refinement Q of the lips (paper §3.3): a finer elastic grid over the lips' box, its
// boundary fixed, fitted to a fine skin distance map; Q∘R stays C1 across the box's boundary.
#include "mmrepAtlasRegistration.h"

#include "mmrepRegistrationSteps.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace mmrep
{
using namespace registration;

namespace
{
// The region's box in frame coordinates, grown by the margins; symmetric about the plane when asked.
void RefinementBox(const FEMesh& registered, const std::vector<std::int32_t>& regionIds,
                   const ElasticTransform& transform, const LocalRefinementOptions& options,
                   LocalRefinementResult& result)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (auto id : regionIds)
  {
    const Eigen::Vector3d f = transform.ToFrame(registered.nodes[static_cast<std::size_t>(id)]);
    lo = lo.cwiseMin(f);
    hi = hi.cwiseMax(f);
  }
  SymmetricInX(options.symmetric, lo, hi);
  const Eigen::Vector3d margin =
    (options.boxMargin * (hi - lo)).cwiseMax(Eigen::Vector3d::Constant(options.minimumMargin));
  result.boxMin = lo - margin;
  result.boxMax = hi + margin;
}

// The fine skin map over the box (world bounds of its corners).
FloatImage::Pointer RefinementMap(vtkPolyData* skin, const ElasticTransform& transform,
                                  const LocalRefinementOptions& options, const LocalRefinementResult& result,
                                  const std::function<void(double)>& progress)
{
  SurfaceDistanceMapOptions mapOptions;
  mapOptions.spacing = options.spacing;
  mapOptions.margin = 2.0 * options.spacing;
  Eigen::Vector3d wlo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), whi = -wlo;
  for (int c = 0; c < 8; ++c)
  {
    const Eigen::Vector3d f((c & 1) ? result.boxMax.x() : result.boxMin.x(),
                            (c & 2) ? result.boxMax.y() : result.boxMin.y(),
                            (c & 4) ? result.boxMax.z() : result.boxMin.z());
    const Eigen::Vector3d w = transform.ToWorld(f);
    wlo = wlo.cwiseMin(w);
    whi = whi.cwiseMax(w);
  }
  mapOptions.region = {wlo.x(), whi.x(), wlo.y(), whi.y(), wlo.z(), whi.z()};
  return DistanceMap(skin, mapOptions, options.signedMap, progress);
}

// Q's problem: the skin nodes inside the box attracted (on a half-face fit the right ones follow),
// the mesh guard, and the pins (skull nodes and landmarks inside the box held where R put them).
ElasticProblem RefinementProblem(const FEMesh& registered, const std::vector<std::int32_t>& skinIds,
                                 const ElasticTransform& transform, const LocalRefinementOptions& options,
                                 const LocalRefinementResult& result)
{
  ElasticProblem problem;
  auto inBox = [&](const Eigen::Vector3d& f) {
    return (f.array() > result.boxMin.array()).all() && (f.array() < result.boxMax.array()).all();
  };
  std::vector<std::int32_t> tracked;
  for (auto id : skinIds)
  {
    const Eigen::Vector3d f = transform.ToFrame(registered.nodes[static_cast<std::size_t>(id)]);
    if (inBox(f))
    {
      problem.points.push_back(f);
      problem.pointMap.push_back(options.symmetric && options.halfFace && f.x() < -kPlaneTolerance ? -1 : 0);
      tracked.push_back(id);
    }
  }
  if (options.elementQualityFloor >= 0)
    AddMeshGuard(
      registered, tracked, [&](const Eigen::Vector3d& x) { return transform.ToFrame(x); }, problem,
      [&](std::size_t v) {
        const bool fitted =
          !(options.symmetric && options.halfFace) || transform.ToFrame(registered.nodes[v]).x() >= -kPlaneTolerance;
        return options.holdingWeight > 0 && fitted ? -2 : -1;
      });
  if (options.pinWeight > 0)
  {
    std::vector<Eigen::Vector3d> pins;
    const auto skull = registered.nodeSets.find(options.skullSet);
    if (skull != registered.nodeSets.end())
      for (auto id : skull->second)
        if (id >= 0 && static_cast<std::size_t>(id) < registered.nodes.size())
          pins.push_back(transform.ToFrame(registered.nodes[static_cast<std::size_t>(id)]));
    for (const auto& l : registered.landmarks)
      pins.push_back(transform.ToFrame(l.position));
    for (const auto& f : pins)
      if (inBox(f))
      {
        problem.controlSources.push_back(f);
        problem.controlTargets.push_back(f);
        problem.controlWeights.push_back(options.pinWeight);
      }
  }
  problem.boxMin = result.boxMin;
  problem.boxMax = result.boxMax;
  return problem;
}
} // namespace

LocalRefinementResult RefineLocally(const FEMesh& registered, vtkPolyData* skin, const LocalRefinementOptions& options)
{
  const auto t0 = Clock::now();
  auto progress = [&](double f) {
    if (options.progress)
      options.progress(f);
  };
  CheckSurface(skin, "local refinement: the subject skin");
  const auto& regionIds = NodeSet(registered, options.regionSet, "local refinement");
  const auto& skinIds = NodeSet(registered, options.skinSet, "local refinement");
  if (!(options.spacing > 0) || options.finestLevel < 0 || options.finestLevel > 8 || !(options.boxMargin >= 0))
    throw std::invalid_argument("local refinement: spacing must be > 0, level in 0..8, margin >= 0");
  if (options.symmetric)
    CheckPlane(options.plane, "local refinement: plane");

  LocalRefinementResult result;
  ElasticTransform& transform = result.transform;
  if (options.symmetric)
    SetPlaneFrame(transform, options.plane);
  std::vector<std::int32_t> lipsSkin = Intersection(regionIds, skinIds);
  if (lipsSkin.empty())
    lipsSkin = regionIds;
  RefinementBox(registered, regionIds, transform, options, result);
  auto map = RefinementMap(skin, transform, options, result, [&](double f) { progress(0.3 * f); });
  ElasticProblem problem = RefinementProblem(registered, skinIds, transform, options, result);
  problem.maps.emplace(problem.maps.begin(), map.GetPointer());

  result.before.name = "before refinement";
  result.before.lips = MeasureSurfaceDistance(registered.nodes, lipsSkin, skin);
  result.before.skin = MeasureSurfaceDistance(registered.nodes, skinIds, skin);

  ElasticOptimizerOptions opt;
  static_cast<ElasticSolverSettings&>(opt) = options;
  opt.firstLevel = 1;
  opt.finestLevel = options.finestLevel > 0 ? options.finestLevel
                                            : AutomaticLevel((problem.boxMax - problem.boxMin).minCoeff(),
                                                             options.spacing, options.minimumCellVoxels);
  opt.fixBoundary = true;
  opt.progress = [&](double f) { progress(0.3 + 0.65 * f); };
  result.after.energyBefore = ElasticEnergy(transform, problem);
  const auto stats = OptimizeElastic(transform, problem, opt);
  result.after.energyAfter = ElasticEnergy(transform, problem);
  result.after.sweepsPerLevel = stats.sweepsPerLevel;
  result.after.stepsPerLevel = transform.StepsPerLevel();

  result.mesh = registered;
  ApplyTransform(transform, result.mesh);
  result.after.name = "refinement";
  result.after.lips = MeasureSurfaceDistance(result.mesh.nodes, lipsSkin, skin);
  result.after.skin = MeasureSurfaceDistance(result.mesh.nodes, skinIds, skin);
  result.after.seconds = Since(t0);
  progress(1.0);
  return result;
}

} // namespace mmrep
