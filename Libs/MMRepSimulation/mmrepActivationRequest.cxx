// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// A user's request -> deck options (see the header).
#include "mmrepActivationRequest.h"

#include "mmrepDeckSections.h"
#include "mmrepBoneSliding.h"
#include "mmrepJaw.h"
#include "mmrepLipContact.h"

#include <algorithm>
#include <stdexcept>

namespace mmrep::simulation
{
namespace
{
bool IsGestureFile(const std::string& g)
{
  return g.size() > 5 && g.compare(g.size() - 5, 5, ".json") == 0;
}

Gesture ResolveGesture(const FEMesh& mesh, const ActivationRequest& request)
{
  if (request.gesture.empty())
    return {};
  if (!request.muscles.empty())
    throw std::invalid_argument("give either --gesture or --muscles, not both");
  try
  {
    return IsGestureFile(request.gesture) ? ReadGestureFile(request.gesture) : BuiltInGesture(request.gesture, mesh);
  }
  catch (const std::exception& e)
  {
    throw std::invalid_argument(std::string(e.what()) +
                                (IsGestureFile(request.gesture) ? "" : " (or a gesture file .json)"));
  }
}

std::vector<MuscleActivation> Activations(const FEMesh& mesh, const ActivationRequest& request, const Gesture& gesture,
                                          double jawAngle)
{
  if (!request.gesture.empty())
    return gesture.activations;
  std::vector<double> levels = request.levels;
  if (request.muscles.empty() && jawAngle == 0)
    throw std::invalid_argument("no muscle given (--muscles or --gesture " + GestureNames() +
                                ") and no jaw opening; the model's muscles are: " + deck::JoinNames(MuscleNames(mesh)));
  if (levels.size() == 1)
    levels.assign(request.muscles.size(), levels.front());
  if (levels.size() != request.muscles.size())
    throw std::invalid_argument("--activations has " + std::to_string(levels.size()) + " values for " +
                                std::to_string(request.muscles.size()) + " muscles (give one, or one per muscle)");
  std::vector<MuscleActivation> out;
  for (std::size_t i = 0; i < request.muscles.size(); ++i)
    out.push_back({request.muscles[i], levels[i]});
  return out;
}
} // namespace

std::array<HyperelasticMaterial, 4> LayerMaterials(double c10Pa, double c20Pa, double poissonRatio,
                                                   const std::array<double, 3>& layerScale)
{
  if (!std::all_of(layerScale.begin(), layerScale.end(), [](double s) { return s > 0; }))
    throw std::invalid_argument("--layerScale needs three positive factors (epidermis, dermis, hypodermis)");
  HyperelasticMaterial base = FaceTissue(poissonRatio);
  const double c10 = c10Pa * 1e-6, c20 = c20Pa * 1e-6; // Pa -> N/mm²
  if (!(c10 > 0) || c20 < 0)
    throw std::invalid_argument("--c10 must be positive and --c20 not negative (Pa)");
  const double d1Factor = base.ShearModulus() / (2 * c10); // keep the Poisson ratio
  base.c10 = c10;
  base.c20 = c20;
  base.d1 *= d1Factor;
  std::array<HyperelasticMaterial, 4> materials;
  materials.fill(base);
  for (int layer = 1; layer <= 3; ++layer)
  {
    HyperelasticMaterial& m = materials[static_cast<std::size_t>(layer)];
    const double s = layerScale[static_cast<std::size_t>(layer - 1)];
    m.c10 *= s;
    m.c20 *= s;
    m.d1 /= s;
  }
  return materials;
}

double DefaultInitialIncrement(const std::vector<MuscleActivation>& activations, double jawAngle)
{
  const bool musclesAtRest =
    std::none_of(activations.begin(), activations.end(), [](const MuscleActivation& a) { return a.level > 0; });
  return jawAngle != 0 && musclesAtRest ? 0.1 : 0.05;
}

DeckOptions MakeDeckOptions(const FEMesh& mesh, const ActivationRequest& request, const std::string& modelName,
                            Gesture& gesture)
{
  gesture = ResolveGesture(mesh, request);
  const double jawAngle = request.hasJawAngle ? request.jawAngle : gesture.jawAngle;
  DeckOptions deck;
  deck.activations = Activations(mesh, request, gesture, jawAngle);
  if (jawAngle != 0 && !HasJaw(mesh))
    throw std::invalid_argument("input model '" + modelName +
                                "' has no jaw (node sets maxilla, mandible, jawAxis): a jaw "
                                "opening needs a model built from the current atlas");
  if (!request.gesture.empty() && !HasMouthSlit(mesh))
    throw std::invalid_argument(
      "input model '" + modelName +
      "' has no mouth slit (sets upperLip, lowerLip, "
      "upperLipContact, lowerLipContact): gestures need a model built from the current atlas");
  deck.materials = LayerMaterials(request.c10, request.c20, request.poissonRatio, request.layerScale);
  deck.hexahedronType = request.elementType;
  deck.cables.forceScale = request.forceScale;
  deck.step.maxIncrements = request.maxIncrements;
  deck.step.initialIncrement =
    request.initialIncrement > 0 ? request.initialIncrement : DefaultInitialIncrement(deck.activations, jawAngle);
  deck.step.minIncrement = std::min(deck.step.minIncrement, deck.step.initialIncrement);
  deck.jawAngle = jawAngle;
  deck.lipContact = request.lipContact;
  CheckActivations(mesh, deck.activations, jawAngle == 0);
  if (request.lipSupport)
    deck.slidingNodes = LipSupportNodes(mesh);
  if (request.boneSliding)
    for (const SlidingNode& s : BoneSlidingNodes(mesh))
      deck.slidingNodes.push_back(s);
  return deck;
}

std::string LipContactWarning(const FEMesh& mesh, const DeckOptions& deck, const std::string& modelName)
{
  if (!deck.lipContact || HasMouthSlit(mesh))
    return "";
  return "input model '" + modelName +
         "' has no mouth slit (sets upperLip, lowerLip, upperLipContact, lowerLipContact): the lips are simulated "
         "as one block, without lip contact";
}

} // namespace mmrep::simulation
