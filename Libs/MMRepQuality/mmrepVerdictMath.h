// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Arithmetic shared by the quality measures, written to round exactly like Verdict (VTK's
// ThirdParty/verdict) so that results agree with vtkMeshQuality to the last bits: same vector
// operation order, same comparison-based min/max (NaN handling differs from std::min/max), and
// Verdict's ±1e30 flags for undefined values.
#pragma once

#include "mmrepFEMesh.h"

#include <algorithm>
#include <cmath>

namespace mmrep::quality
{

// Verdict's VERDICT_DBL_MAX / VERDICT_DBL_MIN: results are clamped to ±kVerdictMax, and
// degenerate cells (zero-length edge, zero volume, …) are flagged with +kVerdictMax by many measures.
constexpr double kVerdictMax = 1.0e30;
constexpr double kVerdictMin = 1.0e-30;

// True for Verdict's "undefined" flag values: ±kVerdictMax, possibly divided by a small constant
// (VTK 9.1's hex aspect Frobenius averages flagged corners: 1e30 / 3, 1e30 / 24). No genuine quality
// value comes near 1e28.
inline bool IsVerdictFlag(double value)
{
  return std::abs(value) >= kVerdictMax / 100;
}

namespace detail
{
inline Point3 Cross(const Point3& a, const Point3& b)
{
  return Point3(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(), a.x() * b.y() - a.y() * b.x());
}
inline double Dot(const Point3& a, const Point3& b)
{
  return a.x() * b.x() + a.y() * b.y() + a.z() * b.z();
}
inline double Length2(const Point3& a)
{
  return Dot(a, a);
}
inline double Length(const Point3& a)
{
  return std::sqrt(Length2(a));
}
// a · (b × c): the determinant of the corner frame (a, b, c).
inline double Det(const Point3& a, const Point3& b, const Point3& c)
{
  return Dot(a, Cross(b, c));
}
// Verdict's VERDICT_MIN / VERDICT_MAX (a comparison, so a NaN first argument is dropped).
inline double VMin(double a, double b)
{
  return a < b ? a : b;
}
inline double VMax(double a, double b)
{
  return a > b ? a : b;
}
// Verdict's final clamp of a signed result to [-kVerdictMax, kVerdictMax]; as in VTK 9.1 a NaN
// (e.g. angles of a collapsed cell) becomes -kVerdictMax.
inline double Clamp(double v)
{
  return v > 0 ? VMin(v, kVerdictMax) : VMax(v, -kVerdictMax);
}
// numerator / denominator, or kVerdictMax when the denominator vanishes.
inline double SafeRatio(double numerator, double denominator)
{
  if (std::abs(numerator) <= kVerdictMax && std::abs(denominator) >= kVerdictMin)
    return numerator / denominator;
  return kVerdictMax;
}
} // namespace detail
} // namespace mmrep::quality
