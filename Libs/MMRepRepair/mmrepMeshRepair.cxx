// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Jacobian-based mesh repair, see mmrepMeshRepair.h: the plan (global untangling, node-by-node
// phases, global relaxations of what stays below the threshold, the folds inside elements) and the
// report.
#include "mmrepMeshRepair.h"

#include "mmrepCertifiedJacobian.h"
#include "mmrepEmbedding.h"
#include "mmrepFoldoverFreeUntangling.h"
#include "mmrepLipContact.h"
#include "mmrepMeshQuality.h"
#include "mmrepNodeByNodeRepair.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mmrep
{
namespace
{
constexpr int kRelaxationRounds = 2; // global relaxations of the elements still below the threshold
constexpr int kInsideRuns = 3;       // rounds at most of opening the folds inside elements

// Untangles `seeds` globally; true when the mesh changed. Progress goes from `from` to `to`.
bool UntangleGlobally(FEMesh& mesh, const RepairOptions& options, const NodeElements& adjacency,
                      const RepairConstraints& constraints, const std::vector<std::size_t>& seeds, bool relax,
                      double from, double to, RepairReport& report)
{
  if (seeds.empty())
    return false;
  const auto start = std::chrono::steady_clock::now();
  UntanglingOptions untangling;
  untangling.relaxValid = relax;
  if (relax)
    untangling.initialEps = 1.0; // what the first stage left: the folds a start from 0.1 does not undo
  if (options.progress)
    untangling.progress = [&](double f) { options.progress(from + (to - from) * f); };
  const UntanglingResult result = UntangleFoldovers(mesh, adjacency, constraints, seeds, untangling);
  report.untanglingSteps += result.steps;
  report.untanglingSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result.kept;
}

// Nodes next to the plane that are on the wrong side of it go back: a mirror pair swaps places,
// another node is put on its side.
void RestoreSides(FEMesh& mesh, const RepairConstraints& constraints)
{
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
  {
    if (constraints.OnItsSide(i, mesh.nodes[i]))
      continue;
    const std::size_t partner = constraints.Partner(i);
    if (partner == i)
      mesh.nodes[i] = constraints.Constrain(i, mesh.nodes[i]);
    else if (constraints.Side(partner) == -constraints.Side(i) && !constraints.OnItsSide(partner, mesh.nodes[partner]))
      std::swap(mesh.nodes[i], mesh.nodes[partner]); // mirror images of each other: a swap keeps the symmetry
  }
}

// Once every corner is good, the folds inside elements: node by node with the certified quality,
// the nodes around them only, no element that meets the threshold pushed below it. Opening a fold can
// leave that element just below the threshold at its corners: the corner phase lifts it, and the folds
// are looked at again. Progress from `from` to 1.
void OpenFoldsInside(FEMesh& mesh, const RepairOptions& options, const NodeElements& adjacency,
                     const RepairConstraints& constraints, NodeByNodeRepair& corners, double from)
{
  for (int run = 0; run < kInsideRuns; ++run)
  {
    const double step = (1 - from) / kInsideRuns, start = from + step * run;
    const NodeByNodeRepair::State cornerState = corners.Current();
    if (cornerState.inverted > 0 || cornerState.below > 0)
      return;
    NodeByNodeRepair inside(mesh, options, adjacency, constraints, true);
    const NodeByNodeRepair::State before = inside.Current();
    if (before.inverted == 0)
      return;
    const std::vector<Point3> kept = mesh.nodes;
    inside.Run(start, start + 0.5 * step);
    if (!inside.Current().BetterThan(before))
    {
      mesh.nodes = kept;
      return;
    }
    corners.Reset();
    corners.Run(start + 0.5 * step, start + step);
  }
}

// The repair's plan: the inverted elements untangled globally, then node by node; while elements
// stay below the threshold, the region around them relaxed globally and repaired node by node
// again, each round kept only when it leaves the mesh better.
void Repair(FEMesh& mesh, const RepairOptions& options, RepairReport& report)
{
  const std::vector<Point3> original = mesh.nodes;
  const NodeElements adjacency(mesh);
  const RepairConstraints constraints(mesh, adjacency, options);
  RestoreSides(mesh, constraints);
  NodeByNodeRepair local(mesh, options, adjacency, constraints);
  const bool global = options.globalUntangling;
  if (global && UntangleGlobally(mesh, options, adjacency, constraints, local.BadElements(true), false, 0, 0.4, report))
    local.Reset();
  local.Run(global ? 0.4 : 0, global ? 0.8 : 0.9);
  for (int round = 0; global && round < kRelaxationRounds; ++round)
  {
    const double from = 0.8 + 0.15 * round / kRelaxationRounds, to = 0.8 + 0.15 * (round + 1) / kRelaxationRounds;
    const NodeByNodeRepair::State before = local.Current();
    if (before.below == 0)
      break;
    const std::vector<Point3> kept = mesh.nodes;
    if (!UntangleGlobally(mesh, options, adjacency, constraints, local.BadElements(false), true, from,
                          0.5 * (from + to), report))
      break;
    local.Reset();
    local.Run(0.5 * (from + to), to);
    if (!local.Current().BetterThan(before))
    {
      mesh.nodes = kept;
      local.Reset();
      break;
    }
  }
  if (options.certifyInside)
    OpenFoldsInside(mesh, options, adjacency, constraints, local, global ? 0.95 : 0.9);
  FollowEmbeddings(mesh, original);
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    if (mesh.nodes[i] != original[i])
    {
      ++report.movedNodes;
      if (constraints.Surface(i) != SurfaceKind::None)
        ++report.movedSurfaceNodes;
    }
  report.symmetricPairs = constraints.MirrorPairs();
}

double Value(double v)
{
  return quality::IsVerdictFlag(v) ? -std::numeric_limits<double>::infinity() : v;
}

void CheckSurface(vtkPolyData* surface, const char* name)
{
  if (surface != nullptr && surface->GetNumberOfCells() == 0)
    throw std::invalid_argument(std::string(name) + " surface has no cells");
}
} // namespace

RepairReport RepairMesh(FEMesh& mesh, const RepairOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  mesh.Validate();
  if (mesh.SolidElementCount() == 0)
    throw std::invalid_argument("mesh has no solid element to repair");
  const double threshold = options.scaledJacobianThreshold;
  if (!(threshold >= -1 && threshold <= 1))
    throw std::invalid_argument("scaled Jacobian threshold " + std::to_string(threshold) + " is outside [-1, 1]");
  CheckSurface(options.skinSurface, "skin");
  CheckSurface(options.skullSurface, "skull");

  RepairReport report;
  const quality::QualityOptions sequential{1, {}};
  const quality::QualitySummary before = quality::SummarizeScaledJacobian(mesh, threshold, sequential);
  report.minScaledJacobianBefore = before.min;
  report.meanScaledJacobianBefore = before.mean;
  report.invertedBefore = before.inverted;
  report.belowThresholdBefore = before.belowThreshold;
  const quality::CertificationSummary certifiedBefore = quality::CertifyMesh(mesh);
  report.notCertifiedBefore = certifiedBefore.NotValid();
  report.certifiedMinimumBefore = certifiedBefore.minimumLower;

  quality::QualitySummary after = before;
  quality::CertificationSummary certifiedAfter = certifiedBefore;
  const bool foldedBefore = options.certifyInside && certifiedBefore.NotValid() > 0;
  if (before.belowThreshold > 0 || before.inverted > 0 || foldedBefore) // else untouched
  {
    // The lips move node by node here: close the mouth slit so that they stay together.
    const ClosedMouth closed = CloseMouth(mesh);
    Repair(mesh, options, report);
    ReopenMouth(mesh, closed);
    after = quality::SummarizeScaledJacobian(mesh, threshold, sequential);
    certifiedAfter = quality::CertifyMesh(mesh);
  }
  report.minScaledJacobianAfter = after.min;
  report.meanScaledJacobianAfter = after.mean;
  report.invertedAfter = after.inverted;
  report.belowThresholdAfter = after.belowThreshold;
  report.notCertifiedAfter = certifiedAfter.NotValid();
  report.certifiedMinimumAfter = certifiedAfter.minimumLower;
  report.success =
    after.belowThreshold == 0 && after.inverted == 0 && (!options.certifyInside || report.notCertifiedAfter == 0);

  std::vector<std::pair<double, std::size_t>> failed;
  const std::vector<double> values = quality::ComputeQuality(mesh, quality::Measure::ScaledJacobian, sequential);
  for (std::size_t e = 0; e < values.size(); ++e)
    if (!std::isnan(values[e]) && (quality::IsVerdictFlag(values[e]) || values[e] < threshold))
      failed.emplace_back(Value(values[e]), e);
  std::sort(failed.begin(), failed.end());
  for (const auto& [value, e] : failed)
  {
    report.failedElements.push_back(e);
    report.failedValues.push_back(value);
  }
  std::vector<std::pair<double, std::size_t>> folded;
  for (std::size_t k = 0; k < certifiedAfter.notValid.size(); ++k)
    if (const std::size_t e = certifiedAfter.notValid[k];
        !(std::isnan(values[e]) || quality::IsVerdictFlag(values[e]) || values[e] < threshold))
      folded.emplace_back(certifiedAfter.notValidLower[k], e);
  std::sort(folded.begin(), folded.end());
  for (const auto& [value, e] : folded)
  {
    report.foldedInside.push_back(e);
    report.foldedInsideValues.push_back(value);
  }
  if (options.progress)
    options.progress(1.0);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

} // namespace mmrep
