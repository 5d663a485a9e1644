// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Muscle activation of an FE face model with CalculiX: deck, solve, displacements of every node
// and of the landmarks, cable forces.
#pragma once

#include "mmrepCalculiXDeck.h"
#include "mmrepCalculiXRunner.h"
#include "mmrepFEMesh.h"

#include <string>
#include <vector>

namespace mmrep::simulation
{

struct ActivationOptions
{
  DeckOptions deck;
  RunOptions run;
};

struct LandmarkMotion
{
  std::string name;
  Point3 rest = Point3::Zero();
  Point3 displacement = Point3::Zero();
  int element = -1;    // solid element used for the interpolation, -1: nearest node
  double distance = 0; // distance from the landmark to that element (0 inside), or to the node
};

struct MuscleForces
{
  std::string muscle;
  double level = 0;
  double meanForce = 0, maxForce = 0; // N, over the cables, deformed state
  double restLength = 0, length = 0;  // mm, whole track
};

struct ActivationResult
{
  DeckSummary deck;
  CalculiXRun run;
  std::vector<Point3> displacements; // one per mesh node (mm)
  std::vector<LandmarkMotion> landmarks;
  std::vector<MuscleForces> muscles; // active muscles
};

// Throws std::invalid_argument for a bad activation (see CheckActivations) and std::runtime_error
// when ccx is missing, fails, or does not converge (the message says which and why).
ActivationResult SimulateMuscleActivation(const FEMesh& mesh, const ActivationOptions& options);

// Displacement at `point`, interpolated with the shape functions of the solid element containing it
// (or the closest solid element when the point lies outside the mesh by at most `tolerance` mm);
// farther away, the displacement of the nearest node of a solid element.
LandmarkMotion InterpolateDisplacement(const FEMesh& mesh, const std::vector<Point3>& displacements,
                                       const Point3& point, double tolerance = 1.0);

// The mesh with every node moved by its displacement (sets, muscles, embedding kept; landmarks moved
// by their interpolated displacement).
FEMesh DeformedMesh(const FEMesh& mesh, const ActivationResult& result);

} // namespace mmrep::simulation
