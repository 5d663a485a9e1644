// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// A user's request -> deck options: the first increment chosen when the request gives none.
#include "mmrepActivationRequest.h"
#include "mmrepFEMeshIO.h"

#include <gtest/gtest.h>

#include <sstream>

namespace
{
using namespace mmrep;
namespace sim = mmrep::simulation;

double FirstIncrement(const FEMesh& atlas, sim::ActivationRequest request)
{
  sim::Gesture gesture;
  const sim::DeckOptions options = sim::MakeDeckOptions(atlas, request, "atlas", gesture);
  // The value must also be what the deck hands ccx: the data line after *STATIC.
  std::ostringstream deck;
  sim::WriteCalculiXDeck(atlas, options, deck);
  const std::string text = deck.str();
  const auto at = text.find("*STATIC\n");
  EXPECT_NE(at, std::string::npos);
  EXPECT_DOUBLE_EQ(std::stod(text.substr(at + 8)), options.step.initialIncrement);
  return options.step.initialIncrement;
}

TEST(ActivationRequest, JawOpeningWithMusclesAtRestStartsFromALargerIncrement)
{
  const FEMesh atlas = ReadFEMesh(std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu");
  sim::ActivationRequest open;
  open.gesture = "open";
  EXPECT_DOUBLE_EQ(FirstIncrement(atlas, open), 0.1);

  sim::ActivationRequest round; // muscles: the activation ramp needs the small first increment
  round.gesture = "round";
  EXPECT_DOUBLE_EQ(FirstIncrement(atlas, round), 0.05);
  round.hasJawAngle = true;
  round.jawAngle = 5;
  EXPECT_DOUBLE_EQ(FirstIncrement(atlas, round), 0.05);

  sim::ActivationRequest given = open; // a value the user gives wins
  given.initialIncrement = 0.2;
  EXPECT_DOUBLE_EQ(FirstIncrement(atlas, given), 0.2);

  sim::ActivationRequest resting; // muscles named but all at level 0, jaw opened: a prescribed motion
  resting.muscles = {"Mentalis_L"};
  resting.levels = {0};
  resting.hasJawAngle = true;
  resting.jawAngle = 8;
  EXPECT_DOUBLE_EQ(FirstIncrement(atlas, resting), 0.1);
}

// Lip contact asked of a model without the mouth slit's sets: simulated without it, and said so.
TEST(ActivationRequest, AModelWithoutTheMouthSlitIsWarnedAbout)
{
  const FEMesh atlas = ReadFEMesh(std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu");
  sim::DeckOptions deck;
  deck.lipContact = true;
  EXPECT_EQ(sim::LipContactWarning(atlas, deck, "atlas.vtu"), "");
  FEMesh noSlit = atlas;
  noSlit.nodeSets.erase("upperLipContact");
  const std::string warning = sim::LipContactWarning(noSlit, deck, "old.vtu");
  EXPECT_NE(warning.find("input model 'old.vtu' has no mouth slit"), std::string::npos) << warning;
  EXPECT_NE(warning.find("without lip contact"), std::string::npos) << warning;
  deck.lipContact = false; // --noLipContact: nothing to warn about
  EXPECT_EQ(sim::LipContactWarning(noSlit, deck, "old.vtu"), "");
}

} // namespace
