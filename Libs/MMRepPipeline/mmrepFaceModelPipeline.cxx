// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFaceModelPipeline.h"
#include "mmrepFieldOfView.h"

#include "mmrepBoundaryFaces.h"
#include "mmrepControlPointMatch.h"

#include "mmrepCanonicalVoxelOrder.h"
#include "mmrepHeadSegmentation.h"
#include "mmrepNotImaged.h"
#include "mmrepSurfaceDistanceMap.h"
#include "mmrepSurfaceExtraction.h"
#include "mmrepSymmetryPlane.h"

#include <vtkBox.h>
#include <vtkNew.h>
#include <vtkExtractPolyDataGeometry.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace mmrep
{
namespace
{
using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// `fittedHalf[i]`: node i of the atlas lies on the fitted (left) half or on the plane.
ModelAccuracy Measure(const std::string& state, const FEMesh& mesh, vtkPolyData* skin, vtkPolyData* skull,
                      const std::vector<std::string>& names, const std::vector<Point3>& targets,
                      const AtlasRegistrationOptions& sets, const std::vector<char>& fittedHalf)
{
  ModelAccuracy a;
  a.state = state;
  auto set = [&](const std::string& name, bool half) {
    std::vector<std::int32_t> ids;
    if (const auto it = mesh.nodeSets.find(name); it != mesh.nodeSets.end())
      for (auto id : it->second)
        if (!half || fittedHalf[static_cast<std::size_t>(id)])
          ids.push_back(id);
    return ids;
  };
  a.skin = MeasureSurfaceDistance(mesh.nodes, set(sets.skinSet, false), skin);
  a.skull = MeasureSurfaceDistance(mesh.nodes, set(sets.skullSet, false), skull);
  a.lips = MeasureSurfaceDistance(mesh.nodes, set(sets.lipsSet, false), skin);
  a.skinHalf = MeasureSurfaceDistance(mesh.nodes, set(sets.skinSet, true), skin);
  a.skullHalf = MeasureSurfaceDistance(mesh.nodes, set(sets.skullSet, true), skull);
  a.lipsHalf = MeasureSurfaceDistance(mesh.nodes, set(sets.lipsSet, true), skin);
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    double e = std::numeric_limits<double>::quiet_NaN();
    for (const auto& l : mesh.landmarks)
      if (l.name == names[i])
        e = (l.position - targets[i]).norm();
    a.controlErrors.push_back(e);
  }
  return a;
}

// What makes the final model a poor fit, in words ("fitted skull 2.9 mm mean (at most 1.5)"), or empty.
std::string PoorFit(const ModelAccuracy& a, const std::vector<std::string>& names, const FaceModelOptions& options)
{
  std::string why;
  auto add = [&](const std::string& what, double value, double bound) {
    if (!(value <= bound)) // NaN is poor too
    {
      char text[200];
      std::snprintf(text, sizeof text, "%s%s %.2f mm (at most %.1f)", why.empty() ? "" : ", ", what.c_str(), value,
                    bound);
      why += text;
    }
  };
  add("fitted skin mean", a.skinHalf.mean, options.poorFitSkin);
  add("fitted skull mean", a.skullHalf.mean, options.poorFitSkull);
  for (std::size_t i = 0; i < names.size() && i < a.controlErrors.size(); ++i)
    add("control point '" + names[i] + "'", a.controlErrors[i], options.poorFitControlPoint);
  return why;
}

} // namespace

std::vector<Point3> MatchControlPoints(const CTImage* ct, const std::vector<Landmark>& points, const FEMesh& atlas,
                                       std::vector<std::string>& names)
{
  std::vector<Point3> targets = MatchControlPointsByName(atlas.landmarks, points);
  for (std::size_t i = 0; i < targets.size(); ++i)
  {
    const Landmark& l = atlas.landmarks[i];
    const Point3& target = targets[i];
    bool inside = target.allFinite();
    if (ct != nullptr && inside)
    {
      const auto region = ct->GetLargestPossibleRegion();
      CTImage::PointType p;
      for (unsigned a = 0; a < 3; ++a)
        p[a] = target[a];
      const auto index = ct->TransformPhysicalPointToContinuousIndex<double>(p);
      for (unsigned a = 0; a < 3 && inside; ++a)
        inside = index[a] >= static_cast<double>(region.GetIndex(a)) - 0.5 &&
                 index[a] <= static_cast<double>(region.GetIndex(a) + static_cast<long>(region.GetSize(a))) - 0.5;
    }
    if (!inside)
    {
      std::ostringstream s;
      s << "control points: '" << l.name << "' at (" << target.x() << ", " << target.y() << ", " << target.z()
        << ") mm LPS lies outside the CT volume (check the coordinate system: LPS vs RAS)";
      throw std::invalid_argument(s.str());
    }
    names.push_back(l.name);
  }
  return targets;
}

vtkSmartPointer<vtkPolyData> CropSurfaceAround(vtkPolyData* surface, const FEMesh& mesh, double margin)
{
  Point3 lo = mesh.nodes.front(), hi = mesh.nodes.front();
  for (const auto& p : mesh.nodes)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  vtkNew<vtkBox> box;
  box->SetBounds(lo.x() - margin, hi.x() + margin, lo.y() - margin, hi.y() + margin, lo.z() - margin, hi.z() + margin);
  vtkNew<vtkExtractPolyDataGeometry> extract;
  extract->SetInputData(surface);
  extract->SetImplicitFunction(box);
  extract->ExtractInsideOn();
  extract->ExtractBoundaryCellsOn();
  extract->Update();
  vtkSmartPointer<vtkPolyData> out = extract->GetOutput();
  return out;
}

SubjectSurfaceSet ExtractSubjectSurfaces(const CTImage* ct, const FaceModelOptions& options,
                                         const std::function<void(double)>& progress)
{
  auto report = [&](double f) {
    if (progress)
      progress(f);
  };
  // One voxel order for every file of the same physical CT: the surfaces, and all that follows,
  // are then the same bytes.
  const auto canonical = CanonicalVoxelOrder(ct);
  ct = canonical.GetPointer();
  SubjectSurfaceSet s;
  s.thresholds = ChooseThresholds(ct, options.thresholdMode, options.skinThreshold, options.boneThreshold);
  HeadSegmentationOptions seg;
  seg.skinThreshold = s.thresholds.skin;
  seg.boneThreshold = s.thresholds.bone;
  seg.openingRadius = options.openingRadius;
  const auto head = SegmentHead(ct, seg, [&](double f) { report(0.6 * f); });
  if (options.closeSlits > 0)
  {
    const double axialSpacing = ct->GetSpacing()[AxialAxis(ct)];
    CloseAxialSlits(head.skin.GetPointer(), std::max(1, static_cast<int>(options.closeSlits / axialSpacing + 1e-9)));
  }
  SurfaceExtractionOptions surf;
  surf.largestPieceOnly = false; // single-component masks (see SkinSkullSurfaces)
  s.skin = ExtractSurface(MaskedIntensities(ct, head.skin, s.thresholds.skin), s.thresholds.skin, surf);
  report(0.8);
  s.skull = ExtractSurface(MaskedIntensities(ct, head.bone, s.thresholds.bone), s.thresholds.bone, surf);
  report(1.0);
  return s;
}

SymmetryPlaneResult EstimateSubjectPlane(vtkPolyData* skin, const FaceModelOptions& options)
{
  return EstimateSymmetryPlane(skin, options.plane);
}

LocalRefinementOptions RefinementOptionsFor(const FaceModelOptions& options, const Plane& plane)
{
  auto q = options.refinement;
  q.elementQualityFloor = options.registration.elementQualityFloor; // one floor for R and Q
  q.symmetric = options.registration.symmetric;
  q.halfFace = options.registration.symmetric && options.registration.halfFace;
  q.plane = plane;
  return q;
}

namespace
{
// The atlas's sets and muscles, the control points (matched to the atlas's landmarks, inside the
// CT) and the field of view, before any stage runs.
void CheckInputs(const CTImage* ct, const std::vector<Landmark>& controlPoints, const FEMesh& atlas,
                 const FaceModelOptions& options, FaceModelResult& result)
{
  if (ct == nullptr)
    throw std::invalid_argument("face model: no CT image");
  atlas.Validate();
  for (const auto& set : {options.registration.skinSet, options.registration.skullSet, options.registration.lipsSet,
                          std::string("midsagittal")})
    if (!atlas.nodeSets.count(set))
      throw std::invalid_argument("atlas: node set '" + set + "' is missing");
  if (atlas.muscles.empty())
    throw std::invalid_argument("atlas: it has no muscle tracks");

  result.controlTargets = MatchControlPoints(ct, controlPoints, atlas, result.controlNames);
  if (!options.trustControlPoints)
    CheckControlPointConfiguration(atlas, result.controlNames, result.controlTargets, options.controlPointBounds);
  // What the CT's extent misses; refused with what it did not image once the skin is known (CheckImagedFace).
  result.fieldOfViewMissing =
    MissingFieldOfView(ct, atlas, options.registration.skinSet, result.controlTargets, options.fieldOfViewMargin);
  // The maps of R cover at least the face region: a spacing that cannot fit it is refused now.
  if (std::array<double, 6> face; FaceRegionBounds(atlas, options.registration.skinSet, result.controlTargets, face))
    CheckDistanceMapGrid(face, options.registration.mapMargin, options.registration.mapSpacing, "--mapSpacing");
}

// With --reorientToFace, a face the control points show turned: the CT's header and the points turned
// upright (result.reorientation); otherwise the CT as it is.
CTImage::ConstPointer Reoriented(const CTImage* ct, std::vector<Landmark>& controlPoints, const FEMesh& atlas,
                                 const FaceModelOptions& options, FaceModelResult& result)
{
  if (!options.reorientToFace || ct == nullptr)
    return ct;
  std::vector<std::string> names;
  const auto targets = MatchControlPoints(ct, controlPoints, atlas, names);
  try
  {
    result.reorientation = FaceUprightRotation(atlas, targets, options.controlPointBounds.maxTurn);
  }
  catch (const std::invalid_argument&)
  {
    return ct; // points that place no face: CheckInputs says so
  }
  if (!result.reorientation.applied)
    return ct;
  for (auto& p : controlPoints)
    p.position = result.reorientation.rotation * p.position;
  return ReorientedCT(ct, result.reorientation.rotation).GetPointer();
}

// After the surfaces: the control points on the skin, and the face region inside the CT's extent
// and imaged (not cut by the reconstruction circle). Refused unless partial models are allowed.
NotImagedTissue CheckImagedFace(const CTImage* ct, const FEMesh& atlas, const FaceModelOptions& options,
                                FaceModelResult& result)
{
  if (!options.trustControlPoints)
    CheckControlPointsOnSkin(result.skin, result.controlNames, result.controlTargets, options.controlPointBounds);
  NotImagedTissue notImaged;
  std::array<double, 6> face;
  if (FaceRegionBounds(atlas, options.registration.skinSet, result.controlTargets, face))
  {
    for (unsigned a = 0; a < 3; ++a)
    {
      face[2 * a] -= options.fieldOfViewMargin;
      face[2 * a + 1] += options.fieldOfViewMargin;
    }
    notImaged = FindNotImagedTissue(ct, result.thresholds.skin, &face);
    result.notImaged = NotImagedMessage(NotImagedRegions(atlas, result.controlTargets, notImaged), notImaged);
  }
  if (options.allowPartialFieldOfView || (result.notImaged.empty() && result.fieldOfViewMissing.empty()))
    return notImaged;
  std::string why = result.notImaged;
  if (!result.fieldOfViewMissing.empty())
  {
    char margin[120];
    std::snprintf(margin, sizeof margin, " (the face region, placed by the control points, needs a %.0f mm margin)",
                  options.fieldOfViewMargin);
    why += (why.empty() ? "the CT does not cover the face: it misses the " : "; the CT also misses the ") +
           result.fieldOfViewMissing + margin;
  }
  throw std::runtime_error(why + "; --allowPartialFieldOfView builds a partial model");
}

} // namespace

FaceModelResult BuildFaceModel(const CTImage* storedCT, const std::vector<Landmark>& storedPoints, const FEMesh& atlas,
                               const FaceModelOptions& options)
{
  FaceModelResult result;
  std::vector<Landmark> controlPoints = storedPoints;
  const CTImage::ConstPointer ct = Reoriented(storedCT, controlPoints, atlas, options, result);
  CheckInputs(ct, controlPoints, atlas, options, result);
  const auto t0 = Clock::now();
  const double weights[] = {0.25, 0.15, 0.35, 0.1, 0.1, 0.05}; // share of the time, per stage
  std::size_t stageIndex = 0;
  double done = 0;
  auto report = [&](const std::string& name, double f) {
    if (options.progress)
      options.progress(name, std::min(1.0, done + weights[stageIndex] * f));
  };
  auto finish = [&](const std::string& name, Clock::time_point start) {
    result.times.push_back({name, Since(start)});
    done += weights[stageIndex++];
    if (options.progress)
      options.progress(name, std::min(1.0, done));
  };

  // 1. Surfaces.
  auto t = Clock::now();
  auto surfaces = ExtractSubjectSurfaces(ct, options, [&](double f) { report("surfaces", f); });
  result.thresholds = surfaces.thresholds;
  result.skin = surfaces.skin;
  result.skull = surfaces.skull;
  const NotImagedTissue notImaged = CheckImagedFace(ct, atlas, options, result);
  finish("surfaces", t);

  // 2. Symmetry plane.
  t = Clock::now();
  const auto plane = EstimateSubjectPlane(result.skin, options);
  result.plane = plane.plane;
  result.planeResidual = plane.rmsResidual;
  finish("symmetry plane", t);

  // 3. Registration R (its distance maps included).
  t = Clock::now();
  SubjectData subject;
  subject.skin = result.skin;
  subject.skull = result.skull;
  subject.plane = result.plane;
  for (std::size_t i = 0; i < result.controlNames.size(); ++i)
    subject.controlPoints.push_back({result.controlNames[i], result.controlTargets[i]});
  auto registrationOptions = options.registration;
  registrationOptions.progress = [&](double f) { report("registration", f); };
  const Plane atlasPlane = FitPlaneToNodeSet(atlas, "midsagittal");
  std::vector<char> fittedHalf(atlas.nodes.size());
  for (std::size_t i = 0; i < atlas.nodes.size(); ++i)
    fittedHalf[i] = atlasPlane.SignedDistance(atlas.nodes[i]) >= -1e-3;
  result.fitted = !options.registration.symmetric ? "whole face (asymmetric fit)"
                  : options.registration.halfFace ? "left half (half-face: the right half is its mirror image)"
                                                  : "both halves, averaged (symmetric fit)";
  auto r = RegisterAtlas(atlas, atlasPlane, subject, registrationOptions);
  result.registration = std::move(r.transform);
  result.registrationReport = std::move(r.report);
  result.registered = r.mesh;
  result.accuracy.push_back(Measure("R", r.mesh, result.skin, result.skull, result.controlNames, result.controlTargets,
                                    options.registration, fittedHalf));
  finish("registration", t);

  // 4. Lips refinement Q.
  t = Clock::now();
  FEMesh refined;
  if (options.refine)
  {
    auto refineOptions = RefinementOptionsFor(options, result.plane);
    refineOptions.progress = [&](double f) { report("refinement", f); };
    auto q = RefineLocally(r.mesh, result.skin, refineOptions);
    result.refinement = std::move(q.transform);
    refined = std::move(q.mesh);
  }
  else
    refined = std::move(r.mesh);
  result.refined = refined;
  result.accuracy.push_back(Measure("Q∘R", refined, result.skin, result.skull, result.controlNames,
                                    result.controlTargets, options.registration, fittedHalf));
  finish("refinement", t);

  // 5. Repair (inner nodes first, surface nodes slide on the subject's surfaces, symmetry kept).
  // With R's and Q's mesh guard on, every element already meets the guard's floor and the repair
  // only acts when the threshold is above it.
  t = Clock::now();
  result.model = std::move(refined);
  result.qualityAfterQ = quality::SummarizeScaledJacobian(result.model, options.repairThreshold);
  const auto skinNearModel = CropSurfaceAround(result.skin, result.model, kRepairSurfaceMargin);
  const auto skullNearModel = CropSurfaceAround(result.skull, result.model, kRepairSurfaceMargin);
  RepairOptions repair;
  repair.scaledJacobianThreshold = options.repairThreshold;
  repair.maximumSweeps = options.repairSweeps;
  repair.skinSurface = skinNearModel;
  repair.skullSurface = skullNearModel;
  repair.hasSymmetryPlane = options.registration.symmetric;
  repair.symmetryPlane = result.plane;
  repair.progress = [&](double f) { report("repair", f); };
  result.repair = RepairMesh(result.model, repair);
  finish("repair", t);

  // 6. Muscles through Q∘R, embedded in the repaired mesh.
  t = Clock::now();
  result.muscles = InferMuscles(
    atlas, [&](const Point3& x) { return result.AtlasToSubject(x); }, result.model);
  if (const auto cut = NodesOnNotImagedSkin(result.model, options.registration.skinSet, notImaged, 3.0); !cut.empty())
  {
    result.model.nodeSets["notImaged"] = cut;
    result.notImagedNodes = cut.size();
  }
  result.accuracy.push_back(Measure("repaired", result.model, result.skin, result.skull, result.controlNames,
                                    result.controlTargets, options.registration, fittedHalf));
  finish("muscles", t);
  result.poorFit = PoorFit(result.accuracy.back(), result.controlNames, options);
  result.totalSeconds = Since(t0);
  return result;
}

vtkSmartPointer<vtkPolyData> ModelSkinSurface(const FEMesh& mesh, const std::string& skinSet)
{
  const std::vector<char> onSkin = NodeSetMask(mesh, skinSet);
  return BoundaryPolygons(mesh, &onSkin);
}

} // namespace mmrep
