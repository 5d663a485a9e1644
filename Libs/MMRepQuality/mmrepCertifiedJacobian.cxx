// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepCertifiedJacobian.h"

#include "mmrepMeshQuality.h"
#include "mmrepWorkerThreads.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

namespace mmrep::quality
{

namespace
{
using Vector3 = Eigen::Vector3d;

// det J of the trilinear map of a hexahedron in VTK node order at (u, v, w) in [0, 1]^3.
double HexDet(const std::array<Vector3, 8>& x, double u, double v, double w)
{
  const double U = 1 - u, V = 1 - v, W = 1 - w;
  const Vector3 xu = V * W * (x[1] - x[0]) + v * W * (x[2] - x[3]) + V * w * (x[5] - x[4]) + v * w * (x[6] - x[7]);
  const Vector3 xv = U * W * (x[3] - x[0]) + u * W * (x[2] - x[1]) + U * w * (x[7] - x[4]) + u * w * (x[6] - x[5]);
  const Vector3 xw = U * V * (x[4] - x[0]) + u * V * (x[5] - x[1]) + U * v * (x[7] - x[3]) + u * v * (x[6] - x[2]);
  return xu.dot(xv.cross(xw));
}

struct Box
{
  double u0, v0, w0, size;
  int depth;
};

// Bernstein coefficients of det J over `box` from its values at the 3 x 3 x 3 points of the box
// (exact: det J is quadratic in each variable). Per axis: b0 = f(0), b1 = 2 f(1/2) - (f(0) + f(1)) / 2,
// b2 = f(1).
std::array<double, 27> Bernstein(const std::array<Vector3, 8>& x, const Box& b)
{
  std::array<double, 27> c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        c[9 * i + 3 * j + k] = HexDet(x, b.u0 + 0.5 * i * b.size, b.v0 + 0.5 * j * b.size, b.w0 + 0.5 * k * b.size);
  auto convert = [&c](int stride, int other1, int other2) {
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q)
      {
        double* f0 = &c[p * other1 + q * other2];
        f0[stride] = 2 * f0[stride] - 0.5 * (f0[0] + f0[2 * stride]);
      }
  };
  convert(9, 3, 1); // along u
  convert(3, 9, 1); // along v
  convert(1, 9, 3); // along w
  return c;
}

CertifiedJacobian CertifyHexahedron(const std::array<Vector3, 8>& x, int maximumDepth)
{
  CertifiedJacobian result;
  const std::array<double, 27> whole = Bernstein(x, {0, 0, 0, 1, 0});
  double mean = 0; // the integral of det J over the unit cube: every Bernstein basis integrates to 1/27
  for (const double b : whole)
    mean += b / 27;
  const double scale = std::abs(mean) > 0 ? std::abs(mean) : 1;
  double upper = std::numeric_limits<double>::infinity();
  bool cornerInverted = false;
  for (int corner = 0; corner < 27; ++corner)
  {
    const int i = corner / 9, j = (corner / 3) % 3, k = corner % 3;
    if (i == 1 || j == 1 || k == 1)
      continue;
    upper = std::min(upper, whole[static_cast<std::size_t>(corner)]);
    cornerInverted = cornerInverted || whole[static_cast<std::size_t>(corner)] <= 0;
  }
  // Branch and bound: a box is split while its lower bound is below the smallest value found less 1 %
  // of the mean, down to `maximumDepth` (and 4096 boxes).
  std::vector<std::pair<Box, std::array<double, 27>>> open{{Box{0, 0, 0, 1, 0}, whole}};
  double lower = std::numeric_limits<double>::infinity();
  int boxes = 1;
  while (!open.empty())
  {
    auto [box, c] = open.back();
    open.pop_back();
    for (std::size_t n : {0u, 2u, 6u, 8u, 18u, 20u, 24u, 26u})
      upper = std::min(upper, c[n]); // values at the box's corners
    const double boxLower = *std::min_element(c.begin(), c.end());
    // Once a corner or an inner point is inverted the sign is known: no more work for the bound.
    const bool refine = upper > 0 && boxLower < upper - 0.01 * scale;
    if (!refine || box.depth >= maximumDepth || boxes > 4096)
    {
      lower = std::min(lower, boxLower);
      continue;
    }
    const double half = 0.5 * box.size;
    for (int child = 0; child < 8; ++child)
    {
      const Box b{box.u0 + half * (child & 1), box.v0 + half * ((child >> 1) & 1), box.w0 + half * ((child >> 2) & 1),
                  half, box.depth + 1};
      open.emplace_back(b, Bernstein(x, b));
      ++boxes;
    }
  }
  result.lower = lower / scale;
  result.upper = upper / scale;
  if (cornerInverted)
    result.validity = Validity::InvertedCorner;
  else if (upper <= 0)
    result.validity = Validity::InvertedInside;
  else if (lower > 0)
    result.validity = Validity::Valid;
  else
    result.validity = Validity::Undecided;
  return result;
}

// Wedge in VTK order (triangle 0-1-2 at t = 0, 3-4-5 at t = 1), signed as the project's corner
// Jacobians: det J(r, s, t) is linear in (r, s) and quadratic in t, so its minimum lies on one of the
// three vertical edges, at an end or at the vertex of that quadratic.
CertifiedJacobian CertifyWedge(const std::array<Vector3, 6>& x, double orientation)
{
  auto det = [&](double r, double s, double t) {
    const double R = 1 - r - s, T = 1 - t;
    const Vector3 xr = T * (x[1] - x[0]) + t * (x[4] - x[3]);
    const Vector3 xs = T * (x[2] - x[0]) + t * (x[5] - x[3]);
    const Vector3 xt = R * (x[3] - x[0]) + r * (x[4] - x[1]) + s * (x[5] - x[2]);
    return orientation * xr.dot(xs.cross(xt));
  };
  const double rs[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  double minimum = std::numeric_limits<double>::infinity(), cornerMinimum = minimum;
  for (const auto& p : rs)
  {
    const double f0 = det(p[0], p[1], 0), fh = det(p[0], p[1], 0.5), f1 = det(p[0], p[1], 1);
    cornerMinimum = std::min({cornerMinimum, f0, f1});
    minimum = std::min({minimum, f0, f1});
    const double a = 2 * f0 - 4 * fh + 2 * f1, b = -3 * f0 + 4 * fh - f1; // f(t) = a t^2 + b t + f0
    if (a > 0 && -b / (2 * a) > 0 && -b / (2 * a) < 1)
      minimum = std::min(minimum, f0 - b * b / (4 * a));
  }
  // Mean over the wedge: the average of det J at the triangle's centroid along t (Simpson, exact).
  const double c = 1.0 / 3, mean = (det(c, c, 0) + 4 * det(c, c, 0.5) + det(c, c, 1)) / 6;
  const double scale = std::abs(mean) > 0 ? std::abs(mean) : 1;
  CertifiedJacobian result;
  result.lower = result.upper = minimum / scale;
  result.validity = cornerMinimum <= 0 ? Validity::InvertedCorner
                    : minimum <= 0     ? Validity::InvertedInside
                                       : Validity::Valid;
  return result;
}

template <std::size_t N> std::array<Vector3, N> Nodes(const FEMesh& mesh, const Element& e)
{
  std::array<Vector3, N> x;
  for (std::size_t i = 0; i < N; ++i)
    x[i] = mesh.nodes.at(static_cast<std::size_t>(e.nodes[i]));
  return x;
}
} // namespace

CertifiedJacobian CertifyElement(const FEMesh& mesh, std::size_t element, int maximumDepth)
{
  const Element& e = mesh.elements.at(element);
  switch (e.type)
  {
    case ElementType::Hexahedron:
      return CertifyHexahedron(Nodes<8>(mesh, e), maximumDepth);
    case ElementType::Wedge:
    {
      // The sign of the project's corner Jacobians (Verdict's wedge is VTK's mirrored).
      static const double orientation = [] {
        FEMesh unit;
        unit.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
        unit.elements.push_back({ElementType::Wedge, {0, 1, 2, 3, 4, 5}, TissueLayer::None});
        return CornerJacobians(unit, 0)[0] > 0 ? 1.0 : -1.0;
      }();
      return CertifyWedge(Nodes<6>(mesh, e), orientation);
    }
    case ElementType::Tetrahedron:
    {
      const double det = CornerJacobians(mesh, element)[0];
      CertifiedJacobian result;
      result.lower = result.upper = det > 0 ? 1 : (det < 0 ? -1 : 0);
      result.validity = det > 0 ? Validity::Valid : Validity::InvertedCorner;
      return result;
    }
    default:
      return {};
  }
}

double CertifiedQuality(const FEMesh& mesh, std::size_t element, double cornerQuality)
{
  const Element& e = mesh.elements.at(element);
  if (e.type == ElementType::Hexahedron)
  {
    const std::array<double, 27> whole = Bernstein(Nodes<8>(mesh, e), {0, 0, 0, 1, 0});
    if (*std::min_element(whole.begin(), whole.end()) > 0)
      return cornerQuality; // det J lies in the convex hull of its Bernstein coefficients
  }
  else if (e.type != ElementType::Wedge)
    return cornerQuality;
  const CertifiedJacobian c = CertifyElement(mesh, element);
  return c.validity == Validity::Valid ? cornerQuality : std::min(c.lower, 0.0);
}

CertificationSummary CertifyMesh(const FEMesh& mesh, int maximumDepth)
{
  const std::size_t n = mesh.elements.size();
  std::vector<CertifiedJacobian> results(n);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t e = next++; e < n; e = next++)
      results[e] = CertifyElement(mesh, e, maximumDepth);
  };
  std::vector<std::thread> workers;
  for (unsigned t = 1; t < WorkerThreads(); ++t)
    workers.emplace_back(work);
  work();
  for (std::thread& w : workers)
    w.join();
  CertificationSummary summary;
  summary.minimumLower = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t e = 0; e < n; ++e)
  {
    const CertifiedJacobian& r = results[e];
    if (r.validity == Validity::NotSolid)
      continue;
    ++summary.solids;
    summary.minimumLower = summary.solids == 1 ? r.lower : std::min(summary.minimumLower, r.lower);
    summary.valid += r.validity == Validity::Valid ? 1 : 0;
    summary.invertedCorner += r.validity == Validity::InvertedCorner ? 1 : 0;
    summary.invertedInside += r.validity == Validity::InvertedInside ? 1 : 0;
    summary.undecided += r.validity == Validity::Undecided ? 1 : 0;
    if (r.validity != Validity::Valid)
    {
      summary.notValid.push_back(e);
      summary.notValidLower.push_back(r.lower);
    }
  }
  return summary;
}

} // namespace mmrep::quality
