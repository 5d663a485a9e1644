// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Validity inside elements (mmrepCertifiedJacobian.h) against a brute-force reference: det J sampled
// on a dense grid from VTK's own shape-function derivatives, its mean from Gauss quadrature.
#include "QualityTestCells.h"
#include "mmrepCertifiedJacobian.h"
#include "mmrepFEMeshIO.h"
#include "mmrepMeshQuality.h"

#include <vtkHexahedron.h>
#include <vtkWedge.h>

#include <algorithm>
#include <iostream>
#include <limits>

namespace mmrep::quality::test
{
namespace
{
// det J at parametric (r, s, t) from VTK's interpolation derivatives (rows: d/dr, d/ds, d/dt).
template <class CellType, std::size_t N> double VtkDet(const std::array<Point3, N>& x, double r, double s, double t)
{
  double pc[3] = {r, s, t}, d[3 * N];
  CellType::InterpolationDerivs(pc, d);
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < N; ++i)
    for (int a = 0; a < 3; ++a)
      j.row(a) += d[a * N + i] * x[i].transpose();
  return j.determinant();
}

struct Sampled
{
  double minimum = std::numeric_limits<double>::infinity(), mean = 0;
};

Sampled SampleHex(const std::array<Point3, 8>& x, int n)
{
  Sampled s;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k)
        s.minimum = std::min(s.minimum, VtkDet<vtkHexahedron>(x, double(i) / n, double(j) / n, double(k) / n));
  const double g[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)}; // 2-point Gauss: exact here
  for (double r : g)
    for (double q : g)
      for (double t : g)
        s.mean += VtkDet<vtkHexahedron>(x, r, q, t) / 8;
  return s;
}

// Wedge: points of the triangle (r + s <= 1) times t.
double SampledWedgeMinimum(const std::array<Point3, 6>& x, int n, double sign)
{
  double minimum = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      for (int k = 0; k <= n; ++k)
        minimum = std::min(minimum, sign * VtkDet<vtkWedge>(x, double(i) / n, double(j) / n, double(k) / n));
  return minimum;
}

template <std::size_t N> FEMesh OneElement(ElementType type, const std::array<Point3, N>& x)
{
  FEMesh mesh;
  Element e;
  e.type = type;
  for (std::size_t i = 0; i < N; ++i)
  {
    e.nodes[i] = static_cast<std::int32_t>(i);
    mesh.nodes.push_back(x[i]);
  }
  mesh.elements.push_back(e);
  return mesh;
}

bool CornersPositive(const FEMesh& mesh, std::size_t e)
{
  const auto j = CornerJacobians(mesh, e);
  return std::all_of(j.begin(), j.end(), [](double v) { return v > 0; });
}
} // namespace

TEST(CertifiedJacobian, AffineHexahedronHasConstantDeterminant)
{
  const auto cell = Transformed(UnitHex(), General(), Point3(3, -1, 2));
  const CertifiedJacobian c = CertifyElement(OneElement(ElementType::Hexahedron, cell), 0);
  EXPECT_EQ(c.validity, Validity::Valid);
  EXPECT_NEAR(c.lower, 1.0, 1e-12);
  EXPECT_NEAR(c.upper, 1.0, 1e-12);
}

// Random trilinear hexahedra (some folded): the certificate never calls an element valid that the dense
// sampling finds inverted, its lower bound lies below every sampled value and within 1 % (plus the
// sampling's own error) of the sampled minimum where the element is valid.
TEST(CertifiedJacobian, HexahedraAgreeWithDenseSampling)
{
  int valid = 0, insideOnly = 0;
  for (const auto& cell : MakeCells(UnitHex(), 300, 17))
  {
    SCOPED_TRACE(cell.name);
    const FEMesh mesh = OneElement(ElementType::Hexahedron, cell.nodes);
    const CertifiedJacobian c = CertifyElement(mesh, 0);
    const Sampled s = SampleHex(cell.nodes, 24);
    if (!(std::abs(s.mean) > 1e-12))
      continue; // a collapsed cell: no scale to compare with
    const double scale = std::abs(s.mean);
    EXPECT_LE(c.lower * scale, s.minimum + 1e-9 * scale);
    if (c.validity == Validity::Valid)
    {
      ++valid;
      EXPECT_GT(s.minimum, 0);
      EXPECT_GE(c.lower * scale, s.minimum - 0.011 * scale - 1e-9);
    }
    if (s.minimum < -1e-9 * scale)
      EXPECT_NE(c.validity, Validity::Valid);
    if (c.validity == Validity::InvertedInside)
    {
      ++insideOnly;
      EXPECT_TRUE(CornersPositive(mesh, 0));
      EXPECT_LE(c.upper, 0);
    }
    if (c.validity == Validity::InvertedCorner)
      EXPECT_FALSE(CornersPositive(mesh, 0));
  }
  EXPECT_GT(valid, 150);
}

// A hexahedron valid at its corners but inverted inside: element 3350 of the atlas as it was before it was
// rebuilt with the certifying repair (hypodermis; nodes 5 and 6 lie 0.014 mm apart). Scaled Jacobian 0.57,
// every corner Jacobian positive; dense sampling finds det J < 0 inside, and so does the certificate.
TEST(CertifiedJacobian, FoldInsideValidCornersReportedInvalid)
{
  const std::array<Point3, 8> x = {Point3(110.30836007788798, 25.086518386083696, 98.464803097702614),
                                   Point3(110.67202214310326, 14.590211385636749, 106.61007612873109),
                                   Point3(112.33477411983563, 16.131957336143799, 106.74960804602772),
                                   Point3(111.0871357037864, 25.437185128633246, 98.501755486168136),
                                   Point3(110.1627319740989, 26.739720162171551, 100.97113667946464),
                                   Point3(110.50656604227811, 17.502732029256052, 107.11826873468775),
                                   Point3(110.52162499502033, 17.509250466193848, 107.11612193362332),
                                   Point3(111.07785227356305, 26.208717350260116, 99.93736173969161)};
  const FEMesh mesh = OneElement(ElementType::Hexahedron, x);
  EXPECT_TRUE(CornersPositive(mesh, 0));
  EXPECT_GT(ElementQuality(mesh, 0, Measure::ScaledJacobian), 0.5);
  const Sampled s = SampleHex(x, 40);
  ASSERT_LT(s.minimum, 0) << "the reference: dense sampling finds the fold";
  const CertifiedJacobian c = CertifyElement(mesh, 0);
  EXPECT_EQ(c.validity, Validity::InvertedInside);
  EXPECT_LE(c.upper, 0);
  EXPECT_LE(c.lower * std::abs(s.mean), s.minimum + 1e-9);
  EXPECT_GE(c.lower * std::abs(s.mean), s.minimum - 0.011 * std::abs(s.mean));
}

// The fold the corner test misses was in the shipped atlas (hypodermis elements 3350 and 8858, a
// mirror pair: scaled Jacobian 0.57 at the corners, inverted inside) until the atlas builder's repair
// certified every element. Now every element is certified valid, and agrees with dense sampling.
TEST(CertifiedJacobian, ShippedAtlasAgreesWithDenseSampling)
{
  const FEMesh atlas = ReadFEMesh(std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu");
  const CertificationSummary summary = CertifyMesh(atlas);
  EXPECT_EQ(summary.solids, atlas.SolidElementCount());
  std::vector<std::size_t> sampledInverted;
  for (std::size_t e = 0; e < atlas.elements.size(); ++e)
  {
    if (atlas.elements[e].type != ElementType::Hexahedron)
      continue;
    std::array<Point3, 8> x;
    for (std::size_t i = 0; i < 8; ++i)
      x[i] = atlas.nodes[static_cast<std::size_t>(atlas.elements[e].nodes[i])];
    if (SampleHex(x, 8).minimum <= 0)
      sampledInverted.push_back(e);
  }
  for (const std::size_t e : sampledInverted) // what sampling finds inverted is never certified
    EXPECT_TRUE(std::binary_search(summary.notValid.begin(), summary.notValid.end(), e)) << "element " << e;
  for (const std::size_t e : summary.notValid)
    EXPECT_TRUE(CornersPositive(atlas, e)) << "element " << e << ": the corner test already sees it";
  EXPECT_EQ(summary.NotValid(), 0u) << "the shipped atlas must be valid inside every element";
  std::cout << "shipped atlas: " << summary.valid << " of " << summary.solids << " certified valid; inverted inside "
            << summary.invertedInside << ", undecided " << summary.undecided << "; sampling finds "
            << sampledInverted.size() << " inverted; smallest lower bound " << summary.minimumLower << "\n";
}

TEST(CertifiedJacobian, WedgesExactAndSignedAsTheCornerJacobians)
{
  // VTK's derivatives and the project's corner Jacobians differ in sign convention for wedges: the
  // sampled determinant takes the corner Jacobians' sign, fixed once on the unit wedge.
  const auto unit = UnitWedge();
  const double sign =
    VtkDet<vtkWedge>(unit, 0, 0, 0) * CornerJacobians(OneElement(ElementType::Wedge, unit), 0)[0] > 0 ? 1 : -1;
  int valid = 0;
  for (const auto& cell : MakeCells(UnitWedge(), 300, 29))
  {
    SCOPED_TRACE(cell.name);
    const FEMesh mesh = OneElement(ElementType::Wedge, cell.nodes);
    const CertifiedJacobian c = CertifyElement(mesh, 0);
    const auto corners = CornerJacobians(mesh, 0);
    const double signedSampled = SampledWedgeMinimum(cell.nodes, 30, sign);
    if (c.validity == Validity::Valid)
    {
      ++valid;
      EXPECT_GT(signedSampled, 0);
    }
    if (signedSampled < -1e-9)
      EXPECT_NE(c.validity, Validity::Valid);
    EXPECT_EQ(c.validity == Validity::InvertedCorner,
              std::any_of(corners.begin(), corners.end(), [](double v) { return v <= 0; }));
  }
  EXPECT_GT(valid, 150);
}

} // namespace mmrep::quality::test
