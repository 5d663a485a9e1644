// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Per-mesh evaluation: agreement with the vtkMeshQuality filter, thread-count independence,
// corner Jacobians, summary statistics and errors.
#include "QualityTestCells.h"
#include "mmrepHexQuality.h"
#include "mmrepMeshQuality.h"
#include "mmrepTetQuality.h"
#include "mmrepWedgeQuality.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkMeshQuality.h>
#include <vtkUnstructuredGrid.h>

#include <cstring>
#include <limits>

namespace mmrep::quality::test
{
namespace
{
// A mesh of perturbed hexes, tets and wedges (some inverted) plus cable elements.
FEMesh MixedMesh(int perType, unsigned seed)
{
  FEMesh mesh;
  auto add = [&mesh](ElementType type, const auto& nodes) {
    Element e;
    e.type = type;
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      e.nodes[i] = static_cast<std::int32_t>(mesh.nodes.size());
      mesh.nodes.push_back(nodes[i]);
    }
    mesh.elements.push_back(e);
  };
  const auto hexes = MakeCells(UnitHex(), perType, seed);
  const auto tets = MakeCells(UnitTet(), perType, seed + 1);
  const auto wedges = MakeCells(UnitWedge(), perType, seed + 2);
  for (std::size_t i = 0; i < hexes.size(); ++i)
  {
    add(ElementType::Hexahedron, hexes[i].nodes);
    add(ElementType::Tetrahedron, tets[i].nodes);
    add(ElementType::Wedge, wedges[i].nodes);
    if (i % 10 == 0)
      add(ElementType::Cable, std::array<Point3, 2>{Point3(0, 0, 0), Point3(1, 1, 1)});
  }
  return mesh;
}

vtkSmartPointer<vtkUnstructuredGrid> ToGrid(const FEMesh& mesh)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const Point3& p : mesh.nodes)
    points->InsertNextPoint(p.data());
  grid->SetPoints(points);
  for (const Element& e : mesh.elements)
  {
    vtkIdType ids[8];
    for (int i = 0; i < NodeCount(e.type); ++i)
      ids[i] = e.nodes[i];
    grid->InsertNextCell(static_cast<int>(e.type), NodeCount(e.type), ids);
  }
  return grid;
}

struct FilterMeasure
{
  Measure measure;
  int hex; // VTK_QUALITY_* for hexes, -1 if none
  int tet; // VTK_QUALITY_* for tets, -1 if none
};

TEST(QualityMesh, EqualsVtkMeshQualityFilter)
{
  const FEMesh mesh = MixedMesh(150, 99u);
  auto grid = ToGrid(mesh);
  const FilterMeasure measures[] = {
    {Measure::Jacobian, VTK_QUALITY_JACOBIAN, VTK_QUALITY_JACOBIAN},
    {Measure::ScaledJacobian, VTK_QUALITY_SCALED_JACOBIAN, VTK_QUALITY_SCALED_JACOBIAN},
    {Measure::Shape, VTK_QUALITY_SHAPE, VTK_QUALITY_SHAPE},
    {Measure::EdgeRatio, VTK_QUALITY_EDGE_RATIO, VTK_QUALITY_EDGE_RATIO},
    {Measure::MaxAspectFrobenius, VTK_QUALITY_MAX_ASPECT_FROBENIUS, -1},
    {Measure::Skew, VTK_QUALITY_SKEW, -1},
    {Measure::Taper, VTK_QUALITY_TAPER, -1},
    {Measure::Stretch, VTK_QUALITY_STRETCH, -1},
    {Measure::AspectRatio, -1, VTK_QUALITY_ASPECT_RATIO},
    {Measure::RadiusRatio, -1, VTK_QUALITY_RADIUS_RATIO},
    {Measure::MinAngle, -1, VTK_QUALITY_MIN_ANGLE},
    {Measure::Volume, VTK_QUALITY_VOLUME, VTK_QUALITY_VOLUME},
  };
  std::vector<Measure> list;
  for (const auto& m : measures)
    list.push_back(m.measure);
  const auto ours = ComputeQuality(mesh, list, {2, nullptr});
  for (std::size_t k = 0; k < list.size(); ++k)
  {
    vtkNew<vtkMeshQuality> filter;
    filter->SetInputData(grid);
    filter->SetHexQualityMeasure(measures[k].hex >= 0 ? measures[k].hex : VTK_QUALITY_JACOBIAN);
    filter->SetTetQualityMeasure(measures[k].tet >= 0 ? measures[k].tet : VTK_QUALITY_JACOBIAN);
    filter->Update();
    vtkDataArray* quality = filter->GetOutput()->GetCellData()->GetArray("Quality");
    ASSERT_NE(quality, nullptr);
    std::size_t compared = 0;
    for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    {
      const ElementType type = mesh.elements[e].type;
      const int vtkMeasure = type == ElementType::Hexahedron    ? measures[k].hex
                             : type == ElementType::Tetrahedron ? measures[k].tet
                                                                : -1;
      if (vtkMeasure < 0)
      {
        EXPECT_EQ(std::isnan(ours[k][e]), !IsDefined(list[k], type)) << MeasureName(list[k]) << " element " << e;
        continue;
      }
      EXPECT_TRUE(SameQuality(ours[k][e], quality->GetTuple1(static_cast<vtkIdType>(e))))
        << MeasureName(list[k]) << " element " << e << " " << ElementTypeName(type);
      ++compared;
    }
    EXPECT_GT(compared, 150u);
  }
}

TEST(QualityMesh, SameBitsForAnyThreadCount)
{
  FEMesh mesh;
  // Many elements so that several chunks exist.
  for (int copy = 0; copy < 12; ++copy)
  {
    FEMesh part = MixedMesh(300, 1000u + static_cast<unsigned>(copy));
    const auto offset = static_cast<std::int32_t>(mesh.nodes.size());
    mesh.nodes.insert(mesh.nodes.end(), part.nodes.begin(), part.nodes.end());
    for (Element e : part.elements)
    {
      for (int i = 0; i < NodeCount(e.type); ++i)
        e.nodes[i] += offset;
      mesh.elements.push_back(e);
    }
  }
  ASSERT_GT(mesh.elements.size(), 5000u);
  const auto& all = AllMeasures();
  const auto one = ComputeQuality(mesh, all, {1, nullptr});
  std::vector<double> reported;
  const auto many = ComputeQuality(mesh, all, {7, [&reported](double f) { reported.push_back(f); }});
  ASSERT_EQ(one.size(), many.size());
  for (std::size_t m = 0; m < one.size(); ++m)
    EXPECT_EQ(0, std::memcmp(one[m].data(), many[m].data(), one[m].size() * sizeof(double))) << MeasureName(all[m]);
  // Progress is reported, never decreases, and ends at 1.
  ASSERT_FALSE(reported.empty());
  EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
  EXPECT_EQ(reported.back(), 1.0);
  // And each value is the single-element function's.
  for (std::size_t e = 0; e < mesh.elements.size(); e += 97)
    EXPECT_TRUE(SameQuality(one[1][e], ElementQuality(mesh, e, all[1])));
}

TEST(QualityMesh, CornerJacobiansPerElementType)
{
  const FEMesh mesh = MixedMesh(10, 5u);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
  {
    const Element& el = mesh.elements[e];
    const auto corners = CornerJacobians(mesh, e);
    ASSERT_EQ(corners.size(), el.type == ElementType::Cable ? 0u : static_cast<std::size_t>(NodeCount(el.type)));
    if (el.type == ElementType::Tetrahedron)
    {
      TetNodes p;
      for (int i = 0; i < 4; ++i)
        p[i] = mesh.nodes[el.nodes[i]];
      for (double c : corners)
        EXPECT_NEAR(c, 6 * TetVolume(p), 1e-12 * std::max(1.0, std::abs(c)));
    }
    if (el.type == ElementType::Wedge)
    {
      WedgeNodes p;
      for (int i = 0; i < 6; ++i)
        p[i] = mesh.nodes[el.nodes[i]];
      const auto expected = WedgeCornerJacobians(p);
      EXPECT_TRUE(std::equal(corners.begin(), corners.end(), expected.begin()));
    }
    if (el.type == ElementType::Hexahedron)
    {
      HexNodes p;
      for (int i = 0; i < 8; ++i)
        p[i] = mesh.nodes[el.nodes[i]];
      const auto expected = HexCornerJacobians(p);
      EXPECT_TRUE(std::equal(corners.begin(), corners.end(), expected.begin()));
    }
  }
}

TEST(QualityMesh, SummaryCountsAndStatistics)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> values = {0.9, 0.2, nan, -0.5, kVerdictMax, 0.3, 1.0};
  const std::vector<double> jacobians = {2.0, 0.1, nan, -1.0, 0.0, 0.5, 3.0};
  const QualitySummary s = Summarize(values, jacobians, 0.3);
  EXPECT_EQ(s.count, 6u);          // NaN (cable) skipped
  EXPECT_EQ(s.degenerate, 1u);     // the 1e30 flag
  EXPECT_EQ(s.belowThreshold, 3u); // 0.2, -0.5 and the degenerate one; 0.3 is not below 0.3
  EXPECT_EQ(s.inverted, 1u);
  EXPECT_DOUBLE_EQ(s.min, -0.5);
  EXPECT_DOUBLE_EQ(s.max, 1.0);
  EXPECT_DOUBLE_EQ(s.mean, (0.9 + 0.2 - 0.5 + 0.3 + 1.0) / 5);

  const QualitySummary empty = Summarize({}, {}, 0.3);
  EXPECT_EQ(empty.count, 0u);
  EXPECT_TRUE(std::isnan(empty.min) && std::isnan(empty.mean) && std::isnan(empty.max));
  EXPECT_THROW(Summarize({1.0}, {}, 0.3), std::invalid_argument);
}

TEST(QualityMesh, ScaledJacobianSummaryMatchesBruteForce)
{
  const FEMesh mesh = MixedMesh(100, 77u);
  const QualitySummary s = SummarizeScaledJacobian(mesh, 0.3);
  std::size_t count = 0, below = 0, inverted = 0, degenerate = 0;
  double minimum = 1e300, sum = 0;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
  {
    if (mesh.elements[e].type == ElementType::Cable)
      continue;
    ++count;
    const double v = ElementQuality(mesh, e, Measure::ScaledJacobian);
    const auto corners = CornerJacobians(mesh, e);
    // Inverted: some corner (or, for hexes, the centre) has a negative determinant.
    bool negative = *std::min_element(corners.begin(), corners.end()) < 0;
    if (mesh.elements[e].type == ElementType::Hexahedron)
    {
      HexNodes p;
      for (int i = 0; i < 8; ++i)
        p[i] = mesh.nodes[mesh.elements[e].nodes[i]];
      negative = negative || HexCenterJacobian(p) < 0;
    }
    inverted += negative;
    if (std::abs(v) >= 1e30)
    {
      ++degenerate;
      ++below;
      continue;
    }
    below += v < 0.3;
    minimum = std::min(minimum, v);
    sum += v;
  }
  EXPECT_EQ(s.count, count);
  EXPECT_EQ(s.belowThreshold, below);
  EXPECT_EQ(s.inverted, inverted);
  EXPECT_EQ(s.degenerate, degenerate);
  EXPECT_GT(s.inverted, 10u);
  EXPECT_DOUBLE_EQ(s.min, minimum);
  EXPECT_DOUBLE_EQ(s.mean, sum / static_cast<double>(count - degenerate));
}

TEST(QualityMesh, BadNodeIndexThrowsNamingTheElement)
{
  FEMesh mesh = MixedMesh(2, 1u);
  mesh.elements[3].nodes[1] = static_cast<std::int32_t>(mesh.nodes.size()) + 5;
  try
  {
    ComputeQuality(mesh, Measure::ScaledJacobian);
    FAIL() << "expected an exception";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("element 3"), std::string::npos) << e.what();
  }
}

TEST(QualityMesh, EmptyMeshGivesEmptyResults)
{
  FEMesh mesh;
  EXPECT_TRUE(ComputeQuality(mesh, Measure::Shape).empty());
  const QualitySummary s = SummarizeScaledJacobian(mesh, 0.3);
  EXPECT_EQ(s.count, 0u);
}
} // namespace
} // namespace mmrep::quality::test
