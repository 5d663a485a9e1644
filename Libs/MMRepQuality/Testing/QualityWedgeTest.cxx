// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Wedge measures. VTK 9.1's vtkMeshQuality has none, so the references are independent:
// vtkWedge::InterpolationDerivs at the corner parametric coordinates (isoparametric Jacobian) for the
// corner determinants' values and signs, and hand-computed values on right prisms. VTK 9.1's Verdict
// library does ship the later wedge functions (unexported from vtkMeshQuality); they serve as a
// further cross-check after mapping VTK order to Verdict's mirrored order.
#include "QualityTestCells.h"
#include "mmrepWedgeQuality.h"

extern "C"
{
  // From libvtkverdict-9.1 (C linkage, Verdict's wedge node order).
  double vtkverdict__wedge_jacobian(int numNodes, double coordinates[][3]);
  double vtkverdict__wedge_scaled_jacobian(int numNodes, double coordinates[][3]);
  double vtkverdict__wedge_shape(int numNodes, double coordinates[][3]);
  double vtkverdict__wedge_edge_ratio(int numNodes, double coordinates[][3]);
}

namespace mmrep::quality::test
{
namespace
{
// Isoparametric Jacobian determinant of vtkWedge at corner i.
double IsoparametricDeterminant(const WedgeNodes& p, int corner)
{
  vtkNew<vtkWedge> wedge;
  const double* pcoords = wedge->GetParametricCoords();
  double derivs[18];
  vtkWedge::InterpolationDerivs(pcoords + 3 * corner, derivs);
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  for (int n = 0; n < 6; ++n)
    for (int d = 0; d < 3; ++d)
      j.col(d) += derivs[6 * d + n] * p[n];
  return j.determinant();
}

TEST(QualityWedge, CornerJacobiansMatchIsoparametricJacobian)
{
  const auto cells = MakeCells(UnitWedge(), 400, 2718u);
  int negative = 0, zero = 0;
  for (const auto& c : cells)
  {
    const auto ours = WedgeCornerJacobians(c.nodes);
    double minimum = ours[0];
    for (int i = 0; i < 6; ++i)
    {
      // vtkWedge's parametric frame is left-handed for a valid wedge: the determinant is the negative.
      const double iso = -IsoparametricDeterminant(c.nodes, i);
      EXPECT_NEAR(ours[i], iso, 1e-12 * std::max(1.0, std::abs(iso))) << c.name << " corner " << i;
      EXPECT_EQ(ours[i] > 0, iso > 0) << c.name << " corner " << i;
      EXPECT_EQ(ours[i] == 0, iso == 0) << c.name << " corner " << i;
      minimum = std::min(minimum, ours[i]);
      negative += ours[i] < 0;
      zero += ours[i] == 0;
    }
    EXPECT_EQ(WedgeJacobian(c.nodes), minimum) << c.name;
    // The scaled Jacobian is negative exactly when some corner is.
    if (!IsVerdictFlag(WedgeScaledJacobian(c.nodes)))
      EXPECT_EQ(WedgeScaledJacobian(c.nodes) < 0, minimum < 0) << c.name;
  }
  EXPECT_GT(negative, 20);
  EXPECT_GT(zero, 5);
}

// Right prism on a right isosceles triangle (legs a) of height h, VTK order.
WedgeNodes RightPrism(double a, double h)
{
  return {Point3(0, 0, 0), Point3(0, a, 0), Point3(a, 0, 0), Point3(0, 0, h), Point3(0, a, h), Point3(a, 0, h)};
}

TEST(QualityWedge, HandValuesOnRightPrisms)
{
  // Equilateral unit prism: every measure is 1; the corner determinant is 2 x area x height.
  const auto unit = UnitWedge();
  for (double j : WedgeCornerJacobians(unit))
    EXPECT_NEAR(j, std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(WedgeScaledJacobian(unit), 1.0, 1e-15);
  EXPECT_NEAR(WedgeShape(unit), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(WedgeEdgeRatio(unit), 1.0);

  for (const auto& [a, h] : {std::pair{1.0, 1.0}, std::pair{2.0, 0.5}, std::pair{0.3, 4.0}})
  {
    const auto p = RightPrism(a, h);
    // Every corner: |leg x leg| h = a^2 h.
    for (double j : WedgeCornerJacobians(p))
      EXPECT_NEAR(j, a * a * h, 1e-14 * a * a * h);
    EXPECT_NEAR(WedgeJacobian(p), a * a * h, 1e-14 * a * a * h);
    // Worst corners are the 45-degree ones: a^2 h / (a * a sqrt2 * h) = 1/sqrt2, times 2/sqrt3.
    EXPECT_NEAR(WedgeScaledJacobian(p), std::sqrt(2.0 / 3.0), 1e-14);
    // Shape at a 45-degree corner: 3 (2 a^2 h / sqrt3)^(2/3) / (a^2 + 2 a^2 + h^2); at the right-angle
    // corner the denominator is 2 a^2 + h^2, so the 45-degree corner is the minimum.
    const double expectedShape = 3 * std::pow(2 * a * a * h / std::sqrt(3.0), 2.0 / 3.0) / (3 * a * a + h * h);
    EXPECT_NEAR(WedgeShape(p), expectedShape, 1e-14);
    const double edges[3] = {a, a * std::sqrt(2.0), h};
    EXPECT_NEAR(WedgeEdgeRatio(p), *std::max_element(edges, edges + 3) / *std::min_element(edges, edges + 3), 1e-14);
  }

  // Mirrored prism: all corners inverted; the most negative scaled corner is the right-angle one,
  // -1 x 2/sqrt3; shape 0.
  const auto mirrored = Transformed(RightPrism(1, 1), Mirror());
  for (double j : WedgeCornerJacobians(mirrored))
    EXPECT_NEAR(j, -1.0, 1e-15);
  EXPECT_NEAR(WedgeScaledJacobian(mirrored), -2 / std::sqrt(3.0), 1e-14);
  EXPECT_EQ(WedgeShape(mirrored), 0.0);

  // Degenerate: zero-length edge flags the scaled Jacobian; a flat wedge has zero determinants.
  auto collapsed = RightPrism(1, 1);
  collapsed[3] = collapsed[0];
  EXPECT_EQ(WedgeScaledJacobian(collapsed), kVerdictMax);
  EXPECT_EQ(WedgeShape(collapsed), 0.0);
  const auto flat = RightPrism(1, 0);
  EXPECT_EQ(WedgeJacobian(flat), 0.0);
}

TEST(QualityWedge, AgreesWithVtk91VerdictLibrary)
{
  const auto cells = MakeCells(UnitWedge(), 400, 161803u);
  for (const auto& c : cells)
  {
    // VTK order -> Verdict order: swap 0<->1 and 3<->4 (as vtkMeshQuality does from VTK 9.3 on).
    double q[6][3];
    const int order[6] = {1, 0, 2, 4, 3, 5};
    for (int i = 0; i < 6; ++i)
      for (int d = 0; d < 3; ++d)
        q[i][d] = c.nodes[order[i]][d];
    EXPECT_TRUE(SameQuality(WedgeJacobian(c.nodes), vtkverdict__wedge_jacobian(6, q))) << c.name;
    // VTK 9.1's wedge_shape predates the later rule "0 when a corner is inverted" (it skips the NaN
    // corners instead), and its edge ratio does not flag 0/0: compare where the definitions agree.
    if (WedgeJacobian(c.nodes) > kVerdictMin)
      EXPECT_TRUE(SameQuality(WedgeShape(c.nodes), vtkverdict__wedge_shape(6, q))) << c.name;
    if (!IsVerdictFlag(WedgeEdgeRatio(c.nodes)))
      EXPECT_TRUE(SameQuality(WedgeEdgeRatio(c.nodes), vtkverdict__wedge_edge_ratio(6, q))) << c.name;
    const double scaled = WedgeScaledJacobian(c.nodes);
    if (!IsVerdictFlag(scaled)) // Verdict divides by zero lengths unguarded
      EXPECT_TRUE(SameQuality(scaled, vtkverdict__wedge_scaled_jacobian(6, q))) << c.name;
  }
}
} // namespace
} // namespace mmrep::quality::test
