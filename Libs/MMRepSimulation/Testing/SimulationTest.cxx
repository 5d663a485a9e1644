// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Unit tests of the CalculiX deck, runner and .frd reader on small blocks with known answers.
#include "mmrepBoneSliding.h"
#include "mmrepMuscleActivation.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace
{
using namespace mmrep;
namespace sim = mmrep::simulation;

// nx × ny × nz hexahedra of size h (VTK node order), one layer; node set "skull" = nodes at z = 0.
FEMesh Block(int nx, int ny, int nz, double h, TissueLayer layer = TissueLayer::Dermis)
{
  FEMesh mesh;
  const auto id = [&](int i, int j, int k) { return static_cast<std::int32_t>((k * (ny + 1) + j) * (nx + 1) + i); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
      {
        mesh.nodes.emplace_back(i * h, j * h, k * h);
        if (k == 0)
          mesh.nodeSets["skull"].push_back(id(i, j, k));
      }
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        Element e;
        e.type = ElementType::Hexahedron;
        e.layer = layer;
        e.nodes = {id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                   id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        mesh.elements.push_back(e);
      }
  return mesh;
}

// Adds a straight muscle track through `points` (each inside the block), embedded by search.
void AddMuscle(FEMesh& mesh, const std::string& name, const std::vector<Point3>& points, int nx, int ny, double h)
{
  MuscleTrack t;
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    const Point3& x = points[p];
    const int i = std::min(static_cast<int>(x.x() / h), nx - 1), j = std::min(static_cast<int>(x.y() / h), ny - 1),
              k = static_cast<int>(x.z() / h);
    Embedding emb;
    emb.element = (k * ny + j) * nx + i;
    emb.pcoords = {x.x() / h - i, x.y() / h - j, x.z() / h - k};
    t.nodes.push_back(static_cast<std::int32_t>(mesh.nodes.size()));
    t.embedding.push_back(emb);
    mesh.nodes.push_back(x);
    if (p > 0)
    {
      Element c;
      c.type = ElementType::Cable;
      c.nodes[0] = t.nodes[p - 1];
      c.nodes[1] = t.nodes[p];
      t.cables.push_back(static_cast<std::int32_t>(mesh.elements.size()));
      mesh.elements.push_back(c);
    }
  }
  mesh.muscles[name] = t;
  mesh.elementSets[name] = t.cables;
}

// One 10 mm hexahedron in uniaxial compression by four vertical cables along its edges: bottom nodes
// slide on z = 0 (node 0 fixed, node 1 also kept on y = 0), lateral faces free, so the state is
// homogeneous and, at small strain s = δ/L, the tissue's force E s A balances the four cables,
// 4 F(λ = 1 − s) with F the cable law: solved here by bisection; E = 9Kμ/(3K+μ) from the polynomial
// law's μ and K.
TEST(Simulation, SingleHexUniaxialMatchesSmallStrainSolution)
{
  FEMesh mesh = Block(1, 1, 1, 10.0);
  mesh.nodeSets["skull"] = {0};
  const double L = 10, A = 100;
  for (int c = 0; c < 4; ++c)
  {
    MuscleTrack t;
    for (int end = 0; end < 2; ++end)
    {
      const int hexNode = c + 4 * end; // bottom corner c, then the top corner above it
      Embedding emb;
      emb.element = 0;
      const Point3& p = mesh.nodes[static_cast<std::size_t>(hexNode)];
      emb.pcoords = {p.x() / L, p.y() / L, p.z() / L};
      t.nodes.push_back(static_cast<std::int32_t>(mesh.nodes.size()));
      t.embedding.push_back(emb);
      mesh.nodes.push_back(p);
    }
    t.maximumForce = 0.001; // N: about 0.3 % strain
    Element cable;
    cable.type = ElementType::Cable;
    cable.nodes[0] = t.nodes[0];
    cable.nodes[1] = t.nodes[1];
    t.cables.push_back(static_cast<std::int32_t>(mesh.elements.size()));
    mesh.elements.push_back(cable);
    mesh.muscles["edge" + std::to_string(c)] = t;
  }
  mesh.Validate();

  sim::ActivationOptions options;
  for (int c = 0; c < 4; ++c)
    options.deck.activations.push_back({"edge" + std::to_string(c), 1.0});
  options.deck.hexahedronType = "C3D8";
  for (int n = 0; n < 4; ++n)
    options.deck.slidingNodes.push_back({n, Point3::UnitZ()});
  options.deck.slidingNodes.push_back({1, Point3::UnitY()});
  options.run.threads = 1;
  const sim::ActivationResult r = sim::SimulateMuscleActivation(mesh, options);
  ASSERT_TRUE(r.run.converged);
  EXPECT_EQ(r.deck.slidingNodes, 4u); // node 0 is fixed, so its sliding condition is skipped
  EXPECT_EQ(r.run.cutbacks, 0);

  const sim::HyperelasticMaterial m = sim::FaceTissue();
  const double mu = m.ShearModulus(), K = m.BulkModulus();
  const double E = 9 * K * mu / (3 * K + mu);
  double lo = 0, hi = 0.5; // strain
  for (int it = 0; it < 100; ++it)
  {
    const double s = 0.5 * (lo + hi);
    (4 * sim::CableForce(options.deck.cables, 0.001, L, 1, -s * L) > E * s * A ? lo : hi) = s;
  }
  const double expected = 0.5 * (lo + hi) * L;
  EXPECT_GT(expected, 0.02); // the cables do shorten the block
  for (int n = 4; n < 8; ++n)
  {
    const double delta = -r.displacements[static_cast<std::size_t>(n)].z();
    std::printf("top node %d: shortening %.6g mm, small-strain solution %.6g mm\n", n, delta, expected);
    EXPECT_NEAR(delta, expected, 0.01 * expected);
  }
  // Lateral expansion by the Poisson ratio of the initial response: ν = (3K − 2μ)/(2(3K + μ)).
  const double nu = (3 * K - 2 * mu) / (2 * (3 * K + mu));
  // Node 7 is the top corner at (10, 10, 10); node 0 is fixed at the origin.
  EXPECT_NEAR(r.displacements[7].x(), nu * expected, 0.02 * nu * expected);
  EXPECT_NEAR(r.displacements[7].y(), nu * expected, 0.02 * nu * expected);
  // The embedded cable nodes follow the corners they sit on.
  for (const auto& [name, t] : mesh.muscles)
    for (std::size_t i = 0; i < 2; ++i)
    {
      const auto host = static_cast<std::size_t>(std::stoi(name.substr(4)) + 4 * static_cast<int>(i));
      EXPECT_LT((r.displacements[static_cast<std::size_t>(t.nodes[i])] - r.displacements[host]).norm(), 1e-5);
    }
  // Cable force balances the tissue: 4F = E δ/L A.
  ASSERT_EQ(r.muscles.size(), 4u);
  EXPECT_NEAR(4 * r.muscles[0].meanForce, E * expected / L * A, 0.02 * E * expected / L * A);
}

// A curved track in a free block: activation shortens the track and pulls its ends toward each other.
TEST(Simulation, BlockMuscleShortensAndIsSymmetric)
{
  const int nx = 4, ny = 2, nz = 2;
  const double h = 5;
  FEMesh mesh = Block(nx, ny, nz, h);
  AddMuscle(mesh, "M", {{2.5, 5, 7.5}, {7.5, 5, 7.5}, {12.5, 5, 7.5}, {17.5, 5, 7.5}}, nx, ny, h);
  mesh.muscles.at("M").maximumForce = 0.2; // N: the free block is soft
  mesh.Validate();
  sim::ActivationOptions options;
  options.deck.activations = {{"M", 1.0}};
  options.run.threads = 1;
  const sim::ActivationResult r = sim::SimulateMuscleActivation(mesh, options);
  ASSERT_TRUE(r.run.converged);
  const auto& t = mesh.muscles.at("M");
  const Point3 first = r.displacements[static_cast<std::size_t>(t.nodes.front())];
  const Point3 last = r.displacements[static_cast<std::size_t>(t.nodes.back())];
  EXPECT_GT(first.x(), 0.1);               // pulled toward the middle
  EXPECT_NEAR(last.x(), -first.x(), 1e-3); // mirror symmetry of block and track
  EXPECT_NEAR(last.z(), first.z(), 1e-3);
  ASSERT_EQ(r.muscles.size(), 1u);
  EXPECT_LT(r.muscles[0].length, r.muscles[0].restLength);
  // Shortened on the ascending limb: less than the maximum force, more than half of it.
  const double fmax = mesh.muscles.at("M").maximumForce;
  EXPECT_LT(r.muscles[0].meanForce, fmax);
  EXPECT_GT(r.muscles[0].meanForce, 0.5 * fmax);
  EXPECT_GT(r.muscles[0].length, 0.5 * r.muscles[0].restLength);
}

// Bone sliding (mmrepBoneSliding.h) on a block whose bottom is the maxilla and whose top is skin:
// the anchors are the bottom perimeter (side faces) and the bottom nodes of the track's end elements,
// every other bottom node slides along z = 0 (normal ±z); the solve keeps them on the plane while
// they move along it, and the block glued to the bone moves less.
TEST(Simulation, BoneSlidingAnchorsEdgesAndMuscleOriginsAndSlidesTheRest)
{
  const int nx = 6, ny = 4, nz = 2;
  const double h = 5;
  FEMesh mesh = Block(nx, ny, nz, h);
  mesh.nodeSets["maxilla"] = mesh.nodeSets.at("skull");
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    if (mesh.nodes[i].z() == nz * h)
      mesh.nodeSets["skin"].push_back(static_cast<std::int32_t>(i));
  AddMuscle(mesh, "M", {{7.5, 10, 2.5}, {12.5, 10, 2.5}, {17.5, 10, 2.5}, {22.5, 10, 2.5}}, nx, ny, h);
  mesh.muscles.at("M").maximumForce = 0.2;
  mesh.Validate();
  // Expected anchors by brute force: bottom nodes on the block's sides or of the end elements (x in
  // [5, 10] and [20, 25], y in [10, 15] at the bottom layer).
  const auto& t = mesh.muscles.at("M");
  std::set<std::int32_t> expected;
  for (auto n : mesh.nodeSets.at("maxilla"))
  {
    const Point3& p = mesh.nodes[static_cast<std::size_t>(n)];
    const bool side = p.x() == 0 || p.x() == nx * h || p.y() == 0 || p.y() == ny * h;
    bool end = false;
    for (auto e : {t.embedding.front().element, t.embedding.back().element})
      for (int k = 0; k < 8; ++k)
        end = end || mesh.elements[static_cast<std::size_t>(e)].nodes[static_cast<std::size_t>(k)] == n;
    if (side || end)
      expected.insert(n);
  }
  const auto anchors = sim::BoneAnchorNodes(mesh);
  EXPECT_EQ(std::set<std::int32_t>(anchors.begin(), anchors.end()), expected);
  const auto sliding = sim::BoneSlidingNodes(mesh);
  EXPECT_EQ(sliding.size() + expected.size(), mesh.nodeSets.at("maxilla").size());
  for (const auto& s : sliding)
  {
    EXPECT_TRUE(s.onBone);
    EXPECT_EQ(expected.count(s.node), 0u);
    EXPECT_NEAR(std::abs(s.normal.z()), 1.0, 1e-12);
  }

  sim::ActivationOptions options;
  options.deck.activations = {{"M", 1.0}};
  options.deck.fixedNodeSet = "maxilla";
  options.run.threads = 1;
  const sim::ActivationResult glued = sim::SimulateMuscleActivation(mesh, options);
  options.deck.slidingNodes = sliding;
  const sim::ActivationResult slid = sim::SimulateMuscleActivation(mesh, options);
  ASSERT_TRUE(glued.run.converged && slid.run.converged);
  EXPECT_EQ(slid.deck.fixedNodes, expected.size());
  EXPECT_EQ(slid.deck.slidingNodes, sliding.size());
  double moved = 0;
  for (const auto& s : sliding)
  {
    const Point3& u = slid.displacements[static_cast<std::size_t>(s.node)];
    EXPECT_LT(std::abs(u.z()), 1e-6);
    moved = std::max(moved, u.head<2>().norm());
    EXPECT_LT(glued.displacements[static_cast<std::size_t>(s.node)].norm(), 1e-9);
  }
  EXPECT_GT(moved, 0.01);
  EXPECT_LT(slid.muscles[0].length, glued.muscles[0].length); // the free-er block lets the muscle shorten more
}

// The Hill-type law against its definition: F = a Fmax f_L(λ) + k Fmax (λ − 1), f_L = exp(−(λ−1)²/γ)
// below λ = 1 and 1 above, exact at the curve's points, linear in the activation, strictly increasing.
TEST(Simulation, CableLawIsHillType)
{
  const sim::CableModel c; // γ = 0.45, k = 0.05
  const double fmax = 3, L0 = 4;
  EXPECT_DOUBLE_EQ(sim::CableForce(c, fmax, L0, 1, 0), fmax); // isometric, optimal length
  EXPECT_NEAR(sim::CableForce(c, fmax, L0, 1, -0.3 * L0), fmax * (std::exp(-0.09 / 0.45) - 0.015), 1e-12); // λ = 0.7
  EXPECT_NEAR(sim::CableForce(c, fmax, L0, 0, 0.1 * L0), fmax * 0.005, 1e-12); // relaxed, stretched 10 %
  EXPECT_NEAR(sim::CableForce(c, fmax, L0, 1, 0.4 * L0), fmax * 1.02, 1e-12);  // plateau above L0
  EXPECT_NEAR(sim::CableForce(c, 2 * fmax, L0, 1, 0), 2 * fmax, 1e-12);        // proportional to Fmax
  sim::CableModel scaled = c;
  scaled.forceScale = 2;
  EXPECT_NEAR(sim::CableForce(scaled, fmax, L0, 1, -1), 2 * sim::CableForce(c, fmax, L0, 1, -1), 1e-12);
  double previous = -1e300;
  for (double e = -L0; e <= 2 * L0; e += 0.01)
  {
    const double f = sim::CableForce(c, fmax, L0, 0.6, e);
    EXPECT_NEAR(f, 0.6 * sim::CableForce(c, fmax, L0, 1, e) + 0.4 * sim::CableForce(c, fmax, L0, 0, e), 1e-12);
    EXPECT_GT(f, previous) << "not increasing at elongation " << e;
    previous = f;
  }
  // The deck's curve is the same law: its points are the function's.
  for (const auto& [e, f] : sim::CableCurve(c, fmax, L0, 0.6))
    EXPECT_NEAR(sim::CableForce(c, fmax, L0, 0.6, e), f, 1e-12);
}

TEST(Simulation, ActivationErrorsAreClear)
{
  FEMesh mesh = Block(2, 1, 1, 5);
  try
  {
    sim::CheckActivations(mesh, {{"M", 1}});
    FAIL() << "no exception";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("no muscles"), std::string::npos) << e.what();
  }
  AddMuscle(mesh, "Zyg_L", {{1, 2, 2}, {8, 2, 2}}, 2, 1, 5);
  AddMuscle(mesh, "Zyg_R", {{1, 3, 3}, {8, 3, 3}}, 2, 1, 5);
  try
  {
    sim::CheckActivations(mesh, {{"zyg_L", 1}});
    FAIL() << "no exception";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_EQ(std::string(e.what()), "unknown muscle 'zyg_L'; the model's muscles are: Zyg_L, Zyg_R");
  }
  EXPECT_THROW(sim::CheckActivations(mesh, {{"Zyg_L", 1.5}}), std::invalid_argument);
  EXPECT_THROW(sim::CheckActivations(mesh, {{"Zyg_L", 0}}), std::invalid_argument);
  EXPECT_THROW(sim::CheckActivations(mesh, {{"Zyg_L", 1}, {"Zyg_L", 1}}), std::invalid_argument);
  EXPECT_NO_THROW(sim::CheckActivations(mesh, {{"Zyg_L", 1}, {"Zyg_R", 0}}));
}

TEST(Simulation, MissingCalculiXIsReported)
{
  try
  {
    sim::FindCalculiX("ccx-not-installed-here");
    FAIL() << "no exception";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("calculix-ccx"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sim::FindCalculiX("/nonexistent/ccx"), std::runtime_error);
}

// Stand-ins for ccx that fail the way a solver or a machine does; each must be named for what it is.
std::string FakeCalculiX(const std::string& name, const std::string& body)
{
  const std::filesystem::path path =
    std::filesystem::temp_directory_path() / ("mmrep-fake-ccx-" + name + "-" + std::to_string(::getpid()));
  std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
  return path.string();
}

TEST(Simulation, CalculiXFaultsAreNamedApartFromANonConvergedSolve)
{
  const std::string deck = "*NODE\n1, 0, 0, 0\n";
  sim::RunOptions options;
  options.executable = FakeCalculiX("crash", "echo ' iteration 1'; kill -SEGV $$");
  sim::CalculiXRun run = sim::RunCalculiX(deck, options);
  EXPECT_EQ(run.outcome, sim::CalculiXOutcome::Crashed);
  EXPECT_NE(sim::DescribeFailure(run).find("CalculiX crashed (Segmentation fault)"), std::string::npos)
    << sim::DescribeFailure(run);
  EXPECT_EQ(sim::DescribeFailure(run).find("converge"), std::string::npos) << sim::DescribeFailure(run);

  options.executable = FakeCalculiX("silent", "exit 0");
  run = sim::RunCalculiX(deck, options);
  EXPECT_EQ(run.outcome, sim::CalculiXOutcome::NoResults);
  EXPECT_NE(sim::DescribeFailure(run).find("ended without results (exit code 0)"), std::string::npos)
    << sim::DescribeFailure(run);

  options.executable = FakeCalculiX("deck", "echo ' *ERROR reading *MATERIAL: no density'; exit 201");
  run = sim::RunCalculiX(deck, options);
  EXPECT_EQ(run.outcome, sim::CalculiXOutcome::DeckRefused);
  EXPECT_NE(sim::DescribeFailure(run).find("refused the model's input deck: *ERROR reading *MATERIAL"),
            std::string::npos)
    << sim::DescribeFailure(run);

  options.executable =
    FakeCalculiX("cutback", "echo ' increment size decreased to 0.1'; echo ' *ERROR: too many cutbacks'; exit 201");
  run = sim::RunCalculiX(deck, options);
  EXPECT_EQ(run.outcome, sim::CalculiXOutcome::DidNotConverge);
  EXPECT_NE(sim::DescribeFailure(run).find("did not converge: *ERROR: too many cutbacks"), std::string::npos)
    << sim::DescribeFailure(run);
}

// A solver that ignores SIGTERM is killed after the grace period when the run is aborted.
TEST(Simulation, AHungCalculiXIsKilledWhenTheRunIsAborted)
{
  const auto pidFile = std::filesystem::temp_directory_path() / ("mmrep-hung-ccx-" + std::to_string(::getpid()));
  std::filesystem::remove(pidFile);
  sim::RunOptions options;
  options.executable = FakeCalculiX("hung", "trap '' TERM; echo $$ > '" + pidFile.string() + "'; while :; do :; done");
  options.progress = [&](double) {
    if (std::filesystem::exists(pidFile) && std::filesystem::file_size(pidFile) > 0)
      throw std::runtime_error("aborted");
  };
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(sim::RunCalculiX("*NODE\n", options), std::runtime_error);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 30.0); // grace period 3 s; without the SIGKILL the call never returns
  std::ifstream in(pidFile);
  pid_t pid = 0;
  ASSERT_TRUE(in >> pid);
  EXPECT_NE(::kill(pid, 0), 0); // gone (and reaped: it was our child)
  EXPECT_EQ(errno, ESRCH);
  std::filesystem::remove(pidFile);
}

TEST(Simulation, FrdReaderParsesLongAndShortRecords)
{
  const std::string text = "    1C\n"
                           "    2C                             2                                     1\n"
                           " -1         1 0.00000E+00 0.00000E+00 0.00000E+00\n"
                           " -3\n"
                           "    1PSTEP                         1           1           1\n"
                           "  100CL  101 5.00000E-01           2                     0    1           1\n"
                           " -4  DISP        4    1\n"
                           " -5  D1          1    2    1    0\n"
                           " -1         1 1.00000E-01-2.50000E-01 3.00000E+00\n"
                           " -1        12-1.00000E-03 0.00000E+00 1.23450E+02\n"
                           " -3\n"
                           "  100CL  102 1.000000000           2                     0    2           0\n"
                           " -4  DISP        4    1\n"
                           " -1    1 2.00000E-01-5.00000E-01 6.00000E+00\n"
                           " -1   12-2.00000E-03 0.00000E+00 2.46900E+02\n"
                           " -3\n"
                           " 9999\n";
  std::istringstream in(text);
  const auto blocks = sim::ReadFrd(in, "test.frd");
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].name, "DISP");
  EXPECT_DOUBLE_EQ(blocks[0].time, 0.5);
  EXPECT_EQ(blocks[0].values.at(12), (std::vector<double>{-1e-3, 0, 123.45}));
  const sim::FrdBlock* last = sim::LastBlock(blocks, "DISP");
  ASSERT_NE(last, nullptr);
  EXPECT_DOUBLE_EQ(last->time, 1.0);
  EXPECT_EQ(last->values.at(1), (std::vector<double>{0.2, -0.5, 6}));
  std::istringstream truncated(text.substr(0, text.find(" -3\n  100CL")));
  EXPECT_THROW(sim::ReadFrd(truncated, "t.frd"), std::runtime_error);
}

} // namespace
