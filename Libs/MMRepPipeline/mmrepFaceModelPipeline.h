// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The speaker model pipeline (paper §3, whole): CT -> skin and skull surfaces -> symmetry plane
// -> elastic registration R of the atlas (distance maps inside) -> lips refinement Q -> repair
// -> muscles carried through Q∘R. One call, usable from C++; the FaceModelPipeline module wraps it
// and writes the files, the report and the pictures.
//
//   mmrep::FaceModelOptions options;                    // every stage's parameters
//   auto model = mmrep::BuildFaceModel(ct, controlPoints, atlas, options);
//   model.model: the FE face model of the speaker (LPS mm), model.times: seconds per stage.
#pragma once

#include "mmrepAtlasRegistration.h"
#include "mmrepControlPointPlausibility.h"
#include "mmrepHeadReorientation.h"
#include "mmrepCTThresholds.h"
#include "mmrepMeshQuality.h"
#include "mmrepMeshRepair.h"
#include "mmrepMuscleInference.h"

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace mmrep
{

struct FaceModelOptions
{
  // Image stage (SkinSkullSurfaces): thresholds chosen automatically unless given.
  ThresholdMode thresholdMode = ThresholdMode::Automatic;
  double skinThreshold = std::numeric_limits<double>::quiet_NaN();
  double boneThreshold = std::numeric_limits<double>::quiet_NaN();
  unsigned int openingRadius = 1;
  // Axial slits of the skin mask up to this height (mm) are closed (CloseAxialSlits): the lips
  // meet at rest, as in the atlas, instead of the skin diving into the lip slit. 0: keep them.
  double closeSlits = 4.0;
  SymmetryPlaneOptions plane;            // mid-sagittal plane of the skin
  AtlasRegistrationOptions registration; // R (progress is set by the pipeline)
  bool refine = true;                    // Q over the lips
  LocalRefinementOptions refinement;     // Q (plane, symmetry, progress and R's quality floor set by the pipeline)
  double repairThreshold = 0.3;          // scaled Jacobian every element must reach
  int repairSweeps = 40;                 // a model that needs more is better re-registered than ground on
  double fieldOfViewMargin = 5;          // mm the CT must extend past the face region (mmrepFieldOfView.h)
  // A CT that misses part of the face region is refused unless this is set: the model is then built
  // all the same, with the missing part in FaceModelResult::fieldOfViewMissing (its shape there is
  // the atlas's, pulled towards whatever skin the CT holds).
  // A CT whose head reaches the scanner's reconstruction circle (mmrepNotImaged.h) likewise: the
  // model's skin nodes on the cut go into node set `notImaged`, the regions into notImagedRegions.
  bool allowPartialFieldOfView = false;
  // Control points that contradict the anatomy (mmrepControlPointPlausibility.h) are refused before
  // the registration unless the user vouches for them.
  ControlPointBounds controlPointBounds;
  bool trustControlPoints = false;
  // A face that the control points show turned more than the plausibility bound (a wrong orientation
  // header) is turned upright by quarter turns of the CT's header (mmrepHeadReorientation.h) instead
  // of being refused; the model is then in the corrected frame (FaceModelResult::reorientation).
  bool reorientToFace = false;
  // A model whose own accuracy (fitted half, after the repair) exceeds these is a poor fit
  // (FaceModelResult::poorFit): the module then publishes nothing unless told to.
  double poorFitSkin = 1.0, poorFitSkull = 1.5, poorFitControlPoint = 2.0; // mm
  // (stage name, fraction of the whole pipeline done)
  std::function<void(const std::string&, double)> progress;
};

struct StageTime
{
  std::string name;
  double seconds = 0;
};

// Errors of one state of the mesh against the subject surfaces, measured on the mesh itself.
struct ModelAccuracy
{
  std::string state;                             // "R", "Q∘R", "repaired"
  SurfaceDistance skin, skull, lips;             // whole model
  SurfaceDistance skinHalf, skullHalf, lipsHalf; // the fitted (left) half and the plane
  std::vector<double> controlErrors;             // per control point, order of FaceModelResult::controlNames
};

struct FaceModelResult
{
  FEMesh model;                             // the speaker model: repaired, muscles inferred
  FEMesh registered, refined;               // the atlas after R and after Q∘R (for inspection)
  vtkSmartPointer<vtkPolyData> skin, skull; // the subject surfaces (LPS mm)
  CTThresholds thresholds;
  Plane plane;                               // the subject's mid-sagittal plane
  double planeResidual = 0;                  // mm, RMS of the mirrored skin
  ElasticTransform registration, refinement; // R and Q (Q is identity when not refined)
  RegistrationReport registrationReport;     // R's stages as RegisterAtlas reports them
  quality::QualitySummary qualityAfterQ;     // before the repair
  RepairReport repair;
  MuscleInferenceReport muscles;
  std::vector<std::string> controlNames; // atlas landmark names = subject control points
  std::vector<Point3> controlTargets;    // the subject's control points, same order
  std::string fieldOfViewMissing;        // the part of the face the CT misses (partial model), or empty
  std::string notImaged;                 // "the nose tip is outside the scanner's field of view ...", or empty
  std::size_t notImagedNodes = 0;        // skin nodes of the model on the cut (node set `notImaged`)
  HeadReorientation reorientation;       // applied: the CT's header and the control points were turned so
  std::string poorFit;                   // "fitted skull 2.9 mm mean (at most 1.5)", or empty for a good fit
  std::vector<ModelAccuracy> accuracy;   // after R, after Q∘R, after repair
  // Which part of the atlas was fitted to the speaker: "left half" (half-face: the right half is its
  // mirror image), "both halves, averaged" or "whole face (asymmetric)".
  std::string fitted;
  std::vector<StageTime> times;
  double totalSeconds = 0;

  // Q∘R(x), atlas -> subject.
  Point3 AtlasToSubject(const Point3& x) const { return refinement.Apply(registration.Apply(x)); }
};

// Stages 1 and 2 of BuildFaceModel, for callers that register several times onto one subject (the
// benchmarks): the skin and skull surfaces as the pipeline extracts them, and the symmetry plane
// estimated on the decimated skin.
struct SubjectSurfaceSet
{
  vtkSmartPointer<vtkPolyData> skin, skull;
  CTThresholds thresholds;
};
SubjectSurfaceSet ExtractSubjectSurfaces(const CTImage* ct, const FaceModelOptions& options,
                                         const std::function<void(double)>& progress = {});
SymmetryPlaneResult EstimateSubjectPlane(vtkPolyData* skin, const FaceModelOptions& options);
// Q's options as the pipeline sets them after R onto a subject with this plane.
LocalRefinementOptions RefinementOptionsFor(const FaceModelOptions& options, const Plane& plane);

// The control points in the atlas landmarks' order (their names in `names`): each landmark named
// once, no other name; with a CT, each inside its volume. Throws std::invalid_argument otherwise.
std::vector<Point3> MatchControlPoints(const CTImage* ct, const std::vector<Landmark>& points, const FEMesh& atlas,
                                       std::vector<std::string>& names);
// The part of a surface within `margin` mm of the mesh's bounding box, as the repair gets it: every
// node's closest surface point is in it when the node is within `margin` of the surface, and the
// repair's projections query a locator over far fewer triangles.
vtkSmartPointer<vtkPolyData> CropSurfaceAround(vtkPolyData* surface, const FEMesh& mesh, double margin);
inline constexpr double kRepairSurfaceMargin = 20.0; // mm, the margin BuildFaceModel crops with

// Throws std::invalid_argument for inputs that cannot work (control points missing, unnamed,
// outside the CT volume, off the skin or contradicting the atlas's face, an atlas without the sets
// or landmarks), std::runtime_error when a stage fails (no head in the CT, a face the CT does not
// cover or did not image, surfaces not overlapping the atlas). A repair that cannot reach the
// threshold does not throw: result.repair.success says so and the caller decides.
FaceModelResult BuildFaceModel(const CTImage* ct, const std::vector<Landmark>& controlPoints, const FEMesh& atlas,
                               const FaceModelOptions& options = {});

// Skin faces of the model's solids (quadrilaterals/triangles whose nodes are all in `skin`, on the
// boundary), as a surface for pictures and comparisons; point ids are the mesh's node ids.
vtkSmartPointer<vtkPolyData> ModelSkinSurface(const FEMesh& mesh, const std::string& skinSet = "skin");

} // namespace mmrep
