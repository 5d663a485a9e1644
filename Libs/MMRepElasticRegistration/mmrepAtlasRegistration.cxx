// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The atlas registration R (paper §3.1–3.2): control-point similarity, then the multi-level elastic
// grid fitted to the subject's skin and skull distance maps, symmetric about the subject plane.
#include "mmrepAtlasRegistration.h"

#include "mmrepControlPointMatch.h"
#include "mmrepRegistrationSteps.h"
#include "mmrepSimilarityTransform.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mmrep
{
using namespace registration;

namespace
{
void ControlErrors(const FEMesh& mesh, const std::vector<Eigen::Vector3d>& targets, RegistrationStage& stage,
                   std::vector<double>* all = nullptr)
{
  stage.controlMean = stage.controlMax = 0;
  stage.controlMeasured = true;
  if (all)
    all->clear();
  for (std::size_t i = 0; i < targets.size(); ++i)
  {
    const double e = (mesh.landmarks[i].position - targets[i]).norm();
    stage.controlMean += e / static_cast<double>(targets.size());
    stage.controlMax = std::max(stage.controlMax, e);
    if (all)
      all->push_back(e);
  }
}

void SurfaceErrors(const FEMesh& mesh, const std::vector<std::int32_t>& skin, const std::vector<std::int32_t>& skull,
                   const std::vector<std::int32_t>& lips, vtkPolyData* skinSurface, vtkPolyData* skullSurface,
                   RegistrationStage& stage)
{
  stage.skin = MeasureSurfaceDistance(mesh.nodes, skin, skinSurface);
  if (skullSurface && !skull.empty())
    stage.skull = MeasureSurfaceDistance(mesh.nodes, skull, skullSurface);
  if (!lips.empty())
    stage.lips = MeasureSurfaceDistance(mesh.nodes, lips, skinSurface);
}

// The atlas landmarks and the subject's control points of the same names.
struct ControlPairs
{
  std::vector<Eigen::Vector3d> source, target;
  std::vector<std::string> names;
};

ControlPairs MatchControls(const FEMesh& atlas, const SubjectData& subject)
{
  if (atlas.landmarks.size() < 3)
    throw std::invalid_argument("atlas registration: the atlas has " + std::to_string(atlas.landmarks.size()) +
                                " control points (landmarks), at least 3 are needed");
  ControlPairs pairs;
  for (const auto& l : atlas.landmarks)
  {
    if (!l.position.allFinite())
      throw std::invalid_argument("atlas registration: atlas landmark '" + l.name + "' is not finite");
    pairs.source.push_back(l.position);
    pairs.names.push_back(l.name);
  }
  try
  {
    pairs.target = MatchControlPointsByName(atlas.landmarks, subject.controlPoints);
  }
  catch (const std::invalid_argument& e)
  {
    throw std::invalid_argument(std::string("atlas registration: ") + e.what());
  }
  for (std::size_t i = 0; i < pairs.target.size(); ++i)
    if (!pairs.target[i].allFinite())
      throw std::invalid_argument("atlas registration: subject control point '" + pairs.names[i] + "' is not finite");
  return pairs;
}

// Least-squares similarity from the control points and, when symmetric, their mirror images: the
// pair set is invariant under (atlas mirror, subject mirror), so the similarity maps plane onto plane.
SimilarityTransform InitialSimilarity(const ControlPairs& cp, const Plane& atlasPlane, const Plane& subjectPlane,
                                      bool symmetric)
{
  std::vector<Eigen::Vector3d> src = cp.source, dst = cp.target;
  if (symmetric)
    for (std::size_t i = 0; i < cp.source.size(); ++i)
    {
      src.push_back(atlasPlane.Mirror(cp.source[i]));
      dst.push_back(subjectPlane.Mirror(cp.target[i]));
    }
  try
  {
    return EstimateSimilarity(src, dst);
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument(std::string("atlas registration: control points: ") + e.what());
  }
}

// The aligned atlas must land on the subject: most skin nodes inside the skin's bounding box.
void CheckOverlap(const FEMesh& aligned, const std::vector<std::int32_t>& skinIds, vtkPolyData* skin, double margin)
{
  double sb[6];
  skin->GetBounds(sb);
  std::size_t inside = 0;
  for (auto id : skinIds)
  {
    const auto& p = aligned.nodes[static_cast<std::size_t>(id)];
    bool in = true;
    for (int a = 0; a < 3; ++a)
      in = in && p[a] >= sb[2 * a] - margin && p[a] <= sb[2 * a + 1] + margin;
    inside += in ? 1 : 0;
  }
  if (inside * 2 < skinIds.size())
    throw std::runtime_error(
      "atlas registration: atlas and subject do not overlap after the control-point alignment (" +
      std::to_string(inside) + " of " + std::to_string(skinIds.size()) +
      " skin nodes near the subject skin); check the control points and surfaces");
}

// R's problem in frame coordinates (the same arithmetic as ElasticTransform::Apply): skin and skull
// nodes attracted by their maps (on a half-face fit the right half only follows), the mesh guard,
// the control points, and the grid box around every aligned atlas node, symmetric about the plane.
ElasticProblem RegistrationProblem(const FEMesh& atlas, const Plane& atlasPlane, const ElasticTransform& transform,
                                   const std::vector<std::int32_t>& skinIds, const std::vector<std::int32_t>& skullIds,
                                   const ControlPairs& cp, const AtlasRegistrationOptions& options)
{
  ElasticProblem problem;
  auto frameOf = [&](const Eigen::Vector3d& x) { return transform.ToFrame(transform.PreApply(x)); };
  const bool halfFace = options.symmetric && options.halfFace;
  auto attracted = [&](std::int32_t id, int map) {
    return halfFace && atlasPlane.SignedDistance(atlas.nodes[static_cast<std::size_t>(id)]) < -kPlaneTolerance ? -1
                                                                                                               : map;
  };
  for (auto id : skinIds)
  {
    problem.points.push_back(frameOf(atlas.nodes[static_cast<std::size_t>(id)]));
    problem.pointMap.push_back(attracted(id, 0));
  }
  for (auto id : skullIds)
  {
    problem.points.push_back(frameOf(atlas.nodes[static_cast<std::size_t>(id)]));
    problem.pointMap.push_back(attracted(id, 1));
  }
  if (options.elementQualityFloor >= 0)
  {
    std::vector<std::int32_t> tracked(skinIds.begin(), skinIds.end());
    tracked.insert(tracked.end(), skullIds.begin(), skullIds.end());
    AddMeshGuard(atlas, tracked, frameOf, problem, [&](std::size_t v) {
      return options.holdingWeight > 0 && attracted(static_cast<std::int32_t>(v), 0) == 0 ? -2 : -1;
    });
  }
  for (std::size_t i = 0; i < cp.source.size(); ++i)
  {
    problem.controlSources.push_back(frameOf(cp.source[i]));
    problem.controlTargets.push_back(transform.ToFrame(cp.target[i]));
    problem.controlWeights.push_back(options.controlPointWeight);
  }
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  auto grow = [&](const Eigen::Vector3d& f) {
    lo = lo.cwiseMin(f);
    hi = hi.cwiseMax(f);
  };
  for (const auto& n : atlas.nodes)
    grow(frameOf(n));
  for (const auto& s : problem.controlSources)
    grow(s);
  SymmetricInX(options.symmetric, lo, hi);
  const Eigen::Vector3d margin = options.gridMargin * (hi - lo) + Eigen::Vector3d::Constant(1e-3);
  problem.boxMin = lo - margin;
  problem.boxMax = hi + margin;
  return problem;
}
} // namespace

void ApplyTransform(const ElasticTransform& transform, FEMesh& mesh)
{
  for (auto& n : mesh.nodes)
    n = transform.Apply(n);
  for (auto& l : mesh.landmarks)
    l.position = transform.Apply(l.position);
}

AtlasRegistrationResult RegisterAtlas(const FEMesh& atlas, const Plane& atlasPlane, const SubjectData& subject,
                                      const AtlasRegistrationOptions& options)
{
  const auto t0 = Clock::now();
  auto progress = [&](double f) {
    if (options.progress)
      options.progress(f);
  };
  if (atlas.nodes.empty())
    throw std::invalid_argument("atlas registration: the atlas mesh has no nodes");
  const auto& skinIds = NodeSet(atlas, options.skinSet, "atlas registration");
  const auto& skullIds = NodeSet(atlas, options.skullSet, "atlas registration");
  const auto lipsIt = atlas.nodeSets.find(options.lipsSet);
  const std::vector<std::int32_t> lipsIds =
    lipsIt == atlas.nodeSets.end() ? std::vector<std::int32_t>{} : lipsIt->second;
  CheckSurface(subject.skin, "atlas registration: the subject skin");
  CheckSurface(subject.skull, "atlas registration: the subject skull");
  CheckPlane(atlasPlane, "atlas registration: atlas plane");
  CheckPlane(subject.plane, "atlas registration: subject plane");
  if (!(options.mapSpacing > 0) || !(options.gridMargin >= 0) || options.finestLevel < 0 || options.finestLevel > 8)
    throw std::invalid_argument("atlas registration: map spacing must be > 0, grid margin >= 0, level in 0..8");
  const ControlPairs cp = MatchControls(atlas, subject);
  RegistrationReport report;
  report.controlNames = cp.names;

  const auto tSim = Clock::now();
  const SimilarityTransform similarity = InitialSimilarity(cp, atlasPlane, subject.plane, options.symmetric);
  AtlasRegistrationResult result;
  ElasticTransform& transform = result.transform;
  transform.preLinear = similarity.Linear();
  transform.preTranslation = similarity.translation;
  SetPlaneFrame(transform, subject.plane);
  result.mesh = atlas;
  ApplyTransform(transform, result.mesh); // no steps yet: the similarity alone
  RegistrationStage simStage;
  simStage.name = "similarity";
  SurfaceErrors(result.mesh, skinIds, skullIds, lipsIds, subject.skin, subject.skull, simStage);
  ControlErrors(result.mesh, cp.target, simStage);
  simStage.seconds = Since(tSim);
  CheckOverlap(result.mesh, skinIds, subject.skin, options.mapMargin);
  progress(0.02);

  const auto tMaps = Clock::now();
  SurfaceDistanceMapOptions mapOptions;
  mapOptions.spacing = options.mapSpacing;
  mapOptions.margin = options.mapMargin;
  FloatImage::Pointer skinMap = subject.skinMap, skullMap = subject.skullMap;
  if (!skinMap)
    skinMap = DistanceMap(subject.skin, mapOptions, options.signedMaps, [&](double f) { progress(0.02 + 0.1 * f); });
  if (!skullMap)
    skullMap = DistanceMap(subject.skull, mapOptions, options.signedMaps, [&](double f) { progress(0.12 + 0.1 * f); });
  RegistrationStage mapStage;
  mapStage.name = "distance maps";
  mapStage.seconds = Since(tMaps);

  const auto tElastic = Clock::now();
  ElasticProblem problem = RegistrationProblem(atlas, atlasPlane, transform, skinIds, skullIds, cp, options);
  problem.maps.emplace(problem.maps.begin(), skinMap.GetPointer());
  problem.maps.emplace(problem.maps.begin() + 1, skullMap.GetPointer());
  ElasticOptimizerOptions opt;
  static_cast<ElasticSolverSettings&>(opt) = options;
  opt.firstLevel = 1;
  opt.finestLevel = options.finestLevel > 0 ? options.finestLevel
                                            : AutomaticLevel((problem.boxMax - problem.boxMin).minCoeff(),
                                                             options.mapSpacing, options.minimumCellVoxels);
  opt.progress = [&](double f) { progress(0.22 + 0.73 * f); };
  RegistrationStage elastic;
  elastic.name = "elastic";
  elastic.energyBefore = ElasticEnergy(transform, problem);
  const auto stats = OptimizeElastic(transform, problem, opt);
  elastic.energyAfter = ElasticEnergy(transform, problem);
  elastic.sweepsPerLevel = stats.sweepsPerLevel;
  elastic.stepsPerLevel = transform.StepsPerLevel();

  result.mesh = atlas;
  ApplyTransform(transform, result.mesh);
  elastic.seconds = Since(tElastic);
  SurfaceErrors(result.mesh, skinIds, skullIds, lipsIds, subject.skin, subject.skull, elastic);
  ControlErrors(result.mesh, cp.target, elastic, &report.controlErrors);
  report.controlWeights = problem.controlWeights;
  report.stages = {simStage, mapStage, elastic};
  RegistrationStage total = elastic;
  total.name = "total";
  total.seconds = Since(t0);
  report.stages.push_back(total);
  result.report = report;
  progress(1.0);
  return result;
}

} // namespace mmrep
