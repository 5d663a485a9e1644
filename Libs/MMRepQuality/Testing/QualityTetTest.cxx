// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Tetrahedron measures against vtkMeshQuality (VTK 9.1) and independent hand values.
#include "QualityTestCells.h"
#include "mmrepTetQuality.h"

#include <vtkMeshQuality.h>

namespace mmrep::quality::test
{
namespace
{
struct TetMeasure
{
  const char* name;
  double (*ours)(const TetNodes&);
  double (*vtk)(vtkCell*);
};

const TetMeasure kTetMeasures[] = {
  {"Jacobian", TetJacobian, vtkMeshQuality::TetJacobian},
  {"ScaledJacobian", TetScaledJacobian, vtkMeshQuality::TetScaledJacobian},
  {"Shape", TetShape, vtkMeshQuality::TetShape},
  {"EdgeRatio", TetEdgeRatio, vtkMeshQuality::TetEdgeRatio},
  {"AspectRatio", TetAspectRatio, vtkMeshQuality::TetAspectRatio},
  {"RadiusRatio", TetRadiusRatio, vtkMeshQuality::TetRadiusRatio},
  {"AspectBeta", TetAspectBeta, vtkMeshQuality::TetAspectBeta},
  {"AspectGamma", TetAspectGamma, vtkMeshQuality::TetAspectGamma},
  {"AspectFrobenius", TetAspectFrobenius, vtkMeshQuality::TetAspectFrobenius},
  {"MinAngle", TetMinAngle, vtkMeshQuality::TetMinAngle},
  {"CollapseRatio", TetCollapseRatio, vtkMeshQuality::TetCollapseRatio},
  {"Condition", TetCondition, vtkMeshQuality::TetCondition},
  {"Volume", TetVolume, vtkMeshQuality::TetVolume},
};

class QualityTet : public ::testing::TestWithParam<TetMeasure>
{
};

TEST_P(QualityTet, EqualsVtkMeshQuality)
{
  const TetMeasure& m = GetParam();
  const auto cells = MakeCells(UnitTet(), 400, 314159u);
  int inverted = 0;
  for (const auto& c : cells)
  {
    auto cell = MakeVtkCell<vtkTetra>(c.nodes);
    EXPECT_TRUE(SameQuality(m.ours(c.nodes), m.vtk(cell), 1.0)) << m.name << " on " << c.name;
    inverted += TetJacobian(c.nodes) < 0;
  }
  EXPECT_GT(inverted, 10);
}

INSTANTIATE_TEST_SUITE_P(QualityTetMeasures, QualityTet, ::testing::ValuesIn(kTetMeasures),
                         [](const ::testing::TestParamInfo<TetMeasure>& info) { return std::string(info.param.name); });

TEST(QualityTetValues, RegularAndRightTetrahedra)
{
  // Regular tetrahedron with unit edges, positively oriented in VTK order.
  const std::array<Point3, 4> regular = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0.5, std::sqrt(3.0) / 2, 0),
                                         Point3(0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3.0))};
  EXPECT_NEAR(TetScaledJacobian(regular), 1.0, 1e-14);
  EXPECT_NEAR(TetShape(regular), 1.0, 1e-14);
  EXPECT_NEAR(TetAspectRatio(regular), 1.0, 1e-14);
  EXPECT_NEAR(TetEdgeRatio(regular), 1.0, 1e-14);
  EXPECT_NEAR(TetVolume(regular), 1.0 / (6 * std::sqrt(2.0)), 1e-15);
  EXPECT_NEAR(TetMinAngle(regular), std::acos(1.0 / 3) * 180 / M_PI, 1e-12);

  // Right corner tet: Jacobian 1, edge ratio sqrt(2), scaled Jacobian sqrt(2) * 1 / (1 * sqrt2 * sqrt2).
  const auto unit = UnitTet();
  EXPECT_DOUBLE_EQ(TetJacobian(unit), 1.0);
  EXPECT_NEAR(TetEdgeRatio(unit), std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(TetScaledJacobian(unit), std::sqrt(2.0) / 2, 1e-15);

  // Mirrored: Jacobian changes sign, shape drops to 0.
  const auto mirrored = Transformed(unit, Mirror());
  EXPECT_DOUBLE_EQ(TetJacobian(mirrored), -1.0);
  EXPECT_NEAR(TetScaledJacobian(mirrored), -std::sqrt(2.0) / 2, 1e-15);
  EXPECT_EQ(TetShape(mirrored), 0.0);
  EXPECT_NEAR(TetAspectRatio(mirrored), TetAspectRatio(unit), 1e-15); // VTK 9.1 ignores orientation
}
} // namespace
} // namespace mmrep::quality::test
