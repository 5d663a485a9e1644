// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Face tissue of Nazari et al. 2010 (see the header).
#include "mmrepTissue.h"

#include <stdexcept>
#include <string>

namespace mmrep::simulation
{

HyperelasticMaterial FaceTissue(double poissonRatio)
{
  if (!(poissonRatio > 0 && poissonRatio < 0.5))
    throw std::invalid_argument("Poisson ratio " + std::to_string(poissonRatio) + " must lie in (0, 0.5)");
  HyperelasticMaterial m;
  m.c10 = 2500e-6; // 2500 Pa in N/mm²
  m.c20 = 1175e-6; // 1175 Pa
  const double mu = m.ShearModulus();
  const double bulk = 2 * mu * (1 + poissonRatio) / (3 * (1 - 2 * poissonRatio));
  m.d1 = 2 / bulk;
  return m;
}

} // namespace mmrep::simulation
