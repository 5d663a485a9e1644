#include "mmrepAtlasRegistration.h"

#include "mmrepSimilarityTransform.h"
#include "mmrepSurfaceDistanceMap.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <functional>
#include <chrono>
#include <cmath>
#include <set>
#include <stdexcept>

namespace mmrep
{

namespace
{
// Nodes within this distance (mm) of the plane count as plane nodes (a symmetric atlas has them on it
// to rounding).
constexpr double kPlaneTolerance = 1e-3;

// Mesh guard: every node of a hexahedron not yet tracked becomes a passive point, and the
// hexahedra are given over point indices (mmrepElasticOptimizer.h says why).
// `innerMap(node)` gives the pointMap of a node that is not tracked yet (−1 passive, −2 held).
void AddMeshGuard(const FEMesh& mesh, const std::vector<std::int32_t>& trackedNodes,
                  const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& toFrame, ElasticProblem& problem,
                  const std::function<int(std::size_t)>& innerMap = [](std::size_t) { return -1; })
{
  std::vector<int> pointOf(mesh.nodes.size(), -1);
  for (std::size_t k = 0; k < trackedNodes.size(); ++k)
    if (pointOf[static_cast<std::size_t>(trackedNodes[k])] < 0)
      pointOf[static_cast<std::size_t>(trackedNodes[k])] = static_cast<int>(k);
  for (const auto& e : mesh.elements)
  {
    if (e.type != ElementType::Hexahedron)
      continue;
    std::array<int, 8> h{};
    for (std::size_t c = 0; c < 8; ++c)
    {
      const auto v = static_cast<std::size_t>(e.nodes[c]);
      if (pointOf[v] < 0)
      {
        pointOf[v] = static_cast<int>(problem.points.size());
        problem.points.push_back(toFrame(mesh.nodes[v]));
        problem.pointMap.push_back(innerMap(v));
      }
      h[c] = pointOf[v];
    }
    problem.hexahedra.push_back(h);
  }
}

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Rigid frame whose x axis is the plane normal and whose origin lies on the plane.
void SetPlaneFrame(ElasticTransform& t, const Plane& plane)
{
  const Eigen::Vector3d e0 = plane.normal.normalized();
  Eigen::Vector3d ref = Eigen::Vector3d::UnitY();
  if (std::abs(e0.dot(ref)) > 0.9)
    ref = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d e1 = (ref - ref.dot(e0) * e0).normalized();
  const Eigen::Vector3d e2 = e0.cross(e1);
  t.frameRotation.row(0) = e0.transpose();
  t.frameRotation.row(1) = e1.transpose();
  t.frameRotation.row(2) = e2.transpose();
  t.frameOrigin = plane.point;
}

void CheckPlane(const Plane& p, const std::string& what)
{
  if (!p.point.allFinite() || !p.normal.allFinite() || !(p.normal.norm() > 1e-12))
    throw std::invalid_argument(what + ": the plane needs a finite point and a non-zero normal");
}

const std::vector<std::int32_t>& NodeSet(const FEMesh& mesh, const std::string& name, const std::string& what)
{
  const auto it = mesh.nodeSets.find(name);
  if (it == mesh.nodeSets.end() || it->second.empty())
    throw std::invalid_argument(what + ": the mesh has no node set '" + name + "' (or it is empty)");
  for (auto id : it->second)
    if (id < 0 || static_cast<std::size_t>(id) >= mesh.nodes.size())
      throw std::invalid_argument(what + ": node set '" + name + "' refers to a missing node");
  return it->second;
}

void CheckSurface(vtkPolyData* s, const std::string& what)
{
  if (s == nullptr || s->GetNumberOfPoints() == 0 || s->GetNumberOfPolys() + s->GetNumberOfStrips() == 0)
    throw std::runtime_error(what + " surface is empty (no triangles)");
}

std::vector<std::int32_t> Intersection(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b)
{
  std::vector<std::int32_t> x(a), y(b), r;
  std::sort(x.begin(), x.end());
  std::sort(y.begin(), y.end());
  std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(r));
  return r;
}

// The finest level whose smallest cell is at least `cellsPerSpacing` map voxels.
int AutomaticLevel(double smallestExtent, double spacing, double cellsPerSpacing)
{
  const double ratio = smallestExtent / (cellsPerSpacing * spacing);
  return std::clamp(static_cast<int>(std::floor(std::log2(std::max(ratio, 1.0)))), 1, 8);
}

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
  stage.skin = MeasureSurfaceError(mesh.nodes, skin, skinSurface);
  if (skullSurface && !skull.empty())
    stage.skull = MeasureSurfaceError(mesh.nodes, skull, skullSurface);
  if (!lips.empty())
    stage.lips = MeasureSurfaceError(mesh.nodes, lips, skinSurface);
}

// Signed map when asked and possible (closed surface), unsigned otherwise: any failure of the
// signed computation (open or non-manifold surface) retries unsigned, whose own errors propagate.
FloatImage::Pointer DistanceMap(vtkPolyData* surface, SurfaceDistanceMapOptions o, bool trySigned,
                                const std::function<void(double)>& progress)
{
  if (trySigned)
  {
    o.signedDistance = true;
    try
    {
      return ComputeSurfaceDistanceMap(surface, o, progress);
    }
    catch (const std::runtime_error&)
    {
    }
  }
  o.signedDistance = false;
  return ComputeSurfaceDistanceMap(surface, o, progress);
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
  const std::vector<std::int32_t> lipsIds = lipsIt == atlas.nodeSets.end() ? std::vector<std::int32_t>{} : lipsIt->second;
  CheckSurface(subject.skin, "atlas registration: the subject skin");
  CheckSurface(subject.skull, "atlas registration: the subject skull");
  CheckPlane(atlasPlane, "atlas registration: atlas plane");
  CheckPlane(subject.plane, "atlas registration: subject plane");
  if (!(options.mapSpacing > 0) || !(options.gridMargin >= 0) || options.finestLevel < 0 || options.finestLevel > 8)
    throw std::invalid_argument("atlas registration: map spacing must be > 0, grid margin >= 0, level in 0..8");

  // Control points: every atlas landmark must be found by name among the subject's, and vice versa.
  if (atlas.landmarks.size() < 3)
    throw std::invalid_argument("atlas registration: the atlas has " + std::to_string(atlas.landmarks.size()) +
                                " control points (landmarks), at least 3 are needed");
  std::vector<Eigen::Vector3d> sourceCP, targetCP;
  RegistrationReport report;
  for (const auto& l : atlas.landmarks)
  {
    if (!l.position.allFinite())
      throw std::invalid_argument("atlas registration: atlas landmark '" + l.name + "' is not finite");
    const auto it = std::find_if(subject.controlPoints.begin(), subject.controlPoints.end(),
                                 [&](const Landmark& s) { return s.name == l.name; });
    if (it == subject.controlPoints.end())
      throw std::invalid_argument("atlas registration: control point '" + l.name +
                                  "' of the atlas is missing from the subject control points");
    if (std::count_if(subject.controlPoints.begin(), subject.controlPoints.end(),
                      [&](const Landmark& s) { return s.name == l.name; }) > 1)
      throw std::invalid_argument("atlas registration: subject control point '" + l.name + "' is given twice");
    if (!it->position.allFinite())
      throw std::invalid_argument("atlas registration: subject control point '" + l.name + "' is not finite");
    sourceCP.push_back(l.position);
    targetCP.push_back(it->position);
    report.controlNames.push_back(l.name);
  }
  for (const auto& s : subject.controlPoints)
    if (std::none_of(atlas.landmarks.begin(), atlas.landmarks.end(), [&](const Landmark& l) { return l.name == s.name; }))
      throw std::invalid_argument("atlas registration: subject control point '" + s.name +
                                  "' has no counterpart among the atlas landmarks");

  // Initial similarity from the control points and their mirror images: the pair set is invariant
  // under (atlas mirror, subject mirror), so the least-squares similarity maps plane onto plane.
  const auto tSim = Clock::now();
  std::vector<Eigen::Vector3d> src = sourceCP, dst = targetCP;
  for (std::size_t i = 0; i < sourceCP.size(); ++i)
  {
    src.push_back(atlasPlane.Mirror(sourceCP[i]));
    dst.push_back(subject.plane.Mirror(targetCP[i]));
  }
  SimilarityTransform similarity;
  try
  {
    similarity = EstimateSimilarity(options.symmetric ? src : sourceCP, options.symmetric ? dst : targetCP);
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument(std::string("atlas registration: control points: ") + e.what());
  }

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
  ControlErrors(result.mesh, targetCP, simStage);
  simStage.seconds = Since(tSim);

  // The aligned atlas must land on the subject: most skin nodes inside the skin's bounding box.
  double sb[6];
  subject.skin->GetBounds(sb);
  std::size_t inside = 0;
  for (auto id : skinIds)
  {
    const auto& p = result.mesh.nodes[static_cast<std::size_t>(id)];
    bool in = true;
    for (int a = 0; a < 3; ++a)
      in = in && p[a] >= sb[2 * a] - options.mapMargin && p[a] <= sb[2 * a + 1] + options.mapMargin;
    inside += in ? 1 : 0;
  }
  if (inside * 2 < skinIds.size())
    throw std::runtime_error("atlas registration: atlas and subject do not overlap after the control-point alignment (" +
                             std::to_string(inside) + " of " + std::to_string(skinIds.size()) +
                             " skin nodes near the subject skin); check the control points and surfaces");
  progress(0.02);

  // Distance maps.
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

  // Problem in frame coordinates: the same arithmetic as ElasticTransform::Apply.
  const auto tElastic = Clock::now();
  ElasticProblem problem;
  problem.maps.emplace_back(skinMap.GetPointer());
  problem.maps.emplace_back(skullMap.GetPointer());
  auto frameOf = [&](const Eigen::Vector3d& x) { return transform.ToFrame(transform.PreApply(x)); };
  // Half-face: right-half nodes are moved along (passive), not attracted.
  const bool halfFace = options.symmetric && options.halfFace;
  auto attracted = [&](std::int32_t id, int map) {
    return halfFace && atlasPlane.SignedDistance(atlas.nodes[static_cast<std::size_t>(id)]) < -kPlaneTolerance ? -1 : map;
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
  for (std::size_t i = 0; i < sourceCP.size(); ++i)
  {
    problem.controlSources.push_back(frameOf(sourceCP[i]));
    problem.controlTargets.push_back(transform.ToFrame(targetCP[i]));
    problem.controlWeights.push_back(options.controlPointWeight);
  }
  // Grid box: every aligned atlas node and landmark, symmetric about the plane, + margin.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  auto grow = [&](const Eigen::Vector3d& f) {
    lo = lo.cwiseMin(f);
    hi = hi.cwiseMax(f);
  };
  for (const auto& n : atlas.nodes)
    grow(frameOf(n));
  for (const auto& s : problem.controlSources)
    grow(s);
  if (options.symmetric)
  {
    const double x = std::max(std::abs(lo.x()), std::abs(hi.x()));
    lo.x() = -x;
    hi.x() = x;
  }
  const Eigen::Vector3d margin = options.gridMargin * (hi - lo) + Eigen::Vector3d::Constant(1e-3);
  problem.boxMin = lo - margin;
  problem.boxMax = hi + margin;

  ElasticOptimizerOptions opt;
  opt.firstLevel = 1;
  opt.finestLevel = options.finestLevel > 0 ? options.finestLevel
                                            : AutomaticLevel((problem.boxMax - problem.boxMin).minCoeff(), options.mapSpacing,
                                                             options.minimumCellVoxels);
  opt.stepSafety = options.stepSafety;
  opt.maximumSweeps = options.maximumSweeps;
  opt.tolerance = options.tolerance;
  opt.symmetric = options.symmetric;
  opt.controlPointTolerance = options.controlPointTolerance;
  opt.controlPointWeightCap = options.controlPointWeightCap;
  opt.elementQualityFloor = options.elementQualityFloor;
  opt.tieWeight = options.tieWeight;
  opt.slidingWeight = options.slidingWeight;
  opt.holdingWeight = options.holdingWeight;
  opt.regularizationFirstLevel = options.regularizationFirstLevel;
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
  ControlErrors(result.mesh, targetCP, elastic, &report.controlErrors);
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

  // Box: the region in frame coordinates, grown; symmetric about the plane when asked.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (auto id : regionIds)
  {
    const Eigen::Vector3d f = transform.ToFrame(registered.nodes[static_cast<std::size_t>(id)]);
    lo = lo.cwiseMin(f);
    hi = hi.cwiseMax(f);
  }
  if (options.symmetric)
  {
    const double x = std::max(std::abs(lo.x()), std::abs(hi.x()));
    lo.x() = -x;
    hi.x() = x;
  }
  const Eigen::Vector3d margin =
    (options.boxMargin * (hi - lo)).cwiseMax(Eigen::Vector3d::Constant(options.minimumMargin));
  result.boxMin = lo - margin;
  result.boxMax = hi + margin;

  // Fine map over the box (world bounds of its corners).
  SurfaceDistanceMapOptions mapOptions;
  mapOptions.spacing = options.spacing;
  mapOptions.margin = 2.0 * options.spacing;
  Eigen::Vector3d wlo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), whi = -wlo;
  for (int c = 0; c < 8; ++c)
  {
    const Eigen::Vector3d f((c & 1) ? result.boxMax.x() : result.boxMin.x(), (c & 2) ? result.boxMax.y() : result.boxMin.y(),
                            (c & 4) ? result.boxMax.z() : result.boxMin.z());
    const Eigen::Vector3d w = transform.ToWorld(f);
    wlo = wlo.cwiseMin(w);
    whi = whi.cwiseMax(w);
  }
  mapOptions.region = {wlo.x(), whi.x(), wlo.y(), whi.y(), wlo.z(), whi.z()};
  auto map = DistanceMap(skin, mapOptions, options.signedMap, [&](double f) { progress(0.3 * f); });

  ElasticProblem problem;
  problem.maps.emplace_back(map.GetPointer());
  std::vector<std::int32_t> tracked;
  for (auto id : skinIds)
  {
    const Eigen::Vector3d f = transform.ToFrame(registered.nodes[static_cast<std::size_t>(id)]);
    if ((f.array() > result.boxMin.array()).all() && (f.array() < result.boxMax.array()).all())
    {
      problem.points.push_back(f);
      problem.pointMap.push_back(options.symmetric && options.halfFace && f.x() < -kPlaneTolerance ? -1 : 0);
      tracked.push_back(id);
    }
  }
  if (options.elementQualityFloor >= 0)
    AddMeshGuard(registered, tracked, [&](const Eigen::Vector3d& x) { return transform.ToFrame(x); }, problem,
                 [&](std::size_t v) {
                   const bool fitted = !(options.symmetric && options.halfFace) ||
                                       transform.ToFrame(registered.nodes[v]).x() >= -kPlaneTolerance;
                   return options.holdingWeight > 0 && fitted ? -2 : -1;
                 });
  auto inBox = [&](const Eigen::Vector3d& f) {
    return (f.array() > result.boxMin.array()).all() && (f.array() < result.boxMax.array()).all();
  };
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

  result.before.name = "before refinement";
  result.before.lips = MeasureSurfaceError(registered.nodes, lipsSkin, skin);
  result.before.skin = MeasureSurfaceError(registered.nodes, skinIds, skin);

  ElasticOptimizerOptions opt;
  opt.firstLevel = 1;
  opt.finestLevel = options.finestLevel > 0 ? options.finestLevel
                                            : AutomaticLevel((problem.boxMax - problem.boxMin).minCoeff(), options.spacing,
                                                             options.minimumCellVoxels);
  opt.stepSafety = options.stepSafety;
  opt.maximumSweeps = options.maximumSweeps;
  opt.tolerance = options.tolerance;
  opt.symmetric = options.symmetric;
  opt.fixBoundary = true;
  opt.elementQualityFloor = options.elementQualityFloor;
  opt.slidingWeight = options.slidingWeight;
  opt.holdingWeight = options.holdingWeight;
  opt.regularizationFirstLevel = options.regularizationFirstLevel;
  opt.progress = [&](double f) { progress(0.3 + 0.65 * f); };
  result.after.energyBefore = ElasticEnergy(transform, problem);
  const auto stats = OptimizeElastic(transform, problem, opt);
  result.after.energyAfter = ElasticEnergy(transform, problem);
  result.after.sweepsPerLevel = stats.sweepsPerLevel;
  result.after.stepsPerLevel = transform.StepsPerLevel();

  result.mesh = registered;
  ApplyTransform(transform, result.mesh);
  result.after.name = "refinement";
  result.after.lips = MeasureSurfaceError(result.mesh.nodes, lipsSkin, skin);
  result.after.skin = MeasureSurfaceError(result.mesh.nodes, skinIds, skin);
  result.after.seconds = Since(t0);
  progress(1.0);
  return result;
}

} // namespace mmrep
