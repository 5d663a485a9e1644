// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Hexahedron measures against vtkMeshQuality (VTK 9.1) and independent hand values.
#include "QualityTestCells.h"
#include "mmrepHexQuality.h"

#include <vtkMeshQuality.h>

namespace mmrep::quality::test
{
namespace
{
struct HexMeasure
{
  const char* name;
  double (*ours)(const HexNodes&);
  double (*vtk)(vtkCell*);
};

const HexMeasure kHexMeasures[] = {
  {"Jacobian", HexJacobian, vtkMeshQuality::HexJacobian},
  {"ScaledJacobian", HexScaledJacobian, vtkMeshQuality::HexScaledJacobian},
  {"Shape", HexShape, vtkMeshQuality::HexShape},
  {"Shear", HexShear, vtkMeshQuality::HexShear},
  {"Skew", HexSkew, vtkMeshQuality::HexSkew},
  {"Taper", HexTaper, vtkMeshQuality::HexTaper},
  {"Stretch", HexStretch, vtkMeshQuality::HexStretch},
  {"Diagonal", HexDiagonal, vtkMeshQuality::HexDiagonal},
  {"EdgeRatio", HexEdgeRatio, vtkMeshQuality::HexEdgeRatio},
  {"MaxEdgeRatio", HexMaxEdgeRatio, vtkMeshQuality::HexMaxEdgeRatio},
  {"MaxAspectFrobenius", HexMaxAspectFrobenius, vtkMeshQuality::HexMaxAspectFrobenius},
  {"MedAspectFrobenius", HexMedAspectFrobenius, vtkMeshQuality::HexMedAspectFrobenius},
  {"Condition", HexCondition, vtkMeshQuality::HexCondition},
  {"Oddy", HexOddy, vtkMeshQuality::HexOddy},
  {"Volume", HexVolume, vtkMeshQuality::HexVolume},
};

class QualityHex : public ::testing::TestWithParam<HexMeasure>
{
};

TEST_P(QualityHex, EqualsVtkMeshQuality)
{
  const HexMeasure& m = GetParam();
  const auto cells = MakeCells(UnitHex(), 400, 20240611u);
  int inverted = 0;
  for (const auto& c : cells)
  {
    auto cell = MakeVtkCell<vtkHexahedron>(c.nodes);
    EXPECT_TRUE(SameQuality(m.ours(c.nodes), m.vtk(cell), 1.0)) << m.name << " on " << c.name;
    inverted += HexJacobian(c.nodes) < 0;
  }
  // The cell set must exercise inverted cells, not only valid ones.
  EXPECT_GT(inverted, 20);
}

INSTANTIATE_TEST_SUITE_P(QualityHexMeasures, QualityHex, ::testing::ValuesIn(kHexMeasures),
                         [](const ::testing::TestParamInfo<HexMeasure>& info) { return std::string(info.param.name); });

// Corner Jacobians against the isoparametric Jacobian matrix of vtkHexahedron at each corner.
TEST(QualityHexCorners, EqualIsoparametricJacobianAtCorners)
{
  const auto cells = MakeCells(UnitHex(), 200, 7u);
  vtkNew<vtkHexahedron> hex;
  const double* pcoords = hex->GetParametricCoords();
  for (const auto& c : cells)
  {
    const auto ours = HexCornerJacobians(c.nodes);
    for (int i = 0; i < 8; ++i)
    {
      double derivs[24];
      vtkHexahedron::InterpolationDerivs(pcoords + 3 * i, derivs);
      Eigen::Matrix3d j = Eigen::Matrix3d::Zero(); // columns d/dr, d/ds, d/dt
      for (int n = 0; n < 8; ++n)
        for (int d = 0; d < 3; ++d)
          j.col(d) += derivs[8 * d + n] * c.nodes[n];
      EXPECT_NEAR(ours[i], j.determinant(), 1e-12 * std::max(1.0, std::abs(ours[i]))) << c.name << " corner " << i;
    }
  }
}

TEST(QualityHexValues, UnitCubeAndKnownShapes)
{
  const auto unit = UnitHex();
  EXPECT_DOUBLE_EQ(HexJacobian(unit), 1.0);
  EXPECT_DOUBLE_EQ(HexScaledJacobian(unit), 1.0);
  EXPECT_DOUBLE_EQ(HexShape(unit), 1.0);
  EXPECT_DOUBLE_EQ(HexSkew(unit), 0.0);
  EXPECT_DOUBLE_EQ(HexTaper(unit), 0.0);
  EXPECT_DOUBLE_EQ(HexStretch(unit), 1.0);
  EXPECT_DOUBLE_EQ(HexEdgeRatio(unit), 1.0);
  EXPECT_DOUBLE_EQ(HexMaxAspectFrobenius(unit), 1.0);
  for (double j : HexCornerJacobians(unit))
    EXPECT_DOUBLE_EQ(j, 1.0);

  // A 2 x 1 x 1 box: corner Jacobians = volume, edge ratio 2, stretch sqrt(3)/sqrt(6).
  const auto box = Transformed(unit, Eigen::Vector3d(2, 1, 1).asDiagonal());
  EXPECT_DOUBLE_EQ(HexJacobian(box), 2.0);
  EXPECT_DOUBLE_EQ(HexScaledJacobian(box), 1.0);
  EXPECT_NEAR(HexStretch(box), std::sqrt(3.0) / std::sqrt(6.0), 1e-15);

  // Shear by 45 degrees in x-z: every corner frame has one edge at 45 degrees -> scaled sin 45.
  Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
  shear(0, 2) = 1.0;
  EXPECT_NEAR(HexScaledJacobian(Transformed(unit, shear)), std::sqrt(0.5), 1e-15);

  // Mirroring inverts every corner: Jacobian -1, scaled Jacobian -1, shape 0.
  const auto mirrored = Transformed(unit, Mirror());
  EXPECT_DOUBLE_EQ(HexJacobian(mirrored), -1.0);
  EXPECT_DOUBLE_EQ(HexScaledJacobian(mirrored), -1.0);
  EXPECT_DOUBLE_EQ(HexShape(mirrored), 0.0);

  // A zero-length edge is flagged by Verdict with +1e30 for the scaled Jacobian.
  auto collapsed = unit;
  collapsed[1] = collapsed[0];
  EXPECT_EQ(HexScaledJacobian(collapsed), kVerdictMax);
  EXPECT_TRUE(IsVerdictFlag(HexScaledJacobian(collapsed)));
}

// Pushing one corner through the opposite face makes exactly the corners around it negative.
TEST(QualityHexCorners, InvertedCornerIsNegative)
{
  auto p = UnitHex();
  p[6] = Point3(0.3, 0.3, 0.3); // node 6 pushed inside past the diagonal plane
  const auto j = HexCornerJacobians(p);
  EXPECT_LT(j[6], 0.0);
  EXPECT_GT(j[0], 0.0);
  EXPECT_LT(HexJacobian(p), 0.0);
  EXPECT_LT(HexScaledJacobian(p), 0.0);
}
} // namespace
} // namespace mmrep::quality::test
