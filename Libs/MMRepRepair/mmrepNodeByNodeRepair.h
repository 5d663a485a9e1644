// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The node-by-node phase of the mesh repair (mmrepMeshRepair.h). Each element's quality is its
// Verdict scaled Jacobian (as vtkMeshQuality computes it), a degenerate element (Verdict's 1e30 flag)
// counting below any real value, optionally an element folded inside good corners its certified bound
// (<= 0, quality::CertifiedQuality). Elements below the target are visited worst first; their nodes move
// one at a time (worst corner first) by a derivative-free local search: geometric "ideal" positions,
// a line search along the finite-difference gradient of the worst element around the node, compass
// steps. A move is kept only when it raises the sorted (leximin) qualities of the elements around the
// node, capped just above the threshold, and never pushes an element that met the threshold below
// it. Phase 1 visits inverted elements only, phase 2 every element below the threshold; each phase
// first moves inner nodes only, then also surface nodes, then the nodes around a stuck element.
#pragma once

#include "mmrepMeshRepair.h"
#include "mmrepNodeElements.h"
#include "mmrepRepairConstraints.h"

#include <cstdint>
#include <vector>

namespace mmrep
{

class NodeByNodeRepair
{
public:
  // `certifyInside`: an element folded inside good corners counts as inverted (its certified bound).
  NodeByNodeRepair(FEMesh& mesh, const RepairOptions& options, const NodeElements& adjacency,
                   const RepairConstraints& constraints, bool certifyInside = false);

  // Runs both phases on the mesh as it is now; options.progress goes from `from` to `to`.
  void Run(double from, double to);
  // Takes the mesh's node positions as changed elsewhere (recomputes every quality).
  void Reset();

  // Inverted (regularity) or below-threshold solid elements, ascending.
  std::vector<std::size_t> BadElements(bool regularity) const;
  // Inverted, then below threshold, then the lowest quality: smaller is worse. Compares two states.
  struct State
  {
    std::size_t inverted = 0, below = 0;
    double minimum = 0;
    bool BetterThan(const State& other) const;
  };
  State Current() const;

private:
  struct Progress
  {
    std::size_t bad = 0;
    double score = 0; // sum of the bad elements' qualities, capped below at -1
  };
  double Quality(std::size_t e) const;
  Progress Measure(bool regularity) const;
  bool Bad(std::size_t e, bool regularity) const;
  bool Sweep(bool regularity, bool surfaceAllowed);
  std::vector<std::size_t> Patch(std::size_t node) const;
  void Place(std::size_t node, const Point3& p);
  void Evaluate(std::size_t node, const Point3& p, const std::vector<std::size_t>& patch, std::vector<double>& out);
  bool Better(const std::vector<double>& before, const std::vector<double>& after, double cap) const;
  bool OptimizeNode(std::size_t node, double cap);

  FEMesh& mesh_;
  const RepairOptions& options_;
  const NodeElements& adjacency_;
  const RepairConstraints& constraints_;
  bool certifyInside_ = false;
  double threshold_ = 0.3, cap_ = 0.35;
  std::vector<double> quality_;
  bool ring_ = false;
  // Logical clock of searches: when each element last changed, when each node's search last failed.
  std::uint64_t clock_ = 1;
  std::vector<std::uint64_t> changedAt_, failedAt_, ringFailedAt_;
};

} // namespace mmrep
