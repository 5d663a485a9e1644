// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Hyperelastic face tissue (polynomial strain energy), in N and mm.
#pragma once

namespace mmrep::simulation
{

// Polynomial hyperelastic coefficients (N/mm²) and compressibilities D1, D2 (mm²/N).
// Strain energy: W = Σ Cij (I1−3)^i (I2−3)^j + Σ (J−1)^(2k)/Dk.
struct HyperelasticMaterial
{
  double c10 = 0, c01 = 0, c20 = 0, c11 = 0, c02 = 0, d1 = 0, d2 = 0;
  // Initial shear modulus 2(C10 + C01) and bulk modulus 2/D1 (N/mm²).
  double ShearModulus() const { return 2 * (c10 + c01); }
  double BulkModulus() const { return 2 / d1; }
};

// Nazari et al. 2010 face tissue: C10 = 2500 Pa, C20 = 1175 Pa, in N/mm²; D1 from the Poisson
// ratio of the initial (small-strain) response: K = 2μ(1+ν)/(3(1−2ν)), D1 = 2/K.
HyperelasticMaterial FaceTissue(double poissonRatio = 0.49);

} // namespace mmrep::simulation
