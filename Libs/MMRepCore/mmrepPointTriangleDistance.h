// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Closest point on a triangle (Ericson, Real-Time Collision Detection, 2005, §5.1.5): region
// tests on barycentric coordinates, exact for every point, no square roots.
#pragma once

#include <Eigen/Core>

namespace mmrep
{

// Which feature of triangle (a, b, c) holds the closest point: needed to pick the right
// pseudo-normal for the sign of a distance.
enum class TriangleFeature : unsigned char
{
  A,
  B,
  C,
  AB,
  AC,
  BC,
  Face
};

inline Eigen::Vector3d ClosestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                              const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                              TriangleFeature* feature = nullptr)
{
  auto at = [feature](TriangleFeature f) {
    if (feature)
      *feature = f;
  };
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0)
  {
    at(TriangleFeature::A); // vertex region A
    return a;
  }
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3)
  {
    at(TriangleFeature::B); // vertex region B
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    at(TriangleFeature::AB); // edge AB
    return Eigen::Vector3d(a + (d1 / (d1 - d3)) * ab);
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6)
  {
    at(TriangleFeature::C); // vertex region C
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    at(TriangleFeature::AC); // edge AC
    return Eigen::Vector3d(a + (d2 / (d2 - d6)) * ac);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    at(TriangleFeature::BC); // edge BC
    return Eigen::Vector3d(b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b));
  }
  const double denom = 1.0 / (va + vb + vc);
  at(TriangleFeature::Face);
  return a + ab * (vb * denom) + ac * (vc * denom); // interior
}

inline double SquaredDistanceToTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        const Eigen::Vector3d& c)
{
  return (ClosestPointOnTriangle(p, a, b, c) - p).squaredNorm();
}

} // namespace mmrep
