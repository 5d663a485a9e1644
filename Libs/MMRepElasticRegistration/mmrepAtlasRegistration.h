// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
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
#include "mmrepSurfaceDistance.h"
#include "mmrepImageIO.h"
#include "mmrepSymmetryPlane.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <functional>
#include <string>
#include <vector>

namespace mmrep
{

// The solver settings (mmrepElasticOptimizer.h) with R's defaults: at most 10 sweeps per level, a
// level ends below a 5e-3 relative decrease, mirrored steps, the holding term on (μ_h = 0.5 per mm²
// from level 2 on, chosen with CorrespondenceBenchmark, so that the fine levels fit the surfaces
// without shifting the tissue behind them), the sliding term off (it also resists the sliding a
// real speaker's shape needs), the tie off (superseded by the holding term), the mesh guard at 0.3
// (every atlas node is moved along and no step may bring a hexahedron below that scaled Jacobian;
// negative: no guard). Control point weights W_i start at `controlPointWeight` (one skin node
// counts 1) and double, up to controlPointWeightCap, while the point is farther than
// controlPointTolerance (mm).
struct AtlasRegistrationOptions : ElasticSolverSettings
{
  AtlasRegistrationOptions()
  {
    maximumSweeps = 10;
    tolerance = 5e-3;
    symmetric = true; // mirrored steps about the subject plane (needs a symmetric atlas)
    holdingWeight = 0.5;
    regularizationFirstLevel = 2;
  }
  // Finest grid level (2^level cells per axis); 0: automatic, the finest level whose smallest
  // cell is at least `minimumCellVoxels` distance-map voxels (finer cells cannot see more of the
  // map; level 5 on the bundled CTs).
  int finestLevel = 0;
  double minimumCellVoxels = 2.0;
  double mapSpacing = 1.5; // mm, distance maps of the subject skin and skull
  // Signed maps (negative inside) when a surface is closed: the energy uses |d| either way, but
  // trilinear interpolation of a signed map crosses zero at the surface, while that of |d| rounds
  // off its V by up to about a quarter of the spacing. Open surfaces fall back to unsigned maps.
  bool signedMaps = true;
  double mapMargin = 15.0;          // mm, around the subject surfaces
  double gridMargin = 0.10;         // box of the aligned atlas points grown by this fraction per side
  double controlPointWeight = 10.0; // initial W_i
  // With `symmetric`: the paper's half-face registration (§3.2). Only the atlas's left half (patient
  // left, the +x side of the atlas plane) and its plane nodes are attracted to the subject; the
  // right half follows through the mirrored steps, so the model is the fitted left half and its
  // mirror image. Off: the averaged symmetric fit, both halves attracted (the subject's asymmetry
  // is split between them). Without `symmetric` (the full fit) this has no effect.
  bool halfFace = true;
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

struct RegistrationStage
{
  std::string name; // "similarity", "elastic", "refinement"
  double seconds = 0;
  SurfaceDistance skin, skull, lips;
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

// The solver settings (mmrepElasticOptimizer.h) with Q's defaults: up to 30 sweeps per level, a
// level ends below a 1e-4 relative decrease, the holding term 0.25 from level 1 on, the mesh guard
// at 0.3 (negative: none), the sliding term off.
struct LocalRefinementOptions : ElasticSolverSettings
{
  LocalRefinementOptions()
  {
    maximumSweeps = 30;
    tolerance = 1e-4;
    holdingWeight = 0.25;
  }
  double spacing = 0.5;  // mm, fine skin distance map over the refinement box
  bool signedMap = true; // signed when the skin is closed (see AtlasRegistrationOptions::signedMaps)
  // Finest level of Q's grid; 0: automatic (smallest cell ≥ minimumCellVoxels × spacing).
  int finestLevel = 0;
  double minimumCellVoxels = 2.0;
  double boxMargin = 0.25;  // the region set's bounding box grown by this fraction per side…
  double minimumMargin = 4; // …and by at least this many mm
  // Region to refine and the nodes attracted: skin nodes inside the box (the region's own skin
  // nodes and their neighbours, which Q moves too and must stay on the skin).
  std::string regionSet = "lips", skinSet = "skin";
  // Pins: nodes of `skullSet` and the mesh's landmarks (control points) inside the box are held
  // where R put them (energy term pinWeight × displacement, raised like a control point's weight
  // while one is off by more than 0.5 mm); without them Q drags the skull nodes under the lips and
  // the lip control points along with the skin. pinWeight 0 disables.
  std::string skullSet = "skull";
  double pinWeight = 1.0;
  // `symmetric`: mirrored steps about `plane` (keeps a symmetric mesh symmetric); with it,
  // `halfFace`: only skin nodes on the left of `plane` (and on it) are attracted.
  bool halfFace = false;
  Plane plane;
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

// FitPlaneToNodeSet (a node set's least-squares plane) is in mmrepPlane.h (MMRepFE).

} // namespace mmrep
