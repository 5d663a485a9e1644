// MMRep atlas-to-subject registration (paper §3.1–3.3): control-point similarity, symmetric
// multi-level elastic registration R of the atlas onto the subject's skin and skull, and the
// local lips refinement Q. See README.md in this folder for the design.
//
//   auto r = mmrep::RegisterAtlas(atlas, atlasPlane, subject, options);   // R
//   auto q = mmrep::RefineLocally(r.mesh, subject.skin, refineOptions);    // Q, on R's output
//   q.mesh: Q∘R of the atlas; every node moves (muscle nodes are mesh nodes), landmarks too.
#pragma once

#include "mmrepElasticOptimizer.h"
#include "mmrepElasticTransform.h"
#include "mmrepFEMesh.h"
#include "mmrepImageIO.h"
#include "mmrepSymmetryPlane.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <functional>
#include <string>
#include <vector>

namespace mmrep
{

struct AtlasRegistrationOptions
{
  // Finest grid level (2^level cells per axis); 0: automatic, the finest level whose smallest
  // cell is at least `minimumCellVoxels` distance-map voxels (finer cells cannot see more of the
  // map; level 5 on the bundled CTs).
  int finestLevel = 0;
  double minimumCellVoxels = 2.0;
  double mapSpacing = 1.5;    // mm, distance maps of the subject skin and skull
  // Signed maps (negative inside) when a surface is closed: the energy uses |d| either way, but
  // trilinear interpolation of a signed map crosses zero at the surface, while that of |d| rounds
  // off its V by up to about a quarter of the spacing. Open surfaces fall back to unsigned maps.
  bool signedMaps = true;
  double mapMargin = 15.0;    // mm, around the subject surfaces
  double gridMargin = 0.10;   // box of the aligned atlas points grown by this fraction per side
  double stepSafety = 0.4;    // |δ| ≤ stepSafety / max|∇φ|
  int maximumSweeps = 10;     // per level
  double tolerance = 5e-3;    // relative energy decrease per sweep that ends a level
  double controlPointWeight = 10.0;    // initial W_i (one skin node counts 1)
  double controlPointTolerance = 0.5;  // mm: W_i doubles while the control point is farther
  double controlPointWeightCap = 1000; // upper bound of W_i
  bool symmetric = true;      // mirrored steps about the subject plane (needs a symmetric atlas)
  // With `symmetric`: the paper's half-face registration (§3.2). Only the atlas's left half (patient
  // left, the +x side of the atlas plane) and its plane nodes are attracted to the subject; the
  // right half follows through the mirrored steps, so the model is the fitted left half and its
  // mirror image. Off: the averaged symmetric fit, both halves attracted (the subject's asymmetry
  // is split between them). Without `symmetric` (the full fit) this has no effect.
  bool halfFace = true;
  // Regularisation from level `regularizationFirstLevel` on (mmrepElasticOptimizer.h), so that the
  // fine levels fit the surfaces without shifting the tissue behind them: the holding term μ_h (per
  // mm²) on the inner nodes (on by default, chosen with CorrespondenceBenchmark), the sliding term
  // μ_s on the surface nodes (off: it also resists the sliding a real speaker's shape needs).
  double slidingWeight = 0.0;
  double holdingWeight = 0.5;
  int regularizationFirstLevel = 2;
  // Mesh guard (mmrepElasticOptimizer.h): every atlas node is moved along and no step may bring a
  // hexahedron below this scaled Jacobian (or lower one already below). Negative: no guard.
  double elementQualityFloor = 0.3;
  // Tie μ (per mm², mmrepElasticOptimizer.h): every attracted node tied to its start, trading
  // surface fit for correspondence; superseded by the holding term, off by default.
  double tieWeight = 0.0;
  // Node sets of the atlas: attracted to the subject skin / skull; `lips` is only reported.
  std::string skinSet = "skin", skullSet = "skull", lipsSet = "lips";
  std::function<void(double)> progress; // fraction in [0, 1]
};

// The subject: surfaces (LPS mm), optional precomputed distance maps (computed when null),
// control points (matched to the atlas landmarks by name) and the symmetry plane.
struct SubjectData
{
  vtkSmartPointer<vtkPolyData> skin, skull;
  FloatImage::Pointer skinMap, skullMap;
  std::vector<Landmark> controlPoints;
  Plane plane;
};

struct SurfaceErrorStatistics
{
  std::size_t count = 0;
  double mean = 0, max = 0, sigma = 0; // mm, node to the surface triangles
};

struct RegistrationStage
{
  std::string name; // "similarity", "elastic", "refinement"
  double seconds = 0;
  SurfaceErrorStatistics skin, skull, lips;
  double controlMean = 0, controlMax = 0; // mm
  bool controlMeasured = false;           // the control-point errors above were measured
  std::vector<std::size_t> stepsPerLevel;
  std::vector<int> sweepsPerLevel;
  double energyBefore = 0, energyAfter = 0;
};

struct RegistrationReport
{
  std::vector<RegistrationStage> stages;
  std::vector<std::string> controlNames;
  std::vector<double> controlErrors;  // mm, after the last stage
  std::vector<double> controlWeights; // final W_i
  std::string ToJson() const;         // pretty-printed JSON
  // Markdown tables like the paper's Tables 1–2: per stage, skin / skull / lips errors (mean, max,
  // σ, mm, to the subject's triangles), control-point mean / max, steps and time; then the control
  // points one by one. A statistic that was not measured at a stage (count 0) shows as "—".
  std::string ToMarkdown(const std::string& title = "Registration report") const;
  const RegistrationStage& Last() const { return stages.back(); }
};

struct AtlasRegistrationResult
{
  ElasticTransform transform; // atlas (world) -> subject (world), similarity included
  FEMesh mesh;                // registered atlas
  RegistrationReport report;
};

// The three symmetry modes by name: "half-face" (symmetric, half-face), "averaged" (symmetric, both
// halves attracted), "full" (no symmetry). Throws std::invalid_argument for another name.
void SetSymmetryMode(AtlasRegistrationOptions& options, const std::string& mode);
std::string SymmetryModeName(const AtlasRegistrationOptions& options);

// Throws std::invalid_argument (bad sets, control point names, planes) or std::runtime_error
// (empty surfaces, atlas and subject not overlapping after the alignment), one line each.
AtlasRegistrationResult RegisterAtlas(const FEMesh& atlas, const Plane& atlasPlane, const SubjectData& subject,
                                      const AtlasRegistrationOptions& options = {});

struct LocalRefinementOptions
{
  double spacing = 0.5;  // mm, fine skin distance map over the refinement box
  bool signedMap = true; // signed when the skin is closed (see AtlasRegistrationOptions::signedMaps)
  // Finest level of Q's grid; 0: automatic (smallest cell ≥ minimumCellVoxels × spacing).
  int finestLevel = 0;
  double minimumCellVoxels = 2.0;
  double boxMargin = 0.25;   // the region set's bounding box grown by this fraction per side…
  double minimumMargin = 4;  // …and by at least this many mm
  double stepSafety = 0.4;
  int maximumSweeps = 30;
  double tolerance = 1e-4;
  // Region to refine and the nodes attracted: skin nodes inside the box (the region's own skin
  // nodes and their neighbours, which Q moves too and must stay on the skin).
  std::string regionSet = "lips", skinSet = "skin";
  // Pins: nodes of `skullSet` and the mesh's landmarks (control points) inside the box are held
  // where R put them (energy term pinWeight × displacement, raised like a control point's weight
  // while one is off by more than 0.5 mm); without them Q drags the skull nodes under the lips and
  // the lip control points along with the skin. pinWeight 0 disables.
  std::string skullSet = "skull";
  double pinWeight = 1.0;
  bool symmetric = false; // mirrored steps about `plane` (keeps a symmetric mesh symmetric)
  bool halfFace = false;  // with `symmetric`: only skin nodes on the left of `plane` (and on it) are attracted
  Plane plane;
  double slidingWeight = 0.0; // sliding and holding terms, as AtlasRegistrationOptions
  double holdingWeight = 0.25;
  int regularizationFirstLevel = 1;
  double elementQualityFloor = 0.3; // mesh guard, as AtlasRegistrationOptions; negative: none
  std::function<void(double)> progress;
};

struct LocalRefinementResult
{
  ElasticTransform transform; // Q (world -> world, identity outside the box)
  FEMesh mesh;
  RegistrationStage before, after; // errors of the region's skin nodes in `lips`, all skin in `skin`
  Eigen::Vector3d boxMin = Eigen::Vector3d::Zero(), boxMax = Eigen::Vector3d::Zero(); // frame coords
  // Stages "R (before refinement)" and "Q∘R", lips = the region's skin nodes (for ToMarkdown/ToJson).
  RegistrationReport Report() const;
};

// Appends Q's stage to R's report: "refinement" with the lips and skin errors after Q∘R, and, when
// `subjectControlPoints` are given, the control-point errors of the refined mesh's landmarks.
void AddRefinementStage(RegistrationReport& report, const LocalRefinementResult& refinement,
                        const std::vector<Landmark>& subjectControlPoints = {});

LocalRefinementResult RefineLocally(const FEMesh& registered, vtkPolyData* skin,
                                    const LocalRefinementOptions& options = {});

// Moves every node and landmark of the mesh by the transform.
void ApplyTransform(const ElasticTransform& transform, FEMesh& mesh);

// Node-to-triangle distances of the given nodes (vtkStaticCellLocator).
SurfaceErrorStatistics MeasureSurfaceError(const std::vector<Point3>& nodes, const std::vector<std::int32_t>& ids,
                                           vtkPolyData* surface);

// FitPlaneToNodeSet (a node set's least-squares plane) is in mmrepPlane.h (MMRepFE).

} // namespace mmrep
