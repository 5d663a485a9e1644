// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The muscle fibre law of the cable elements (Hill-type force-length), in N and mm.
#pragma once

#include <utility>
#include <vector>

namespace mmrep::simulation
{

// The fibre law. λ = L/L0 with L0 the cable's rest length, taken as the fibre's optimal length:
//   F = a · s · Fmax · f_L(λ) + k · s · Fmax · (λ − 1)   (N),
// a the activation, s = forceScale, Fmax the track's maximumForce. f_L is the active force-length
// curve of Thelen 2003 (J Biomech Eng 125:70-77), f_L = exp(−(λ − 1)²/γ), on its ascending limb
// (λ < 1); for λ >= 1 it stays at 1: the descending limb's negative slope would make the static
// equilibrium unstable. k adds a small positive slope everywhere: ccx's non-linear SPRINGA diverges
// on a branch of zero stiffness (the first Newton correction is ~100 mm whatever the load), and an
// inactive cable must still carry a little stiffness; with k = 0.05 a relaxed fibre stretched by
// 10 % pulls with 0.5 % of Fmax.
struct CableModel
{
  double forceScale = 1.0;        // multiplies every track's maximum force (1: the stored forces)
  double lengthWidth = 0.45;      // γ of f_L (Thelen 2003)
  double stabilisingSlope = 0.05; // k, per unit strain, as a fraction of Fmax
};

// The cable law of a cable of rest length `restLength` (mm) on a track of maximum force
// `maximumForce` (N) at activation `level`, as the piecewise-linear curve the deck writes:
// (elongation mm, force N) at λ = 0, 0.3, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95, 1 and 3.
std::vector<std::pair<double, double>> CableCurve(const CableModel& model, double maximumForce, double restLength,
                                                  double level);

// The force (N) of that curve at `elongation` (mm), linear between its points and beyond its ends:
// the one definition used by the deck and by the reported cable forces.
double CableForce(const CableModel& model, double maximumForce, double restLength, double level, double elongation);

} // namespace mmrep::simulation
