// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// CalculiX deck writer for muscle activation (see the header for the model): checks the options,
// plans the nodes, then writes the sections of mmrepDeckSections.h in order.
#include "mmrepCalculiXDeck.h"

#include "mmrepDeckSections.h"
#include "mmrepHalfModel.h"
#include "mmrepJaw.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace mmrep::simulation
{
using deck::FormatDouble;

std::vector<std::string> MuscleNames(const FEMesh& mesh)
{
  std::vector<std::string> names;
  for (const auto& [name, track] : mesh.muscles)
    names.push_back(name);
  return names;
}

void CheckActivations(const FEMesh& mesh, const std::vector<MuscleActivation>& activations, bool requireActive)
{
  if (activations.empty() && !requireActive)
    return;
  if (mesh.muscles.empty())
    throw std::invalid_argument("the model has no muscles (no muscle tracks stored in the mesh)");
  if (activations.empty())
    throw std::invalid_argument("no muscle to activate was given");
  std::set<std::string> seen;
  bool anyActive = false;
  for (const auto& a : activations)
  {
    if (mesh.muscles.count(a.muscle) == 0 && IsHalfModel(mesh) && a.muscle.size() > 2 &&
        a.muscle.compare(a.muscle.size() - 2, 2, "_R") == 0)
      throw std::invalid_argument("muscle '" + a.muscle +
                                  "' is on the right side, which this half model does not hold "
                                  "(it is the left half, with node set '" +
                                  kSymmetryBoundarySet + "'): activate '" + a.muscle.substr(0, a.muscle.size() - 2) +
                                  "_L', its mirror image");
    if (mesh.muscles.count(a.muscle) == 0)
      throw std::invalid_argument("unknown muscle '" + a.muscle +
                                  "'; the model's muscles are: " + deck::JoinNames(MuscleNames(mesh)));
    if (!seen.insert(a.muscle).second)
      throw std::invalid_argument("muscle '" + a.muscle + "' is given twice");
    if (!(a.level >= 0 && a.level <= 1))
      throw std::invalid_argument("activation level " + std::to_string(a.level) + " of muscle '" + a.muscle +
                                  "' must lie in [0, 1]");
    if (mesh.muscles.at(a.muscle).cables.empty())
      throw std::invalid_argument("muscle '" + a.muscle + "' has no cable elements");
    anyActive = anyActive || a.level > 0;
  }
  if (!anyActive && requireActive)
    throw std::invalid_argument("every activation level is 0: nothing to simulate");
}

namespace deck
{
namespace
{
void CheckSolverOptions(const FEMesh& mesh, const DeckOptions& options)
{
  if (!options.activations.empty() || options.loads.empty())
    CheckActivations(mesh, options.activations, options.jawAngle == 0 && options.loads.empty());
  const std::string& hexType = options.hexahedronType;
  if (hexType != "C3D8" && hexType != "C3D8I" && hexType != "C3D8R")
    throw std::invalid_argument("hexahedron type '" + hexType + "' must be C3D8, C3D8I or C3D8R");
  const StepControl& step = options.step;
  if (!(step.initialIncrement > 0 && step.minIncrement > 0 && step.minIncrement <= step.initialIncrement &&
        step.initialIncrement <= step.maxIncrement && step.maxIncrement <= 1 && step.maxIncrements > 0))
    throw std::invalid_argument(
      "step control needs 0 < minimum <= initial <= maximum increment <= 1 and at least one increment");
  const CableModel& cm = options.cables;
  if (!(cm.forceScale > 0 && cm.lengthWidth > 0 && cm.stabilisingSlope > 0) || !std::isfinite(cm.forceScale))
    throw std::invalid_argument("the cable force scale, force-length width and stabilising slope must be positive");
}

// Fixed nodes: those of the set that carry a solid (a node without a solid has no stiffness). A
// model with a jaw: the maxilla is fixed and the mandible moves with the jaw (a half model keeps
// maxilla, mandible and the left condyle: its axis is the plane normal, mmrepJaw.h).
void PlanBone(const FEMesh& mesh, const DeckOptions& options, DeckPlan& plan)
{
  const bool jaw = options.fixedNodeSet == "skull" && mesh.nodeSets.count(kMaxillaSet) &&
                   mesh.nodeSets.count(kMandibleSet) && !mesh.nodeSets.at(kMaxillaSet).empty();
  if (!(options.jawAngle >= kMinJawAngle && options.jawAngle <= kMaxJawAngle))
    throw std::invalid_argument("jaw angle " + FormatDouble(options.jawAngle) + " deg is outside [" +
                                FormatDouble(kMinJawAngle) + ", " + FormatDouble(kMaxJawAngle) + "] deg");
  if (options.jawAngle != 0 && !(jaw && HasJaw(mesh)))
    throw std::invalid_argument(
      "a jaw opening needs a model with a jaw (node sets 'maxilla', 'mandible' and 'jawAxis'); "
      "this one has none: rebuild it from the current atlas");
  if (!(options.contactStiffness > 0))
    throw std::invalid_argument("the lip contact stiffness must be positive");
  const auto fixedIt = mesh.nodeSets.find(jaw ? kMaxillaSet : options.fixedNodeSet);
  if (fixedIt == mesh.nodeSets.end())
    throw std::invalid_argument("the model has no node set '" + options.fixedNodeSet + "' to fix");
  std::vector<char> slides(mesh.nodes.size(), 0); // bone nodes that slide instead
  for (const auto& s : options.slidingNodes)
    if (s.onBone && s.node >= 0 && static_cast<std::size_t>(s.node) < mesh.nodes.size())
      slides[static_cast<std::size_t>(s.node)] = 1;
  for (auto n : fixedIt->second)
    if (plan.used[static_cast<std::size_t>(n)] && !slides[static_cast<std::size_t>(n)])
      plan.fixed.push_back(n);
  if (jaw)
    for (auto n : mesh.nodeSets.at(kMandibleSet))
      if (plan.used[static_cast<std::size_t>(n)])
        (options.jawAngle == 0 ? plan.fixed : plan.mandible).push_back(n);
  std::sort(plan.fixed.begin(), plan.fixed.end());
  plan.fixed.erase(std::unique(plan.fixed.begin(), plan.fixed.end()), plan.fixed.end());
  if (plan.fixed.empty())
    throw std::invalid_argument("node set '" + options.fixedNodeSet +
                                "' holds no node of a solid element: nothing is fixed");
}

// The active tracks' nodes join the deck; each must be embedded in a solid and be no solid's node.
void PlanTracks(const FEMesh& mesh, DeckPlan& plan)
{
  for (const auto* a : plan.active)
  {
    const MuscleTrack& track = mesh.muscles.at(a->muscle);
    if (track.embedding.size() != track.nodes.size())
      throw std::invalid_argument("muscle '" + a->muscle + "' has no embedding for every track node");
    for (std::size_t i = 0; i < track.nodes.size(); ++i)
    {
      const auto& emb = track.embedding[i];
      if (emb.element < 0 || static_cast<std::size_t>(emb.element) >= mesh.elements.size() ||
          mesh.elements[static_cast<std::size_t>(emb.element)].type == ElementType::Cable)
        throw std::invalid_argument("muscle '" + a->muscle + "': track node " + std::to_string(i) +
                                    " is not embedded in a solid element");
      if (plan.solidNode[static_cast<std::size_t>(track.nodes[i])])
        throw std::invalid_argument("muscle '" + a->muscle + "': track node " + std::to_string(i) +
                                    " is also a node of a solid element (muscle nodes must be separate)");
      plan.used[static_cast<std::size_t>(track.nodes[i])] = 1;
    }
  }
}
} // namespace

DeckPlan PlanDeck(const FEMesh& mesh, const DeckOptions& options, DeckSummary& summary)
{
  CheckSolverOptions(mesh, options);
  DeckPlan plan;
  plan.used.assign(mesh.nodes.size(), 0);
  for (const auto& e : mesh.elements)
    if (e.type != ElementType::Cable)
      for (int k = 0; k < NodeCount(e.type); ++k)
        plan.used[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])] = 1;
  PlanBone(mesh, options, plan);
  summary.fixedNodes = plan.fixed.size();
  for (const auto& a : options.activations)
    if (a.level > 0)
    {
      plan.active.push_back(&a);
      summary.activeMuscles.push_back(a.muscle);
    }
  plan.solidNode = plan.used;
  for (const auto& load : options.loads)
    if (load.node < 0 || static_cast<std::size_t>(load.node) >= mesh.nodes.size() ||
        !plan.solidNode[static_cast<std::size_t>(load.node)] || !load.force.allFinite())
      throw std::invalid_argument("load on node " + std::to_string(load.node) +
                                  ": not a node of a solid element, or a non-finite force");
  PlanTracks(mesh, plan);
  return plan;
}
} // namespace deck

DeckSummary WriteCalculiXDeck(const FEMesh& mesh, const DeckOptions& options, std::ostream& out)
{
  DeckSummary summary;
  const deck::DeckPlan plan = deck::PlanDeck(mesh, options, summary);
  deck::WriteNodes(mesh, plan, out);
  deck::WriteSolids(mesh, options, summary, out);
  deck::WriteCables(mesh, options, plan, summary, out);
  deck::WriteEmbedding(mesh, plan, summary, out);
  deck::WriteConstraints(mesh, options, plan, summary, out);
  deck::WriteLipGaps(mesh, options, plan, summary, out);
  deck::WriteStep(mesh, options, plan, summary, out);
  return summary;
}

} // namespace mmrep::simulation
