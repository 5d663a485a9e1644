// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Mesh repair on the shell atlas stand-in and its generated tangles; quality is checked
// independently with vtkMeshQuality, surface distances with brute force over the triangles.
#include "mmrepFEMeshIO.h"
#include "mmrepMeshQuality.h"
#include "mmrepMeshRepair.h"
#include "mmrepSurfaceDistance.h"
#include "mmrepSurfaceProjector.h"
#include "mmrepTangledMeshGenerator.h"

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkMeshQuality.h>
#include <vtkNew.h>
#include <vtkTriangle.h>
#include <vtkUnstructuredGrid.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstring>
#include <limits>

namespace
{
using namespace mmrep;
using mmrep::testing::MakeShellAtlas;
using mmrep::testing::ShellAtlas;
using mmrep::testing::Tangle;
using mmrep::testing::TangleOptions;

const ShellAtlas& Atlas()
{
  static const ShellAtlas atlas = MakeShellAtlas();
  return atlas;
}

RepairOptions WithSurfaces(const ShellAtlas& atlas, bool symmetric)
{
  RepairOptions o;
  o.skinSurface = atlas.skin;
  o.skullSurface = atlas.skull;
  o.hasSymmetryPlane = symmetric;
  return o;
}

// Scaled Jacobian per cell from VTK's own filter (independent of mmrep::quality).
std::vector<double> VTKScaledJacobian(const FEMesh& mesh)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = ToVTK(mesh);
  vtkNew<vtkMeshQuality> filter;
  filter->SetInputData(grid);
  filter->SetHexQualityMeasureToScaledJacobian();
  filter->SetTetQualityMeasureToScaledJacobian();
  filter->Update();
  vtkDataArray* q = filter->GetOutput()->GetCellData()->GetArray("Quality");
  std::vector<double> v(static_cast<std::size_t>(q->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < q->GetNumberOfTuples(); ++i)
    v[static_cast<std::size_t>(i)] = q->GetTuple1(i);
  return v;
}

// Distance to the closest triangle by brute force over every triangle (vtkTriangle::EvaluatePosition).
double BruteForceDistance(vtkPolyData* surface, const Point3& p)
{
  double best = std::numeric_limits<double>::infinity();
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    double a[3], b[3], d[3];
    surface->GetPoint(ids->GetId(0), a);
    surface->GetPoint(ids->GetId(1), b);
    surface->GetPoint(ids->GetId(2), d);
    // Cheap reject: farther than the best from the triangle's first vertex by more than its size.
    const double size =
      std::sqrt(vtkMath::Distance2BetweenPoints(a, b)) + std::sqrt(vtkMath::Distance2BetweenPoints(a, d));
    if (std::sqrt(vtkMath::Distance2BetweenPoints(a, p.data())) - size > best)
      continue;
    double closest[3], pcoords[3], weights[3], d2 = 0;
    int subId = 0;
    surface->GetCell(c)->EvaluatePosition(p.data(), closest, subId, pcoords, d2, weights);
    best = std::min(best, std::sqrt(d2));
  }
  return best;
}

bool SameBits(const FEMesh& a, const FEMesh& b)
{
  if (a.nodes.size() != b.nodes.size())
    return false;
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    if (std::memcmp(a.nodes[i].data(), b.nodes[i].data(), 3 * sizeof(double)) != 0)
      return false;
  return true;
}

// Largest distance between a node's mirror image and its partner, over the mesh size.
double SymmetryError(const FEMesh& mesh, const Plane& plane, const std::vector<std::int32_t>& partner)
{
  Eigen::AlignedBox3d box;
  for (const auto& p : mesh.nodes)
    box.extend(p);
  double worst = 0;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    worst = std::max(worst, (plane.Mirror(mesh.nodes[i]) - mesh.nodes[partner[i]]).norm());
  return worst / box.diagonal().norm();
}

std::vector<std::int32_t> GridPartners(const ShellAtlas& atlas)
{
  std::vector<std::int32_t> partner(atlas.grid.size());
  const int columns = atlas.options.columns, rows = atlas.options.rows;
  for (std::size_t i = 0; i < atlas.grid.size(); ++i)
  {
    const Eigen::Vector3i c = atlas.grid[i];
    partner[i] = (c.z() * (rows + 1) + c.y()) * (columns + 1) + (-c.x() + columns / 2);
  }
  return partner;
}
} // namespace

TEST(RepairGenerator, AtlasIsValidSymmetricAndOnItsSurfaces)
{
  const ShellAtlas& atlas = Atlas();
  EXPECT_EQ(atlas.mesh.elements.size(), 24u * 20u * 3u);
  const std::vector<double> sj = VTKScaledJacobian(atlas.mesh);
  EXPECT_GT(*std::min_element(sj.begin(), sj.end()), 0.8);
  EXPECT_EQ(SymmetryError(atlas.mesh, Plane{}, GridPartners(atlas)), 0.0);
  for (const char* set : {"skin", "skull", "lips", "midsagittal"})
    EXPECT_FALSE(atlas.mesh.nodeSets.at(set).empty()) << set;
  // Mesh nodes are surface vertices: distance 0 by brute force; skull nodes lie on the skull.
  for (const auto id : atlas.mesh.nodeSets.at("skin"))
    ASSERT_LT(BruteForceDistance(atlas.skin, atlas.mesh.nodes[id]), 1e-9);
  for (const auto id : atlas.mesh.nodeSets.at("skull"))
    ASSERT_LT(BruteForceDistance(atlas.skull, atlas.mesh.nodes[id]), 1e-9);
  for (const auto id : atlas.mesh.nodeSets.at("midsagittal"))
    ASSERT_EQ(atlas.mesh.nodes[id].x(), 0.0);
  // The tangles really tangle.
  TangleOptions fold;
  fold.noise = 0, fold.folds = 3, fold.seed = 7;
  const FEMesh folded = Tangle(atlas, fold);
  const std::vector<double> foldedSJ = VTKScaledJacobian(folded);
  EXPECT_LT(*std::min_element(foldedSJ.begin(), foldedSJ.end()), 0.0);
}

TEST(RepairMesh, ValidMeshUnchangedBitForBit)
{
  const ShellAtlas& atlas = Atlas();
  TangleOptions mild;
  mild.noise = 0.03, mild.folds = 0, mild.seed = 3;
  const FEMesh input = Tangle(atlas, mild);
  FEMesh mesh = input;
  const RepairReport report = RepairMesh(mesh, WithSurfaces(atlas, false));
  EXPECT_TRUE(report.success);
  EXPECT_EQ(report.movedNodes, 0u);
  EXPECT_EQ(report.belowThresholdBefore, 0u);
  EXPECT_TRUE(SameBits(mesh, input));
  const auto before = quality::ComputeQuality(input, quality::Measure::ScaledJacobian);
  const auto after = quality::ComputeQuality(mesh, quality::Measure::ScaledJacobian);
  EXPECT_EQ(std::memcmp(before.data(), after.data(), before.size() * sizeof(double)), 0);
  EXPECT_EQ(report.minScaledJacobianBefore, report.minScaledJacobianAfter);
}

TEST(RepairMesh, RandomTanglesRepaired)
{
  const ShellAtlas& atlas = Atlas();
  const int cases = 100;
  int repaired = 0, tangled = 0;
  std::size_t movedSurface = 0;
  for (int c = 1; c <= cases; ++c)
  {
    const TangleOptions t = mmrep::testing::RandomTangle(static_cast<std::uint32_t>(c));
    FEMesh mesh = Tangle(atlas, t);
    const RepairReport report = RepairMesh(mesh, WithSurfaces(atlas, t.symmetric));
    tangled += report.invertedBefore > 0 ? 1 : 0;
    movedSurface += report.movedSurfaceNodes;
    // Independent check of the claim with VTK's quality filter.
    const std::vector<double> sj = VTKScaledJacobian(mesh);
    const double minimum = *std::min_element(sj.begin(), sj.end());
    const bool ok = minimum >= 0.3;
    EXPECT_EQ(report.success, ok) << "case " << c;
    if (ok)
      ++repaired;
    else
      std::printf("case %d not repaired: min scaled Jacobian %g\n", c, minimum);
  }
  const double rate = double(repaired) / cases;
  std::printf("repaired %d of %d tangled shells (rate %.3f, %d with inverted elements before)\n", repaired, cases, rate,
              tangled);
  RecordProperty("RepairRate", std::to_string(rate));
  EXPECT_GE(rate, 0.99);
  EXPECT_GE(tangled, cases / 2); // the cases are hard: most start with inverted elements
  EXPECT_GT(movedSurface, 0u);   // and need surface nodes to slide
}

TEST(RepairMesh, SurfaceNodesStayOnSurfacesAndLipsKeepAccuracy)
{
  const ShellAtlas& atlas = Atlas();
  std::size_t movedSkin = 0, movedSkull = 0, movedLips = 0;
  for (std::uint32_t seed = 1; seed <= 6; ++seed)
  {
    TangleOptions t;
    t.seed = seed, t.noise = 0.15, t.folds = 4, t.warp = 1, t.symmetric = seed % 2 == 0;
    const FEMesh input = Tangle(atlas, t);
    FEMesh mesh = input;
    const RepairReport report = RepairMesh(mesh, WithSurfaces(atlas, t.symmetric));
    ASSERT_TRUE(report.success) << "seed " << seed;
    for (const auto& [set, surface] :
         {std::pair<std::string, vtkPolyData*>{"skin", atlas.skin.Get()}, {"skull", atlas.skull.Get()}})
      for (const auto id : mesh.nodeSets.at(set))
      {
        if (mesh.nodes[id] == input.nodes[id])
          continue;
        (set == "skin" ? movedSkin : movedSkull)++;
        ASSERT_LT(BruteForceDistance(surface, mesh.nodes[id]), 1e-6) << set << " node " << id << " seed " << seed;
      }
    double lipsBefore = 0, lipsAfter = 0;
    for (const auto id : mesh.nodeSets.at("lips"))
    {
      lipsBefore = std::max(lipsBefore, BruteForceDistance(atlas.skin, input.nodes[id]));
      lipsAfter = std::max(lipsAfter, BruteForceDistance(atlas.skin, mesh.nodes[id]));
      movedLips += mesh.nodes[id] != input.nodes[id] ? 1 : 0;
    }
    EXPECT_LE(lipsAfter - lipsBefore, 0.05) << "seed " << seed;
    const SurfaceDistance measured = MeasureSurfaceDistance(mesh, "lips", atlas.skin);
    EXPECT_NEAR(measured.max, lipsAfter, 1e-9);
  }
  EXPECT_GT(movedSkin, 0u);
  EXPECT_GT(movedSkull, 0u);
  std::printf("moved surface nodes: skin %zu, skull %zu, lips %zu\n", movedSkin, movedSkull, movedLips);
}

TEST(RepairMesh, SymmetricInputStaysSymmetric)
{
  const ShellAtlas& atlas = Atlas();
  const std::vector<std::int32_t> partner = GridPartners(atlas);
  // A general plane too: the whole model rotated and shifted, mirror images then carry rounding.
  const Eigen::Isometry3d pose =
    Eigen::Translation3d(12, -5, 30) * Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.3, 1, 0.2).normalized());
  for (const bool rotated : {false, true})
    for (std::uint32_t seed = 2; seed <= 8; seed += 2)
    {
      TangleOptions t;
      t.seed = seed, t.symmetric = true, t.noise = 0.15, t.folds = 3, t.warp = 1;
      FEMesh mesh = Tangle(atlas, t);
      RepairOptions o = WithSurfaces(atlas, true);
      vtkNew<vtkPolyData> skin, skull;
      if (rotated)
      {
        for (auto& p : mesh.nodes)
          p = pose * p;
        o.symmetryPlane.point = pose.translation();
        o.symmetryPlane.normal = pose.linear() * Eigen::Vector3d::UnitX();
        for (auto [from, to] : {std::pair{atlas.skin.Get(), skin.Get()}, std::pair{atlas.skull.Get(), skull.Get()}})
        {
          to->DeepCopy(from);
          for (vtkIdType i = 0; i < to->GetNumberOfPoints(); ++i)
          {
            Eigen::Vector3d p;
            to->GetPoint(i, p.data());
            p = pose * p;
            to->GetPoints()->SetPoint(i, p.data());
          }
        }
        o.skinSurface = skin, o.skullSurface = skull;
      }
      const double errorBefore = SymmetryError(mesh, o.symmetryPlane, partner);
      ASSERT_LT(errorBefore, 1e-12);
      const RepairReport report = RepairMesh(mesh, o);
      EXPECT_TRUE(report.success) << "seed " << seed;
      EXPECT_TRUE(report.symmetricPairs);
      EXPECT_GT(report.movedNodes, 0u);
      EXPECT_LT(SymmetryError(mesh, o.symmetryPlane, partner), 1e-9) << "seed " << seed << " rotated " << rotated;
      for (const auto id : mesh.nodeSets.at("midsagittal"))
        ASSERT_LT(std::abs(o.symmetryPlane.SignedDistance(mesh.nodes[id])), 1e-9);
    }
}

// Tangled inputs can hold coincident nodes (two skin nodes projected onto the same surface point):
// the mirror partner of such a node is ambiguous by position alone, and the repair must still
// find the mirror pairs (by their neighbourhoods) and keep the mesh symmetric.
TEST(RepairMesh, SymmetricInputWithCoincidentNodesStaysSymmetric)
{
  const ShellAtlas& atlas = Atlas();
  const std::vector<std::int32_t> partner = GridPartners(atlas);
  TangleOptions t;
  t.seed = 4, t.symmetric = true, t.noise = 0.15, t.folds = 3, t.warp = 1;
  FEMesh mesh = Tangle(atlas, t);
  const auto& skin = mesh.nodeSets.at("skin");
  std::size_t pairs = 0;
  for (const auto a : skin)
  {
    const Eigen::Vector3i c = atlas.grid[static_cast<std::size_t>(a)];
    if (c.x() != 3 || c.y() % 6 != 3)
      continue;
    const auto b = std::find_if(skin.begin(), skin.end(), [&](std::int32_t n) {
      return atlas.grid[static_cast<std::size_t>(n)] == Eigen::Vector3i(4, c.y(), c.z());
    });
    ASSERT_NE(b, skin.end());
    mesh.nodes[static_cast<std::size_t>(*b)] = mesh.nodes[static_cast<std::size_t>(a)];
    mesh.nodes[static_cast<std::size_t>(partner[*b])] = mesh.nodes[static_cast<std::size_t>(partner[a])];
    ++pairs;
  }
  ASSERT_GE(pairs, 2u);
  ASSERT_LT(SymmetryError(mesh, Plane{}, partner), 1e-12);
  const RepairReport report = RepairMesh(mesh, WithSurfaces(atlas, true));
  EXPECT_TRUE(report.symmetricPairs);
  EXPECT_LT(SymmetryError(mesh, Plane{}, partner), 1e-9);
}

TEST(RepairMesh, HopelessElementFailsAndIsListed)
{
  const ShellAtlas& atlas = Atlas();
  FEMesh mesh = atlas.mesh;
  // All 8 nodes of an epidermis element on one skin point and bound to the skin: never valid again.
  const std::size_t collapsed = 250;
  const Point3 onSkin = mesh.nodes[mesh.elements[collapsed].nodes[0]];
  auto& skin = mesh.nodeSets["skin"];
  for (int k = 0; k < 8; ++k)
  {
    mesh.nodes[mesh.elements[collapsed].nodes[k]] = onSkin;
    skin.push_back(mesh.elements[collapsed].nodes[k]);
  }
  const RepairReport report = RepairMesh(mesh, WithSurfaces(atlas, false));
  EXPECT_FALSE(report.success);
  ASSERT_FALSE(report.failedElements.empty());
  EXPECT_NE(std::find(report.failedElements.begin(), report.failedElements.end(), collapsed),
            report.failedElements.end());
  EXPECT_EQ(report.failedElements.size(), report.belowThresholdAfter);
  EXPECT_TRUE(std::is_sorted(report.failedValues.begin(), report.failedValues.end()));
  // Listed values are the elements' scaled Jacobians (VTK), degenerate ones as -infinity.
  const std::vector<double> sj = VTKScaledJacobian(mesh);
  for (std::size_t k = 0; k < report.failedElements.size(); ++k)
  {
    const double v = sj[report.failedElements[k]];
    if (std::abs(v) >= 1e28)
      EXPECT_TRUE(std::isinf(report.failedValues[k]));
    else
      EXPECT_EQ(report.failedValues[k], v);
  }
}

TEST(RepairMesh, QualityAfterRepairEqualsVTKMeshQuality)
{
  const ShellAtlas& atlas = Atlas();
  TangleOptions t;
  t.seed = 21, t.noise = 0.18, t.folds = 4, t.warp = 1;
  FEMesh mesh = Tangle(atlas, t);
  const std::vector<double> vtkBefore = VTKScaledJacobian(mesh);
  const RepairReport report = RepairMesh(mesh, WithSurfaces(atlas, false));
  ASSERT_TRUE(report.success);
  const std::vector<double> vtkAfter = VTKScaledJacobian(mesh);
  const std::vector<double> ours = quality::ComputeQuality(mesh, quality::Measure::ScaledJacobian);
  ASSERT_EQ(ours.size(), vtkAfter.size());
  for (std::size_t e = 0; e < ours.size(); ++e)
    ASSERT_NEAR(ours[e], vtkAfter[e], 1e-12) << e;
  EXPECT_EQ(report.minScaledJacobianAfter, *std::min_element(ours.begin(), ours.end()));
  EXPECT_NEAR(report.minScaledJacobianAfter, *std::min_element(vtkAfter.begin(), vtkAfter.end()), 1e-12);
  EXPECT_NEAR(report.minScaledJacobianBefore, *std::min_element(vtkBefore.begin(), vtkBefore.end()), 1e-12);
  EXPECT_EQ(report.belowThresholdBefore,
            std::size_t(std::count_if(vtkBefore.begin(), vtkBefore.end(), [](double v) { return v < 0.3; })));
  EXPECT_EQ(report.invertedBefore,
            std::size_t(std::count_if(vtkBefore.begin(), vtkBefore.end(), [](double v) { return v < 0; })));
  EXPECT_GE(*std::min_element(vtkAfter.begin(), vtkAfter.end()), 0.3);
}

TEST(RepairMesh, OwnBoundaryWithoutSurfacesAndDeterministic)
{
  const ShellAtlas& atlas = Atlas();
  TangleOptions t;
  t.seed = 6, t.noise = 0.15, t.folds = 3, t.warp = 1, t.symmetric = true; // mid-sagittal nodes stay at x = 0
  const FEMesh input = Tangle(atlas, t);
  FEMesh first = input, second = input;
  const RepairReport a = RepairMesh(first, RepairOptions{});
  const RepairReport b = RepairMesh(second, RepairOptions{});
  EXPECT_TRUE(a.success);
  EXPECT_TRUE(SameBits(first, second));
  EXPECT_EQ(a.movedNodes, b.movedNodes);
  // Moved skin nodes lie on the input mesh's own outer boundary (its skin faces).
  std::vector<char> mask(input.nodes.size(), 0);
  for (const auto id : input.nodeSets.at("skin"))
    mask[id] = 1;
  vtkSmartPointer<vtkPolyData> boundary = BoundarySurface(input, &mask);
  ASSERT_EQ(boundary->GetNumberOfCells(), 2 * 24 * 20);
  std::size_t moved = 0;
  for (const auto id : input.nodeSets.at("skin"))
    if (first.nodes[id] != input.nodes[id])
    {
      ++moved;
      ASSERT_LT(BruteForceDistance(boundary, first.nodes[id]), 1e-9);
    }
  EXPECT_GT(moved, 0u);
  // Mid-sagittal nodes (coplanar, x = 0) stay on their plane without a symmetry plane given.
  for (const auto id : input.nodeSets.at("midsagittal"))
    ASSERT_LT(std::abs(first.nodes[id].x()), 1e-9);
}

TEST(RepairMesh, WedgeMeshRepaired)
{
  // Each hexahedron split into two VTK wedges (triangle 0-1-2 facing away from 3-4-5).
  const ShellAtlas& atlas = Atlas();
  TangleOptions t;
  t.seed = 9, t.noise = 0.15, t.folds = 3;
  FEMesh hexes = Tangle(atlas, t);
  FEMesh mesh = hexes;
  mesh.elements.clear();
  for (const Element& h : hexes.elements)
    for (const std::array<int, 6> w : {std::array<int, 6>{0, 3, 1, 4, 7, 5}, std::array<int, 6>{1, 3, 2, 5, 7, 6}})
    {
      Element e;
      e.type = ElementType::Wedge;
      e.layer = h.layer;
      for (int k = 0; k < 6; ++k)
        e.nodes[k] = h.nodes[w[k]];
      mesh.elements.push_back(e);
    }
  mesh.UpdateLayerSets();
  FEMesh clean = mesh;
  clean.nodes = atlas.mesh.nodes;
  for (std::size_t e = 0; e < clean.elements.size(); ++e)
  {
    const auto corners = quality::CornerJacobians(clean, e);
    ASSERT_GT(*std::min_element(corners.begin(), corners.end()), 0) << e;
  }
  const RepairReport report = RepairMesh(mesh, WithSurfaces(atlas, false));
  EXPECT_GT(report.invertedBefore, 0u);
  EXPECT_TRUE(report.success);
  const auto sj = quality::ComputeQuality(mesh, quality::Measure::ScaledJacobian);
  EXPECT_GE(*std::min_element(sj.begin(), sj.end()), 0.3);
}

TEST(RepairMesh, InvalidInputsThrow)
{
  FEMesh empty;
  EXPECT_THROW(RepairMesh(empty, RepairOptions{}), std::invalid_argument);
  FEMesh mesh = Atlas().mesh;
  RepairOptions o;
  o.scaledJacobianThreshold = 1.5;
  EXPECT_THROW(RepairMesh(mesh, o), std::invalid_argument);
  vtkNew<vtkPolyData> nothing;
  RepairOptions s;
  s.skinSurface = nothing;
  EXPECT_THROW(RepairMesh(mesh, s), std::invalid_argument);
  FEMesh bad = Atlas().mesh;
  bad.elements[0].nodes[0] = 1 << 30;
  EXPECT_THROW(RepairMesh(bad, RepairOptions{}), std::invalid_argument);
}
