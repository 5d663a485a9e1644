// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The foldover-free untangling (mmrepFoldoverFreeUntangling.h): its Jacobian frames against the
// quality library's corner Jacobians (Verdict's conventions), its energy against a closed form and
// its gradient against finite differences, and tangles that node-by-node moves cannot undo.
#include "mmrepAtlasTangles.h"
#include "mmrepFoldoverFreeEnergy.h"
#include "mmrepHexQuality.h"
#include "mmrepMeshQuality.h"
#include "mmrepMeshRepair.h"
#include "mmrepSurfaceDistance.h"
#include "mmrepTangledMeshGenerator.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace
{
using namespace mmrep;

const mmrep::testing::ShellAtlas& Shell()
{
  static const mmrep::testing::ShellAtlas atlas = mmrep::testing::MakeShellAtlas();
  return atlas;
}

std::vector<JacobianFrame> AllFrames(const FEMesh& mesh)
{
  std::vector<JacobianFrame> frames;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    AppendJacobianFrames(mesh, e, frames);
  return frames;
}

// Every corner frame has the sign of the quality library's corner Jacobian at the same node, and the
// ratio of the two is the same at every corner of an element (one reference shape per element);
// the hexahedron's centre frame is Verdict's centre Jacobian at that ratio too.
void ExpectFramesMatchCornerJacobians(const FEMesh& mesh)
{
  const std::vector<Point3>& x = mesh.nodes;
  const std::vector<JacobianFrame> frames = AllFrames(mesh);
  std::size_t f = 0, negative = 0;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
  {
    const std::vector<double> corners = quality::CornerJacobians(mesh, e);
    if (corners.empty())
      continue;
    const std::size_t count = mesh.elements[e].type == ElementType::Tetrahedron ? 1 : corners.size();
    // The ratio from the corner farthest from 0 (the others may be nearly degenerate).
    std::size_t largest = 0;
    for (std::size_t k = 1; k < corners.size(); ++k)
      largest = std::abs(corners[k]) > std::abs(corners[largest]) ? k : largest;
    const double ratio = FrameJacobian(frames[f + (count == 1 ? 0 : largest)], x).determinant() / corners[largest];
    ASSERT_GT(ratio, 0) << "element " << e;
    for (std::size_t k = 0; k < count; ++k, ++f)
    {
      ASSERT_EQ(frames[f].element, e);
      const double det = FrameJacobian(frames[f], x).determinant();
      negative += det <= 0 ? 1 : 0;
      ASSERT_NEAR(det / ratio, corners[k], 1e-9 * std::abs(corners[largest])) << "element " << e << " corner " << k;
    }
    if (mesh.elements[e].type == ElementType::Hexahedron)
    {
      ASSERT_FALSE(frames[f].corner);
      quality::HexNodes p;
      for (int k = 0; k < 8; ++k)
        p[k] = mesh.nodes[mesh.elements[e].nodes[k]];
      const double centre = quality::HexCenterJacobian(p);
      ASSERT_NEAR(FrameJacobian(frames[f], x).determinant() / ratio, centre, 1e-9 * std::abs(corners[largest]))
        << "element " << e;
      ++f;
    }
  }
  EXPECT_EQ(f, frames.size());
  ::testing::Test::RecordProperty("NegativeFrames", std::to_string(negative));
}
} // namespace

TEST(FoldoverFrames, MatchCornerJacobiansOnTheAtlasAndItsTangles)
{
  const auto& c = mmrep::testing::ShippedAtlasTangleContext();
  ExpectFramesMatchCornerJacobians(c.mesh);
  const FEMesh tangled = mmrep::testing::TangleMesh(c, mmrep::testing::RandomTangle(3, 0.3));
  std::size_t inverted = 0;
  for (std::size_t e = 0; e < tangled.elements.size(); ++e)
  {
    const std::vector<double> corners = quality::CornerJacobians(tangled, e);
    inverted += !corners.empty() && *std::min_element(corners.begin(), corners.end()) <= 0 ? 1 : 0;
  }
  EXPECT_GT(inverted, 100u) << "the tangle must contain inverted corners";
  ExpectFramesMatchCornerJacobians(tangled);
  ExpectFramesMatchCornerJacobians(Shell().mesh);
}

// The ideal element (the reference box itself): det J = 1, |J|^2 = 3 at all nine frames, so
// E = (a b c / 9) x 9 x ((1 - theta) 3 / chi^(2/3) + theta 2 / chi) with chi = (1 + sqrt(1 + eps^2)) / 2.
TEST(FoldoverEnergy, IdealBoxHasClosedFormEnergy)
{
  FEMesh box;
  const double a = 2, b = 3, c = 5;
  for (int k = 0; k < 8; ++k)
  {
    const int sx = (k == 1 || k == 2 || k == 5 || k == 6), sy = (k == 2 || k == 3 || k == 6 || k == 7), sz = k >= 4;
    box.nodes.emplace_back(a * sx, b * sy, c * sz);
  }
  Element hex;
  hex.type = ElementType::Hexahedron;
  for (int k = 0; k < 8; ++k)
    hex.nodes[k] = k;
  box.elements.push_back(hex);
  const FoldoverFreeEnergy energy(AllFrames(box), 0.25);
  ASSERT_EQ(energy.Frames().size(), 9u);
  for (const double eps : {1e-8, 0.5})
  {
    const double chi = (1 + std::sqrt(1 + eps * eps)) / 2;
    EXPECT_NEAR(energy.Evaluate(box.nodes, eps), a * b * c * (0.75 * 3 / std::cbrt(chi * chi) + 0.25 * 2 / chi), 1e-9);
  }
  EXPECT_NEAR(energy.MinimumDeterminant(box.nodes), 1.0, 1e-12);
  EXPECT_NEAR(FoldoverChi(0.1, -3.0), (-3.0 + std::sqrt(0.01 + 9.0)) / 2, 1e-15);
  EXPECT_NEAR(FoldoverChiDerivative(0.1, -3.0), (1 - 3.0 / std::sqrt(0.01 + 9.0)) / 2, 1e-12);
}

TEST(FoldoverEnergy, GradientMatchesFiniteDifferences)
{
  mmrep::testing::TangleOptions t;
  t.seed = 5, t.noise = 0.3, t.folds = 3;
  const FEMesh mesh = mmrep::testing::Tangle(Shell(), t);
  const std::vector<JacobianFrame> frames = AllFrames(mesh);
  const FoldoverFreeEnergy energy(frames);
  ASSERT_FALSE(energy.InvertedElements(mesh.nodes).empty());
  for (const double eps : {1.0, 0.05})
  {
    std::vector<Point3> gradient(mesh.nodes.size(), Point3::Zero());
    energy.Evaluate(mesh.nodes, eps, &gradient);
    for (std::size_t n = 7; n < mesh.nodes.size(); n += 97)
    {
      // The differences of the frames at node n only (the whole mesh's sum would drown them in rounding).
      std::vector<JacobianFrame> around;
      for (const JacobianFrame& frame : frames)
        if (std::find(frame.nodes.begin(), frame.nodes.begin() + frame.count, static_cast<std::int32_t>(n)) !=
            frame.nodes.begin() + frame.count)
          around.push_back(frame);
      const FoldoverFreeEnergy local(around);
      for (int d = 0; d < 3; ++d)
      {
        // Richardson extrapolation of two central differences (error O(h^4)).
        const auto central = [&](double h) {
          std::vector<Point3> plus = mesh.nodes, minus = mesh.nodes;
          plus[n][d] += h, minus[n][d] -= h;
          return (local.Evaluate(plus, eps) - local.Evaluate(minus, eps)) / (2 * h);
        };
        const double numeric = (4 * central(1e-4) - central(2e-4)) / 3;
        ASSERT_NEAR(gradient[n][d], numeric, 1e-7 * (1 + std::abs(numeric))) << "node " << n << " axis " << d;
      }
    }
  }
}
TEST(FoldoverEnergy, SameBitsOnAnyNumberOfThreads)
{
  const FEMesh mesh = mmrep::testing::Tangle(Shell(), mmrep::testing::RandomTangle(4, 0.3));
  const FoldoverFreeEnergy energy(AllFrames(mesh));
  ASSERT_GT(energy.Frames().size(), 4 * 2048u) << "the frames must span several chunks";
  std::vector<std::vector<Point3>> gradients;
  std::vector<double> values;
  for (const char* threads : {"1", "2", "5"})
  {
    setenv("ITK_GLOBAL_DEFAULT_NUMBER_OF_THREADS", threads, 1);
    gradients.emplace_back(mesh.nodes.size(), Point3::Zero());
    values.push_back(energy.Evaluate(mesh.nodes, 0.1, &gradients.back()));
  }
  unsetenv("ITK_GLOBAL_DEFAULT_NUMBER_OF_THREADS");
  for (std::size_t k = 1; k < values.size(); ++k)
  {
    EXPECT_EQ(std::memcmp(&values[k], &values[0], sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(gradients[k].data(), gradients[0].data(), gradients[0].size() * sizeof(Point3)), 0);
  }
}

namespace
{
std::size_t ShellNode(int column, int row, int level)
{
  const auto& grid = Shell().grid;
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (grid[i] == Eigen::Vector3i(column, row, level))
      return i;
  throw std::out_of_range("no such shell node");
}

RepairOptions ShellRepairOptions(bool global)
{
  RepairOptions o;
  o.skinSurface = Shell().skin;
  o.skullSurface = Shell().skull;
  o.globalUntangling = global;
  return o;
}

// A block of 2 x 2 x 2 inner nodes (both inner node levels, columns c..c+1, rows 9..10) turned by
// 180 degrees about its axis: each node sits where its opposite was, all twelve elements around the
// block are inverted, and any single node moved back alone lands among crossed neighbours. With
// `symmetric`, the mirror block (columns -c-1..-c) is turned too and the plane is given.
FEMesh TurnedBlock(int c, bool symmetric)
{
  FEMesh mesh = Shell().mesh;
  for (const int side : symmetric ? std::vector<int>{1, -1} : std::vector<int>{1})
    for (int col = c; col <= c + 1; ++col)
      for (int row = 9; row <= 10; ++row)
        for (int level = 1; level <= 2; ++level)
          mesh.nodes[ShellNode(side * col, row, level)] =
            Shell().mesh.nodes[ShellNode(side * (2 * c + 1 - col), 19 - row, level)];
  return mesh;
}

double ShellSymmetryError(const FEMesh& mesh)
{
  double worst = 0;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
  {
    const Eigen::Vector3i g = Shell().grid[i];
    const Point3& p = mesh.nodes[ShellNode(-g.x(), g.y(), g.z())];
    worst = std::max(worst, (mesh.nodes[i] - Point3(-p.x(), p.y(), p.z())).norm());
  }
  return worst;
}
} // namespace

TEST(Untangling, TurnedBlockNeedsAllNodesAtOnce)
{
  for (const bool symmetric : {false, true})
  {
    SCOPED_TRACE(symmetric ? "symmetric" : "one side");
    const FEMesh input = TurnedBlock(3, symmetric);
    RepairOptions options = ShellRepairOptions(false);
    options.hasSymmetryPlane = symmetric;
    FEMesh nodeByNode = input;
    const RepairReport alone = RepairMesh(nodeByNode, options);
    EXPECT_GT(alone.invertedBefore, 0u);
    EXPECT_FALSE(alone.success) << "the case must be beyond node-by-node moves";

    options.globalUntangling = true;
    std::vector<double> fractions;
    options.progress = [&](double f) { fractions.push_back(f); };
    FEMesh mesh = input;
    const RepairReport report = RepairMesh(mesh, options);
    EXPECT_TRUE(report.success);
    // Progress through the untangling (the first half) and on to 1, never backwards.
    ASSERT_FALSE(fractions.empty());
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_GT(std::count_if(fractions.begin(), fractions.end(), [](double f) { return f > 0 && f <= 0.5; }), 0);
    EXPECT_EQ(fractions.back(), 1.0);
    EXPECT_GT(report.untanglingSteps, 0);
    const auto sj = quality::ComputeQuality(mesh, quality::Measure::ScaledJacobian);
    EXPECT_GE(*std::min_element(sj.begin(), sj.end()), 0.3);
    EXPECT_LT(MeasureSurfaceDistance(mesh, "skin", Shell().skin).max, 1e-6);
    EXPECT_LT(MeasureSurfaceDistance(mesh, "skull", Shell().skull).max, 1e-6);
    // Only nodes of the block's elements and of their neighbours may move.
    std::vector<char> near(mesh.nodes.size(), 0);
    for (const Element& e : mesh.elements)
    {
      bool touches = false;
      for (int k = 0; k < NodeCount(e.type); ++k)
        touches = touches || input.nodes[e.nodes[k]] != Shell().mesh.nodes[e.nodes[k]];
      for (int k = 0; touches && k < NodeCount(e.type); ++k)
        near[e.nodes[k]] = 1;
    }
    std::size_t moved = 0;
    for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
      if (mesh.nodes[n] != input.nodes[n])
      {
        ++moved;
        bool nextToBlock = near[n] != 0;
        for (const Element& e : mesh.elements)
          for (int k = 0; !nextToBlock && k < NodeCount(e.type); ++k)
            if (e.nodes[k] == static_cast<std::int32_t>(n))
              for (int j = 0; j < NodeCount(e.type); ++j)
                nextToBlock = nextToBlock || near[e.nodes[j]] != 0;
        EXPECT_TRUE(nextToBlock) << "node " << n << " moved far from the block";
      }
    EXPECT_GT(moved, 0u);
    if (symmetric)
      EXPECT_LT(ShellSymmetryError(mesh), 1e-9 * 200);
    for (const auto id : mesh.nodeSets.at("midsagittal"))
      ASSERT_LT(std::abs(mesh.nodes[id].x()), 1e-9) << "node " << id;
  }
}
