// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Hexahedron quality (Verdict definitions as in VTK 9.1), see mmrepHexQuality.h.
#include "mmrepHexQuality.h"

namespace mmrep::quality
{
using namespace detail;

namespace
{
// Corner i: node i and its neighbours along xi, eta, zeta; the frame is right-handed in a valid hex.
constexpr int kCorner[8][4] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                               {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};

struct Frame
{
  Point3 a, b, c;
};

Frame CornerFrame(const HexNodes& p, int i)
{
  const int* k = kCorner[i];
  return {p[k[1]] - p[k[0]], p[k[2]] - p[k[0]], p[k[3]] - p[k[0]]};
}

// Principal axes at the centre (4x the parametric derivatives for xi in [-1, 1]); Verdict's "efg".
Point3 Axis1(const HexNodes& p)
{
  return p[1] + p[2] + p[5] + p[6] - p[0] - p[3] - p[4] - p[7];
}
Point3 Axis2(const HexNodes& p)
{
  return p[2] + p[3] + p[6] + p[7] - p[0] - p[1] - p[4] - p[5];
}
Point3 Axis3(const HexNodes& p)
{
  return p[4] + p[5] + p[6] + p[7] - p[0] - p[1] - p[2] - p[3];
}
// Cross-derivatives (bilinear terms) used by the taper.
Point3 Axis12(const HexNodes& p)
{
  return p[0] + p[2] + p[4] + p[6] - p[1] - p[3] - p[5] - p[7];
}
Point3 Axis13(const HexNodes& p)
{
  return p[0] + p[3] + p[5] + p[6] - p[1] - p[2] - p[4] - p[7];
}
Point3 Axis23(const HexNodes& p)
{
  return p[0] + p[1] + p[6] + p[7] - p[2] - p[3] - p[4] - p[5];
}

// Frobenius condition number of a corner frame; kVerdictMax when not positively oriented.
double Condition(const Frame& f)
{
  const double det = Det(f.a, f.b, f.c);
  if (det <= kVerdictMin)
    return kVerdictMax;
  const double term1 = Dot(f.a, f.a) + Dot(f.b, f.b) + Dot(f.c, f.c);
  const Point3 ab = Cross(f.a, f.b), bc = Cross(f.b, f.c), ca = Cross(f.c, f.a);
  const double term2 = Dot(ab, ab) + Dot(bc, bc) + Dot(ca, ca);
  return std::sqrt(term1 * term2) / det;
}

double Oddy(const Point3& xxi, const Point3& xet, const Point3& xze)
{
  static const double third = 1.0 / 3.0;
  const double g11 = Dot(xxi, xxi), g12 = Dot(xxi, xet), g13 = Dot(xxi, xze);
  const double g22 = Dot(xet, xet), g23 = Dot(xet, xze), g33 = Dot(xze, xze);
  const double rtg = Det(xxi, xet, xze);
  if (!(rtg > kVerdictMin))
    return kVerdictMax;
  const double normG2 = g11 * g11 + 2.0 * g12 * g12 + 2.0 * g13 * g13 + g22 * g22 + 2.0 * g23 * g23 + g33 * g33;
  const double normJ2 = g11 + g22 + g33;
  return (normG2 - third * normJ2 * normJ2) / std::pow(rtg, 4. * third);
}

// The 12 edges in Verdict's order: bottom ring, top ring, verticals.
constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                               {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
constexpr int kDiagonals[4][2] = {{0, 6}, {2, 4}, {1, 7}, {3, 5}};
} // namespace

std::array<double, 8> HexCornerJacobians(const HexNodes& p)
{
  std::array<double, 8> det{};
  for (int i = 0; i < 8; ++i)
  {
    const Frame f = CornerFrame(p, i);
    det[i] = Det(f.a, f.b, f.c);
  }
  return det;
}

double HexCenterJacobian(const HexNodes& p)
{
  return Det(Axis1(p), Axis2(p), Axis3(p)) / 64.0;
}

double HexJacobian(const HexNodes& p)
{
  double jacobian = kVerdictMax;
  const double center = HexCenterJacobian(p);
  if (center < jacobian)
    jacobian = center;
  for (double det : HexCornerJacobians(p))
    if (det < jacobian)
      jacobian = det;
  return Clamp(jacobian);
}

double HexScaledJacobian(const HexNodes& p)
{
  double minScaled = kVerdictMax;
  // Centre first, then corners; any vanishing edge vector flags the cell.
  auto visit = [&](const Point3& a, const Point3& b, const Point3& c) {
    const double det = Det(a, b, c);
    const double l1 = Length2(a), l2 = Length2(b), l3 = Length2(c);
    if (l1 <= kVerdictMin || l2 <= kVerdictMin || l3 <= kVerdictMin)
      return false;
    const double scaled = det / std::sqrt(l1 * l2 * l3);
    if (scaled < minScaled)
      minScaled = scaled;
    return true;
  };
  if (!visit(Axis1(p), Axis2(p), Axis3(p)))
    return kVerdictMax;
  for (int i = 0; i < 8; ++i)
  {
    const Frame f = CornerFrame(p, i);
    if (!visit(f.a, f.b, f.c))
      return kVerdictMax;
  }
  return Clamp(minScaled);
}

double HexShape(const HexNodes& p)
{
  static const double twoThirds = 2.0 / 3.0;
  double minShape = 1.0;
  for (int i = 0; i < 8; ++i)
  {
    const Frame f = CornerFrame(p, i);
    const double det = Det(f.a, f.b, f.c);
    if (!(det > kVerdictMin))
      return 0;
    const double shape = 3 * std::pow(det, twoThirds) / (Dot(f.a, f.a) + Dot(f.b, f.b) + Dot(f.c, f.c));
    if (shape < minShape)
      minShape = shape;
  }
  if (minShape <= kVerdictMin)
    minShape = 0;
  return Clamp(minShape);
}

double HexShear(const HexNodes& p)
{
  double minShear = 1.0;
  for (int i = 0; i < 8; ++i)
  {
    const Frame f = CornerFrame(p, i);
    const double l1 = Length2(f.a), l2 = Length2(f.b), l3 = Length2(f.c);
    if (l1 <= kVerdictMin || l2 <= kVerdictMin || l3 <= kVerdictMin)
      return 0;
    const double lengths = std::sqrt(l1 * l2 * l3);
    const double det = Det(f.a, f.b, f.c);
    if (det < kVerdictMin)
      return 0;
    minShear = VMin(det / lengths, minShear);
  }
  if (minShear <= kVerdictMin)
    minShear = 0;
  return Clamp(minShear);
}

double HexSkew(const HexNodes& p)
{
  Point3 axes[3] = {Axis1(p), Axis2(p), Axis3(p)};
  for (Point3& a : axes)
  {
    const double length = Length(a);
    if (length != 0)
      a = Point3(a.x() / length, a.y() / length, a.z() / length);
    if (length <= kVerdictMin)
      return kVerdictMax;
  }
  const double s12 = std::abs(Dot(axes[0], axes[1]));
  const double s13 = std::abs(Dot(axes[0], axes[2]));
  const double s23 = std::abs(Dot(axes[1], axes[2]));
  return Clamp(VMax(s12, VMax(s13, s23)));
}

double HexTaper(const HexNodes& p)
{
  const double l1 = Length(Axis1(p)), l2 = Length(Axis2(p)), l3 = Length(Axis3(p));
  const double t1 = std::abs(SafeRatio(Length(Axis12(p)), VMin(l1, l2)));
  const double t2 = std::abs(SafeRatio(Length(Axis13(p)), VMin(l1, l3)));
  const double t3 = std::abs(SafeRatio(Length(Axis23(p)), VMin(l2, l3)));
  return Clamp(VMax(t1, VMax(t2, t3)));
}

namespace
{
double EdgeLength(const HexNodes& p, int a, int b)
{
  double t[3];
  for (int i = 0; i < 3; ++i)
  {
    t[i] = p[b][i] - p[a][i];
    t[i] = t[i] * t[i];
  }
  return std::sqrt(t[0] + t[1] + t[2]);
}
} // namespace

double HexStretch(const HexNodes& p)
{
  static const double sqrt3 = std::sqrt(3.0);
  double minEdge = EdgeLength(p, kEdges[0][0], kEdges[0][1]);
  for (int e = 1; e < 12; ++e)
    minEdge = VMin(minEdge, EdgeLength(p, kEdges[e][0], kEdges[e][1]));
  double maxDiagonal = EdgeLength(p, kDiagonals[0][0], kDiagonals[0][1]);
  for (int d = 1; d < 4; ++d)
    maxDiagonal = VMax(maxDiagonal, EdgeLength(p, kDiagonals[d][0], kDiagonals[d][1]));
  return Clamp(sqrt3 * SafeRatio(minEdge, maxDiagonal));
}

double HexDiagonal(const HexNodes& p)
{
  double minDiagonal = EdgeLength(p, kDiagonals[0][0], kDiagonals[0][1]);
  double maxDiagonal = minDiagonal;
  for (int d = 1; d < 4; ++d)
  {
    const double length = EdgeLength(p, kDiagonals[d][0], kDiagonals[d][1]);
    minDiagonal = VMin(minDiagonal, length);
    maxDiagonal = VMax(maxDiagonal, length);
  }
  return Clamp(SafeRatio(minDiagonal, maxDiagonal));
}

double HexEdgeRatio(const HexNodes& p)
{
  double l2[12];
  for (int e = 0; e < 12; ++e)
    l2[e] = Length2(p[kEdges[e][1]] - p[kEdges[e][0]]);
  // Verdict sorts the edges in pairs, then takes min over all pairs but max over the first three.
  double pairMin[6], pairMax[6];
  for (int k = 0; k < 6; ++k)
  {
    const double a = l2[2 * k], b = l2[2 * k + 1];
    pairMin[k] = a < b ? a : b;
    pairMax[k] = a < b ? b : a;
  }
  double m2 = pairMin[0];
  for (int k = 1; k < 6; ++k)
    m2 = m2 < pairMin[k] ? m2 : pairMin[k];
  if (m2 < kVerdictMin)
    return kVerdictMax;
  double M2 = pairMax[0] > pairMax[1] ? pairMax[0] : pairMax[1];
  M2 = M2 > pairMax[2] ? M2 : pairMax[2];
  return Clamp(std::sqrt(M2 / m2));
}

double HexMaxEdgeRatio(const HexNodes& p)
{
  const double m1 = Length(Axis1(p)), m2 = Length(Axis2(p)), m3 = Length(Axis3(p));
  const double a12 = SafeRatio(VMax(m1, m2), VMin(m1, m2));
  const double a13 = SafeRatio(VMax(m1, m3), VMin(m1, m3));
  const double a23 = SafeRatio(VMax(m2, m3), VMin(m2, m3));
  return Clamp(VMax(a12, VMax(a13, a23)));
}

double HexMaxAspectFrobenius(const HexNodes& p)
{
  double condition = Condition(CornerFrame(p, 0));
  for (int i = 1; i < 8; ++i)
  {
    const double c = Condition(CornerFrame(p, i));
    if (c > condition)
      condition = c;
  }
  // VTK 9.1 divides the flag too: a non-positive corner gives 1e30 / 3.
  return Clamp(condition / 3.);
}

double HexMedAspectFrobenius(const HexNodes& p)
{
  double sum = 0;
  for (int i = 0; i < 8; ++i)
    sum += Condition(CornerFrame(p, i));
  // Flagged corners (1e30 each) are averaged in, as VTK 9.1 does.
  return Clamp(sum / 24.);
}

double HexCondition(const HexNodes& p)
{
  return HexMaxAspectFrobenius(p);
}

double HexOddy(const HexNodes& p)
{
  double oddy = 0.0;
  const double center = Oddy(Axis1(p), Axis2(p), Axis3(p));
  if (center > oddy)
    oddy = center;
  for (int i = 0; i < 8; ++i)
  {
    const Frame f = CornerFrame(p, i);
    const double o = Oddy(f.a, f.b, f.c);
    if (o > oddy)
      oddy = o;
  }
  return Clamp(oddy);
}

double HexVolume(const HexNodes& p)
{
  return Clamp(HexCenterJacobian(p));
}

} // namespace mmrep::quality
