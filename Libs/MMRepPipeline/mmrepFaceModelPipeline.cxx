#include "mmrepFaceModelPipeline.h"
#include "mmrepFieldOfView.h"

#include "mmrepCanonicalVoxelOrder.h"
#include "mmrepHeadSegmentation.h"
#include "mmrepSurfaceDistanceMap.h"
#include "mmrepSurfaceExtraction.h"
#include "mmrepSymmetryPlane.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkBox.h>
#include <vtkExtractPolyDataGeometry.h>

#include <algorithm>
#include <chrono>
#include <cmath>
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
  a.skin = MeasureSurfaceError(mesh.nodes, set(sets.skinSet, false), skin);
  a.skull = MeasureSurfaceError(mesh.nodes, set(sets.skullSet, false), skull);
  a.lips = MeasureSurfaceError(mesh.nodes, set(sets.lipsSet, false), skin);
  a.skinHalf = MeasureSurfaceError(mesh.nodes, set(sets.skinSet, true), skin);
  a.skullHalf = MeasureSurfaceError(mesh.nodes, set(sets.skullSet, true), skull);
  a.lipsHalf = MeasureSurfaceError(mesh.nodes, set(sets.lipsSet, true), skin);
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

} // namespace

std::vector<Point3> MatchControlPoints(const CTImage* ct, const std::vector<Landmark>& points, const FEMesh& atlas,
                                       std::vector<std::string>& names)
{
  if (points.empty())
    throw std::invalid_argument("control points: none given (the atlas needs " +
                                std::to_string(atlas.landmarks.size()) + ")");
  if (atlas.landmarks.empty())
    throw std::invalid_argument("atlas: it has no landmarks to match control points with");
  std::map<std::string, Point3> byName;
  for (const auto& p : points)
  {
    if (p.name.empty())
      throw std::invalid_argument("control points: a point has no name");
    if (!byName.emplace(p.name, p.position).second)
      throw std::invalid_argument("control points: '" + p.name + "' is given twice");
  }
  std::vector<Point3> targets;
  for (const auto& l : atlas.landmarks)
  {
    const auto it = byName.find(l.name);
    if (it == byName.end())
      throw std::invalid_argument("control points: '" + l.name + "' is missing (the atlas landmarks are named" +
                                  [&] {
                                    std::string s;
                                    for (const auto& a : atlas.landmarks)
                                      s += " " + a.name;
                                    return s;
                                  }() +
                                  ")");
    bool inside = it->second.allFinite();
    if (ct != nullptr && inside)
    {
      const auto region = ct->GetLargestPossibleRegion();
      CTImage::PointType p;
      for (unsigned a = 0; a < 3; ++a)
        p[a] = it->second[a];
      const auto index = ct->TransformPhysicalPointToContinuousIndex<double>(p);
      for (unsigned a = 0; a < 3 && inside; ++a)
        inside = index[a] >= static_cast<double>(region.GetIndex(a)) - 0.5 &&
                 index[a] <= static_cast<double>(region.GetIndex(a) + static_cast<long>(region.GetSize(a))) - 0.5;
    }
    if (!inside)
    {
      std::ostringstream s;
      s << "control points: '" << l.name << "' at (" << it->second.x() << ", " << it->second.y() << ", "
        << it->second.z() << ") mm LPS lies outside the CT volume (check the coordinate system: LPS vs RAS)";
      throw std::invalid_argument(s.str());
    }
    names.push_back(l.name);
    targets.push_back(it->second);
  }
  for (const auto& p : points)
    if (std::none_of(atlas.landmarks.begin(), atlas.landmarks.end(), [&](const Landmark& l) { return l.name == p.name; }))
      throw std::invalid_argument("control points: '" + p.name + "' is not an atlas landmark");
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
  q.symmetric = options.registration.symmetric;
  q.halfFace = options.registration.symmetric && options.registration.halfFace;
  q.plane = plane;
  return q;
}

namespace
{
// The atlas is valid and has the node sets and muscles the stages use.
void CheckAtlas(const FEMesh& atlas, const FaceModelOptions& options)
{
  atlas.Validate();
  for (const auto& set : {options.registration.skinSet, options.registration.skullSet, options.registration.lipsSet,
                          std::string("midsagittal")})
    if (!atlas.nodeSets.count(set))
      throw std::invalid_argument("atlas: node set '" + set + "' is missing");
  if (atlas.muscles.empty())
    throw std::invalid_argument("atlas: it has no muscle tracks");
}
} // namespace

FaceModelResult BuildFaceModel(const CTImage* ct, const std::vector<Landmark>& controlPoints, const FEMesh& atlas,
                               const FaceModelOptions& options)
{
  if (ct == nullptr)
    throw std::invalid_argument("face model: no CT image");
  CheckAtlas(atlas, options);

  FaceModelResult result;
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

  result.controlTargets = MatchControlPoints(ct, controlPoints, atlas, result.controlNames);
  if (options.allowPartialFieldOfView)
    result.fieldOfViewMissing =
      MissingFieldOfView(ct, atlas, options.registration.skinSet, result.controlTargets, options.fieldOfViewMargin);
  else
    CheckFieldOfView(ct, atlas, options.registration.skinSet, result.controlTargets, options.fieldOfViewMargin);
  // The maps of R cover at least the face region: a spacing that cannot fit it is refused now.
  if (std::array<double, 6> face; FaceRegionBounds(atlas, options.registration.skinSet, result.controlTargets, face))
    CheckDistanceMapGrid(face, options.registration.mapMargin, options.registration.mapSpacing, "--mapSpacing");

  // 1. Surfaces.
  auto t = Clock::now();
  auto surfaces = ExtractSubjectSurfaces(ct, options, [&](double f) { report("surfaces", f); });
  result.thresholds = surfaces.thresholds;
  result.skin = surfaces.skin;
  result.skull = surfaces.skull;
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
  result.accuracy.push_back(Measure("R", r.mesh, result.skin, result.skull, result.controlNames,
                                    result.controlTargets, options.registration, fittedHalf));
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
  result.muscles = InferMuscles(atlas, [&](const Point3& x) { return result.AtlasToSubject(x); }, result.model);
  result.accuracy.push_back(Measure("repaired", result.model, result.skin, result.skull, result.controlNames,
                                    result.controlTargets, options.registration, fittedHalf));
  finish("muscles", t);
  result.totalSeconds = Since(t0);
  return result;
}

vtkSmartPointer<vtkPolyData> ModelSkinSurface(const FEMesh& mesh, const std::string& skinSet)
{
  std::vector<char> onSkin(mesh.nodes.size(), 0);
  if (const auto it = mesh.nodeSets.find(skinSet); it != mesh.nodeSets.end())
    for (const auto n : it->second)
      onSkin[static_cast<std::size_t>(n)] = 1;
  // Boundary faces = faces used by exactly one solid; VTK's local face orders.
  static const std::vector<std::vector<int>> hexFaces = {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                                         {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  static const std::vector<std::vector<int>> wedgeFaces = {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
  static const std::vector<std::vector<int>> tetFaces = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {0, 2, 1}};
  std::map<std::vector<std::int32_t>, std::pair<int, std::vector<std::int32_t>>> faces; // sorted key -> (uses, face)
  for (const auto& e : mesh.elements)
  {
    const auto* local = e.type == ElementType::Hexahedron ? &hexFaces
                        : e.type == ElementType::Wedge    ? &wedgeFaces
                        : e.type == ElementType::Tetrahedron ? &tetFaces
                                                             : nullptr;
    if (!local)
      continue;
    for (const auto& f : *local)
    {
      std::vector<std::int32_t> face;
      for (int k : f)
        face.push_back(e.nodes[static_cast<std::size_t>(k)]);
      auto key = face;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      if (entry.first++ == 0)
        entry.second = face;
    }
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.nodes.size()));
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.nodes[i].data());
  vtkNew<vtkCellArray> polys;
  for (const auto& [key, entry] : faces)
  {
    if (entry.first != 1)
      continue;
    if (!std::all_of(entry.second.begin(), entry.second.end(), [&](std::int32_t n) { return onSkin[static_cast<std::size_t>(n)]; }))
      continue;
    std::vector<vtkIdType> ids(entry.second.begin(), entry.second.end());
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(polys);
  return surface;
}

} // namespace mmrep
