// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The parts of the CalculiX deck, written in order by WriteCalculiXDeck (internal to MMRepSimulation).
#pragma once

#include "mmrepCalculiXDeck.h"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace mmrep::simulation::deck
{

// CalculiX reads numbers from fields of at most 20 characters: 12 significant digits always fit.
std::string FormatDouble(double v);
// Abaqus/CalculiX: at most 16 ids per data line.
void WriteIds(std::ostream& out, const std::vector<std::int32_t>& ids);
std::string JoinNames(const std::vector<std::string>& names);

// Which nodes the deck holds and how the bone moves, checked against the options.
struct DeckPlan
{
  std::vector<char> used;                      // nodes written (solid nodes and the active tracks' nodes)
  std::vector<char> solidNode;                 // nodes of a solid element
  std::vector<std::int32_t> fixed;             // sorted, unique
  std::vector<std::int32_t> mandible;          // solid nodes moved by the jaw (empty at angle 0)
  std::vector<const MuscleActivation*> active; // positive levels, in activation order
};

// Validates the options and plans the nodes (throws std::invalid_argument, one line).
DeckPlan PlanDeck(const FEMesh& mesh, const DeckOptions& options, DeckSummary& summary);

void WriteNodes(const FEMesh& mesh, const DeckPlan& plan, std::ostream& out);
// Solids grouped by (layer, type); one material and section per layer.
void WriteSolids(const FEMesh& mesh, const DeckOptions& options, DeckSummary& summary, std::ostream& out);
// One SPRINGA element set per cable of an active track (each has its own rest length and curve).
void WriteCables(const FEMesh& mesh, const DeckOptions& options, const DeckPlan& plan, DeckSummary& summary,
                 std::ostream& out);
// The active tracks' nodes follow their host solids (*EQUATION with the shape functions).
void WriteEmbedding(const FEMesh& mesh, const DeckPlan& plan, DeckSummary& summary, std::ostream& out);
// n·u = 0 for the sliding nodes and a half model's symmetry-plane nodes; then the fixed nodes.
void WriteConstraints(const FEMesh& mesh, const DeckOptions& options, const DeckPlan& plan, DeckSummary& summary,
                      std::ostream& out);
// One GAPUNI element per pair of facing lip nodes (no interpenetration).
void WriteLipGaps(const FEMesh& mesh, const DeckOptions& options, const DeckPlan& plan, DeckSummary& summary,
                  std::ostream& out);
// The static step: the load parameter ramp, the jaw rotation, the nodal loads, the output request.
void WriteStep(const FEMesh& mesh, const DeckOptions& options, const DeckPlan& plan, DeckSummary& summary,
               std::ostream& out);

} // namespace mmrep::simulation::deck
