// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Tetrahedron quality (Verdict definitions as in VTK 9.1), see mmrepTetQuality.h.
#include "mmrepTetQuality.h"

namespace mmrep::quality
{
using namespace detail;

namespace
{
// Verdict's six sides: 0-1, 1-2, 2-0 around the base, then 0-3, 1-3, 2-3.
struct Sides
{
  Point3 s[6];
  explicit Sides(const TetNodes& p) : s{p[1] - p[0], p[2] - p[1], p[0] - p[2], p[3] - p[0], p[3] - p[1], p[3] - p[2]} {}
};

// |circumradius numerator| x (sum of face areas) / (108 V^2): the radius ratio before the sign test.
double RadiusRatioTerm(const TetNodes& p, double volume)
{
  const Sides t(p);
  const Point3* s = t.s;
  const Point3 numerator =
    Length2(s[3]) * Cross(s[2], s[0]) + Length2(s[2]) * Cross(s[3], s[0]) + Length2(s[0]) * Cross(s[3], s[2]);
  const double areaSum =
    (Length(Cross(s[2], s[0])) + Length(Cross(s[3], s[0])) + Length(Cross(s[4], s[1])) + Length(Cross(s[3], s[2]))) *
    0.5;
  return Length(numerator) * areaSum / (108 * volume * volume);
}
} // namespace

double TetJacobian(const TetNodes& p)
{
  const Point3 side0 = p[1] - p[0], side2 = p[0] - p[2], side3 = p[3] - p[0];
  return Dot(side3, Cross(side2, side0));
}

double TetVolume(const TetNodes& p)
{
  return TetJacobian(p) / 6.0;
}

double TetScaledJacobian(const TetNodes& p)
{
  const Sides t(p);
  const Point3* s = t.s;
  const double jacobi = Dot(s[3], Cross(s[2], s[0]));
  // Product of the squared lengths of the three edges at each node.
  const double products[4] = {
    Length2(s[0]) * Length2(s[2]) * Length2(s[3]), Length2(s[0]) * Length2(s[1]) * Length2(s[4]),
    Length2(s[1]) * Length2(s[2]) * Length2(s[5]), Length2(s[3]) * Length2(s[4]) * Length2(s[5])};
  int which = 0;
  for (int i = 1; i < 4; ++i)
    if (products[i] > products[which])
      which = i;
  double lengthProduct = std::sqrt(products[which]);
  if (lengthProduct < std::abs(jacobi))
    lengthProduct = std::abs(jacobi);
  if (lengthProduct < kVerdictMin)
    return kVerdictMax;
  static const double sqrt2 = std::sqrt(2.0);
  return sqrt2 * jacobi / lengthProduct;
}

double TetShape(const TetNodes& p)
{
  static const double twoThirds = 2.0 / 3.0;
  static const double sqrt2 = std::sqrt(2.0);
  const Point3 e0 = p[1] - p[0], e2 = p[0] - p[2], e3 = p[3] - p[0];
  const double jacobian = Dot(e3, Cross(e2, e0));
  if (jacobian < kVerdictMin)
    return 0.0;
  const double num = 3 * std::pow(sqrt2 * jacobian, twoThirds);
  const Point3 minusE2 = -e2;
  const double den =
    1.5 * (Dot(e0, e0) + Dot(e2, e2) + Dot(e3, e3)) - (Dot(e0, minusE2) + Dot(minusE2, e3) + Dot(e3, e0));
  if (den < kVerdictMin)
    return 0.0;
  return std::max(num / den, 0.);
}

double TetEdgeRatio(const TetNodes& p)
{
  const Sides t(p);
  // Verdict's pairs: (0-1, 1-2), (2-0, 0-3), (1-3, 2-3).
  double m[3], M[3];
  for (int k = 0; k < 3; ++k)
  {
    const double a = Length2(t.s[2 * k]), b = Length2(t.s[2 * k + 1]);
    m[k] = a < b ? a : b;
    M[k] = a < b ? b : a;
  }
  double m2 = m[0] < m[1] ? m[0] : m[1];
  m2 = m2 < m[2] ? m2 : m[2];
  if (m2 < kVerdictMin)
    return kVerdictMax;
  double M2 = M[0] > M[1] ? M[0] : M[1];
  M2 = M2 > M[2] ? M2 : M[2];
  return Clamp(std::sqrt(M2 / m2));
}

double TetAspectRatio(const TetNodes& p)
{
  static const double normalCoeff = std::sqrt(6.) / 12.;
  const Point3 ab = p[1] - p[0], ac = p[2] - p[0], ad = p[3] - p[0];
  const double det = Dot(ab, Cross(ac, ad));
  if (std::abs(det) < kVerdictMin) // VTK 9.1: inverted tets get a value too
    return kVerdictMax;
  const Point3 bc = p[2] - p[1], bd = p[3] - p[1], cd = p[3] - p[2];
  const double ab2 = Length2(ab), bc2 = Length2(bc), ac2 = Length2(ac);
  const double ad2 = Length2(ad), bd2 = Length2(bd), cd2 = Length2(cd);
  const double A = ab2 > bc2 ? ab2 : bc2;
  const double B = ac2 > ad2 ? ac2 : ad2;
  const double C = bd2 > cd2 ? bd2 : cd2;
  const double D = A > B ? A : B;
  const double hm = D > C ? std::sqrt(D) : std::sqrt(C);
  const double faces = Length(Cross(ab, bc)) + Length(Cross(ab, ad)) + Length(Cross(ac, ad)) + Length(Cross(bc, cd));
  return Clamp(normalCoeff * hm * faces / std::abs(det));
}

double TetRadiusRatio(const TetNodes& p)
{
  const double volume = TetVolume(p);
  if (std::abs(volume) < kVerdictMin)
    return kVerdictMax;
  return std::min(RadiusRatioTerm(p, volume), kVerdictMax);
}

double TetAspectBeta(const TetNodes& p)
{
  // VTK 9.1 flags near-zero volumes of either sign (so it equals the radius ratio).
  const double volume = TetVolume(p);
  if (std::abs(volume) < kVerdictMin)
    return kVerdictMax;
  return std::min(RadiusRatioTerm(p, volume), kVerdictMax);
}

double TetAspectGamma(const TetNodes& p)
{
  const Sides t(p);
  const double volume = std::abs(TetVolume(p));
  if (volume < kVerdictMin)
    return kVerdictMax;
  const double sum =
    Length2(t.s[0]) + Length2(t.s[1]) + Length2(t.s[2]) + Length2(t.s[3]) + Length2(t.s[4]) + Length2(t.s[5]);
  const double srms = std::sqrt(sum / 6.0);
  return std::pow(srms, 3) / (8.48528137423857 * volume);
}

double TetAspectFrobenius(const TetNodes& p)
{
  static const double normalExp = 1. / 3.;
  const Point3 u = p[1] - p[0], v = p[2] - p[0], w = p[3] - p[0];
  double denominator = Dot(u, Cross(v, w));
  denominator *= denominator;
  denominator *= 2.;
  denominator = 3. * std::pow(denominator, normalExp);
  if (denominator < kVerdictMin)
    return kVerdictMax;
  double numerator = Dot(u, u);
  numerator += Dot(v, v);
  numerator += Dot(w, w);
  numerator *= 1.5;
  numerator -= Dot(v, u);
  numerator -= Dot(w, u);
  numerator -= Dot(w, v);
  return Clamp(numerator / denominator);
}

double TetMinAngle(const TetNodes& p)
{
  static const double toDegrees = 180. * .3183098861837906715377675267450287;
  const Point3 ab = p[1] - p[0], ad = p[3] - p[0], bc = p[2] - p[1], cd = p[3] - p[2];
  const Point3 abc = Cross(ab, bc), abd = Cross(ab, ad), acd = Cross(ad, cd), bcd = Cross(bc, cd);
  const double nabc = Length(abc), nabd = Length(abd), nacd = Length(acd), nbcd = Length(bcd);
  double alpha = std::acos(Dot(abc, abd) / (nabc * nabd));
  const double others[5] = {std::acos(Dot(abc, acd) / (nabc * nacd)), std::acos(Dot(abc, bcd) / (nabc * nbcd)),
                            std::acos(Dot(abd, acd) / (nabd * nacd)), std::acos(Dot(abd, bcd) / (nabd * nbcd)),
                            std::acos(Dot(acd, bcd) / (nacd * nbcd))};
  for (double angle : others)
    alpha = alpha < angle ? alpha : angle;
  alpha *= toDegrees;
  if (alpha < kVerdictMin)
    return kVerdictMax;
  return Clamp(alpha);
}

double TetCollapseRatio(const TetNodes& p)
{
  const Point3 e01 = p[1] - p[0], e02 = p[2] - p[0], e03 = p[3] - p[0];
  const Point3 e12 = p[2] - p[1], e13 = p[3] - p[1], e23 = p[3] - p[2];
  const double l[6] = {Length(e01), Length(e02), Length(e03), Length(e12), Length(e13), Length(e23)};
  // Longest edge of each face (Verdict's expressions, including its choice of edges).
  double l012 = l[4] > l[0] ? l[4] : l[0];
  l012 = l[1] > l012 ? l[1] : l012;
  double l031 = l[0] > l[2] ? l[0] : l[2];
  l031 = l[3] > l031 ? l[3] : l031;
  double l023 = l[2] > l[1] ? l[2] : l[1];
  l023 = l[5] > l023 ? l[5] : l023;
  double l132 = l[4] > l[3] ? l[4] : l[3];
  l132 = l[5] > l132 ? l[5] : l132;

  auto ratio = [](const Point3& apex, const Point3& n, double longest) { return Dot(apex, n) / Length(n) / longest; };
  double crMin = ratio(e03, Cross(e01, e02), l012);
  double cr = ratio(e02, Cross(e03, e01), l031);
  if (cr < crMin)
    crMin = cr;
  cr = ratio(e01, Cross(e02, e03), l023);
  if (cr < crMin)
    crMin = cr;
  cr = ratio(e01, Cross(e12, e13), l132);
  if (cr < crMin)
    crMin = cr;
  if (std::abs(crMin) < kVerdictMin) // VTK 9.1: negative for inverted tets
    return kVerdictMax;
  return Clamp(crMin);
}

double TetCondition(const TetNodes& p)
{
  static const double rt3 = std::sqrt(3.0), rt6 = std::sqrt(6.0);
  const Point3 side0 = p[1] - p[0], side2 = p[0] - p[2], side3 = p[3] - p[0];
  const Point3 c1 = side0;
  const Point3 c2 = (-2 * side2 - side0) / rt3;
  const Point3 c3 = (3 * side3 + side2 - side0) / rt6;
  const double term1 = Dot(c1, c1) + Dot(c2, c2) + Dot(c3, c3);
  const Point3 c12 = Cross(c1, c2), c23 = Cross(c2, c3), c13 = Cross(c1, c3);
  const double term2 = Dot(c12, c12) + Dot(c23, c23) + Dot(c13, c13);
  const double det = Dot(c1, Cross(c2, c3));
  if (std::abs(det) <= kVerdictMin) // VTK 9.1: negative for inverted tets
    return kVerdictMax;
  return std::sqrt(term1 * term2) / (3.0 * det);
}

} // namespace mmrep::quality
