// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The global untangling stage of the mesh repair (mmrepMeshRepair.h): the nodes around the inverted
// elements move together, minimising the foldover-free energy (mmrepFoldoverFreeEnergy.h) with
// L-BFGS (LBFGSpp) while its regularisation eps decreases as Garanzha et al. (2021) prescribe. Moving
// all of them at once undoes tangles that node-by-node moves cannot (two nodes crossed through each
// other: moving either one alone only makes its elements worse). Each node keeps the repair's
// constraints: surface nodes slide on their surface (in its tangent plane during a minimisation, then
// projected back onto it), nodes on the symmetry plane stay on it, mirror partners stay mirrored.
#pragma once

#include "mmrepRepairConstraints.h"

#include <functional>
#include <vector>

namespace mmrep
{

struct UntanglingOptions
{
  int maximumSteps = 100;     // decreases of eps (one L-BFGS minimisation each)
  int iterationsPerStep = 20; // L-BFGS iterations per minimisation
  int patience = 10;          // steps without fewer inverted elements before giving up
  double theta = 0.5;         // weight of the volume term against the shape term
  // eps of the first minimisation (at least 0.2 |smallest det J|). Garanzha et al. start from 1;
  // 0.1 untangles the tangles of a whole mesh in far fewer steps, 1 gets out of the folds that a
  // start from 0.1 leaves (elements pressed flat between two surfaces or across the plane).
  double initialEps = 0.1;
  // When nothing around the seeds is inverted: lower the energy all the same (valid but flat
  // elements take shapes closer to their ideal box), keeping every frame positive.
  bool relaxValid = false;
  // After each minimisation: the fraction of the inverted elements undone so far (never decreasing).
  // It may throw to abort; the mesh is then unchanged.
  std::function<void(double)> progress;
};

struct UntanglingResult
{
  int steps = 0;                  // minimisations run
  std::size_t freeNodes = 0;      // nodes allowed to move
  std::size_t invertedBefore = 0; // elements with a frame det J <= 0, in the region
  std::size_t invertedAfter = 0;
  bool kept = false; // false: the result was not better (or a relaxation not lower), the mesh is unchanged
};

// Untangles the mesh around `seeds` (elements to make valid) in place; moves only nodes of the seeds
// and of the elements sharing a node with them, never a fixed node. Leaves the mesh unchanged when
// it cannot lower the number of inverted elements (with relaxValid and nothing inverted: the energy).
UntanglingResult UntangleFoldovers(FEMesh& mesh, const NodeElements& adjacency, const RepairConstraints& constraints,
                                   const std::vector<std::size_t>& seeds, const UntanglingOptions& options = {});

} // namespace mmrep
