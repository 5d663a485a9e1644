// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The Hill-type cable law (see the header).
#include "mmrepCableLaw.h"

#include <cmath>

namespace mmrep::simulation
{

std::vector<std::pair<double, double>> CableCurve(const CableModel& model, double maximumForce, double restLength,
                                                  double level)
{
  // Stretches λ where the curve is sampled: dense on the ascending limb, where the cables work.
  static const double stretches[] = {0, 0.3, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95, 1, 3};
  const double fmax = model.forceScale * maximumForce;
  std::vector<std::pair<double, double>> curve;
  for (double lambda : stretches)
  {
    const double active = lambda < 1 ? std::exp(-(lambda - 1) * (lambda - 1) / model.lengthWidth) : 1.0;
    curve.emplace_back((lambda - 1) * restLength, fmax * (level * active + model.stabilisingSlope * (lambda - 1)));
  }
  return curve;
}

double CableForce(const CableModel& model, double maximumForce, double restLength, double level, double elongation)
{
  const auto curve = CableCurve(model, maximumForce, restLength, level);
  std::size_t k = 1;
  while (k + 1 < curve.size() && elongation > curve[k].first)
    ++k;
  const auto& [e0, f0] = curve[k - 1];
  const auto& [e1, f1] = curve[k];
  return f0 + (f1 - f0) * (elongation - e0) / (e1 - e0);
}

} // namespace mmrep::simulation
