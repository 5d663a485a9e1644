// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The multi-level virtual-grid optimiser that builds the steps of an ElasticTransform by
// decreasing the registration energy (paper Eq. 2)
//   E = Σ_points |d_map(p)(R(a))| + Σ_i W_i |R(ā_i) − s̄_i|
// (d = trilinear distance maps, signed or unsigned; every point is tracked in frame coordinates).
//
// Per level ℓ (2^ℓ cells per axis over the box): sweeps over the grid nodes whose support holds
// points, in a fixed (z, y, x) order. For each node: the energy gradient with respect to its
// displacement, g = Σ φ(p) ∇e(p) (+ the mirror node's mirrored terms), then a backtracking line
// search along −g from the largest non-folding step safety/L (halving, at most 12 times; the
// better of the first decreasing step and its half is kept). A step is recorded only when it
// lowers the energy. The level ends when a sweep lowers E by less than `tolerance` (relative) or
// after `maximumSweeps`. The paper moves the single node of largest gradient at a time; sweeping
// every node once per pass gives the same kind of descent with far fewer gradient evaluations.
// After each sweep the weight of every control point farther than `controlPointTolerance` from
// its target doubles (up to the cap).
//
// Mesh guard (optional): R is a diffeomorphism, yet at the finest levels it bends on the scale of
// the atlas's thin layers, and a hexahedron whose outer and inner faces are bent differently
// turns inside out (on the bundled CT, 2900 of 11016 elements after R at level 5, none at
// level 3). With `hexahedra` given, a step is taken only when every hexahedron it moves keeps a
// scaled Jacobian of at least `elementQualityFloor` (or does not lose any, when it was already
// below); otherwise the step is halved up to 4 times, then dropped. The surfaces are then fitted
// as far as the mesh allows, instead of as far as the transform allows.
//
// Single-threaded and in a fixed order: results are the same bytes on every run.
#pragma once

#include "mmrepDistanceMapSampler.h"
#include "mmrepElasticTransform.h"

#include <array>
#include <functional>
#include <vector>

namespace mmrep
{

// The solver settings shared by the optimiser and the registrations that drive it (R, Q): their
// option structs derive from it, so a registration hands its settings over in one assignment.
struct ElasticSolverSettings
{
  double stepSafety = 0.4;             // |δ| ≤ stepSafety / L (< 1 guarantees non-folding)
  int maximumSweeps = 20;              // per level
  double tolerance = 1e-3;             // relative energy decrease of a sweep below which the level ends
  bool symmetric = false;              // mirrored steps about frame x = 0 (box must be symmetric in x)
  double controlPointTolerance = 0.5;  // mm
  double controlPointWeightCap = 1000; // weights double up to this
  double elementQualityFloor = 0.3;    // scaled Jacobian the guarded hexahedra keep (see above)
  // Tie: μ |p − p₀|² per attracted point (p₀ = its start): the distance terms do not see sliding
  // along a surface, so without it the greedy steps drift tissue tangentially. 0 = off.
  double tieWeight = 0.0;
  // Sliding: μ_s |P(p − p_ℓ)|² per attracted point, P the projection on the tangent plane of its
  // surface at p_ℓ, its position when level ℓ starts (normal = the map gradient there). Surface
  // distances do not see a node moving along its surface, so without this term the fine levels
  // slide tissue tangentially wherever that lowers another node's distance; with it a level may
  // move nodes along their normals freely, and along the surface only as far as the smooth coarse
  // levels already did. Applied from level `regularizationFirstLevel` on (coarse levels carry the global
  // shape). 0 = off.
  double slidingWeight = 0.0;
  // Holding: μ_h |p − p_ℓ|² per held point (pointMap −2: the atlas's inner nodes, attached to no
  // surface). A grid node deep in the tissue moves them freely while the few surface points at the
  // edge of its support barely move; that step lowers the energy, so without this term the fine
  // levels shift the inside of the face (muscles) while the surfaces stay put. The cost is
  // quadratic in the step and the surfaces' gain linear, so steps that the surfaces need still pass.
  double holdingWeight = 0.0;
  int regularizationFirstLevel = 1; // first level of the sliding and holding terms
};

struct ElasticOptimizerOptions : ElasticSolverSettings
{
  int firstLevel = 1;
  int finestLevel = 5;
  bool fixBoundary = false; // only interior grid nodes move (local refinement)
  std::function<void(double)> progress;
};

struct ElasticProblem
{
  std::vector<DistanceMapSampler> maps;
  // Tracked points in frame coordinates, each attracted by maps[pointMap[k]]; pointMap[k] = −1: a
  // passive point (no energy), moved along for the mesh guard; −2: a held point (holdingWeight).
  std::vector<Eigen::Vector3d> points;
  std::vector<int> pointMap;
  // Mesh guard: hexahedra over `points` (8 indices, VTK order); empty = no guard.
  std::vector<std::array<int, 8>> hexahedra;
  // Control points: tracked sources and fixed targets (frame coordinates), weights.
  std::vector<Eigen::Vector3d> controlSources, controlTargets;
  std::vector<double> controlWeights;
  Eigen::Vector3d boxMin = Eigen::Vector3d::Zero(), boxMax = Eigen::Vector3d::Zero(); // grid box (frame)
};

struct ElasticOptimizerStats
{
  std::vector<int> sweepsPerLevel;
  std::size_t guardedSteps = 0, droppedSteps = 0; // steps shortened / dropped by the mesh guard
  std::vector<double> energyAfterLevel;
  double initialEnergy = 0;
};

// Appends one ElasticLevel per level to `transform` (whose frame must be set) and moves the
// problem's points and control sources along. Calls transform.BuildIndex() at the end.
ElasticOptimizerStats OptimizeElastic(ElasticTransform& transform, ElasticProblem& problem,
                                      const ElasticOptimizerOptions& options);

// Energy of the problem in its current state (same terms as the optimiser).
double ElasticEnergy(const ElasticTransform& transform, const ElasticProblem& problem);

} // namespace mmrep
