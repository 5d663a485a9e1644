// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The half-face model (mmrepHalfModel.h) of the shipped atlas: the cut against counts computed here
// from the full model, the symmetry condition as CalculiX reads it from the exported .inp and from
// the simulation deck, and the same symmetric gesture on the full model and on the half.
#include "mmrepFEMeshIO.h"
#include "mmrepHalfModel.h"
#include "mmrepMuscleActivation.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace
{
using namespace mmrep;
namespace sim = mmrep::simulation;
namespace fs = std::filesystem;

const std::string kAtlas = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu";

const FEMesh& Atlas()
{
  static const FEMesh atlas = ReadFEMesh(kAtlas);
  return atlas;
}

// The plane of the midsagittal nodes by an SVD of the centred coordinates (not FitPlaneToNodeSet's
// eigen-decomposition of the covariance), normal to +x.
Plane ReferencePlane(const FEMesh& mesh, const std::string& set)
{
  const auto& ids = mesh.nodeSets.at(set);
  Eigen::MatrixXd a(ids.size(), 3);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (auto id : ids)
    c += mesh.nodes[static_cast<std::size_t>(id)] / static_cast<double>(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k)
    a.row(static_cast<Eigen::Index>(k)) = (mesh.nodes[static_cast<std::size_t>(ids[k])] - c).transpose();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinV);
  Plane p;
  p.point = c;
  p.normal = svd.matrixV().col(2).normalized();
  if (p.normal.x() < 0)
    p.normal = -p.normal;
  return p;
}

std::string Key(const Point3& p)
{
  std::ostringstream s;
  s.precision(17);
  s << p.x() << " " << p.y() << " " << p.z();
  return s.str();
}

std::string Slurp(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path Scratch(const std::string& name)
{
  const fs::path dir = fs::path(MMREP_BINARY_DIR) / "Testing" / "HalfModel" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Largest |u·n| and largest in-plane |u| over the solid nodes of the symmetry boundary.
std::pair<double, double> PlaneMotion(const FEMesh& half, const std::vector<Point3>& u)
{
  const Plane plane = SymmetryPlaneOf(half);
  std::vector<char> solid(half.nodes.size(), 0);
  for (const auto& e : half.elements)
    if (e.type != ElementType::Cable)
      for (int k = 0; k < NodeCount(e.type); ++k)
        solid[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])] = 1;
  double normal = 0, inPlane = 0;
  for (auto n : half.nodeSets.at(kSymmetryBoundarySet))
    if (solid[static_cast<std::size_t>(n)])
    {
      const Point3& v = u[static_cast<std::size_t>(n)];
      normal = std::max(normal, std::abs(v.dot(plane.normal)));
      inPlane = std::max(inPlane, (v - v.dot(plane.normal) * plane.normal).norm());
    }
  return {normal, inPlane};
}
} // namespace

TEST(HalfModel, AtlasLeftHalfMatchesTheFullModelsLeftSide)
{
  const FEMesh& full = Atlas();
  const FEMesh half = LeftHalfModel(full);
  const Plane plane = ReferencePlane(full, "midsagittal");
  const double tol = 1e-6;

  // Independent left side of the full model: solids by centroid, tracks named _L, their nodes.
  std::size_t leftSolids = 0, straddling = 0;
  std::set<std::int32_t> leftNodes;
  for (const auto& e : full.elements)
  {
    if (e.type == ElementType::Cable)
      continue;
    double lo = 1e300, hi = -1e300;
    Point3 c = Point3::Zero();
    for (int k = 0; k < NodeCount(e.type); ++k)
    {
      const Point3& p = full.nodes[static_cast<std::size_t>(e.nodes[k])];
      lo = std::min(lo, plane.SignedDistance(p));
      hi = std::max(hi, plane.SignedDistance(p));
      c += p / NodeCount(e.type);
    }
    straddling += lo < -tol && hi > tol;
    if (plane.SignedDistance(c) > 0)
    {
      ++leftSolids;
      for (int k = 0; k < NodeCount(e.type); ++k)
        leftNodes.insert(e.nodes[k]);
    }
  }
  std::size_t leftCables = 0, leftMuscles = 0;
  for (const auto& [name, track] : full.muscles)
    if (name.size() > 2 && name.compare(name.size() - 2, 2, "_L") == 0)
    {
      ++leftMuscles;
      leftCables += track.cables.size();
      leftNodes.insert(track.nodes.begin(), track.nodes.end());
    }
  // Nodes of no element on the left (the jaw axis's left condyle) are kept too.
  {
    std::vector<char> inElement(full.nodes.size(), 0);
    for (const auto& e : full.elements)
      for (int k = 0; k < NodeCount(e.type); ++k)
        inElement[static_cast<std::size_t>(e.nodes[k])] = 1;
    for (std::size_t i = 0; i < full.nodes.size(); ++i)
      if (!inElement[i] && plane.SignedDistance(full.nodes[i]) > tol)
        leftNodes.insert(static_cast<std::int32_t>(i));
  }
  EXPECT_EQ(straddling, 0u);
  EXPECT_EQ(2 * leftSolids, full.SolidElementCount()); // the atlas is symmetric: exactly half
  EXPECT_EQ(half.SolidElementCount(), leftSolids);
  EXPECT_EQ(half.elements.size() - half.SolidElementCount(), leftCables);
  EXPECT_EQ(half.muscles.size(), leftMuscles);
  EXPECT_EQ(half.nodes.size(), leftNodes.size());
  std::printf("atlas %zu nodes, %zu solids, %zu cables -> half %zu nodes, %zu solids, %zu cables, %zu muscles, "
              "%zu symmetry-boundary nodes\n",
              full.nodes.size(), full.SolidElementCount(), full.elements.size() - full.SolidElementCount(),
              half.nodes.size(), half.SolidElementCount(), half.elements.size() - half.SolidElementCount(),
              half.muscles.size(), half.nodeSets.at(kSymmetryBoundarySet).size());

  // Every kept node is a left-side node of the full model, on the left or on the plane, in the full
  // model's order (positions alone do not identify nodes: the mouth slit's twins coincide).
  const std::vector<std::int32_t> origin(leftNodes.begin(), leftNodes.end());
  ASSERT_EQ(origin.size(), half.nodes.size());
  for (std::size_t i = 0; i < half.nodes.size(); ++i)
  {
    EXPECT_EQ(half.nodes[i], full.nodes[static_cast<std::size_t>(origin[i])]) << i;
    EXPECT_GE(plane.SignedDistance(half.nodes[i]), -tol);
  }
  // Sets: each is the full set's left-side nodes / elements.
  for (const auto& [name, ids] : full.nodeSets)
  {
    std::set<std::int32_t> expected;
    for (auto n : ids)
      if (leftNodes.count(n))
        expected.insert(n);
    std::set<std::int32_t> actual;
    if (half.nodeSets.count(name))
      for (auto n : half.nodeSets.at(name))
        actual.insert(origin[static_cast<std::size_t>(n)]);
    EXPECT_EQ(actual, expected) << "node set " << name;
  }
  std::set<std::int32_t> planeNodes;
  for (auto n : half.nodeSets.at(kSymmetryBoundarySet))
  {
    planeNodes.insert(origin[static_cast<std::size_t>(n)]);
    EXPECT_LT(std::abs(plane.SignedDistance(half.nodes[static_cast<std::size_t>(n)])), tol);
  }
  std::set<std::int32_t> leftMidsagittal;
  for (auto n : full.nodeSets.at("midsagittal"))
    if (leftNodes.count(n))
      leftMidsagittal.insert(n);
  EXPECT_EQ(planeNodes, leftMidsagittal);
  for (const auto& [name, ids] : half.elementSets)
  {
    ASSERT_EQ(full.elementSets.count(name), 1u) << name;
    EXPECT_EQ(name.find("_R"), std::string::npos) << "right-side set kept: " << name;
    std::size_t fullLeft = 0;
    for (auto e : full.elementSets.at(name))
    {
      const Element& el = full.elements[static_cast<std::size_t>(e)];
      bool left = true;
      for (int k = 0; k < NodeCount(el.type); ++k)
        left = left && leftNodes.count(el.nodes[k]);
      fullLeft += left;
    }
    EXPECT_EQ(ids.size(), fullLeft) << "element set " << name;
  }
  // Muscle embeddings are inside kept solids and give back the track points.
  for (const auto& [name, track] : half.muscles)
    for (std::size_t k = 0; k < track.nodes.size(); ++k)
    {
      const Element& host = half.elements[static_cast<std::size_t>(track.embedding[k].element)];
      const auto w = sim::ShapeFunctions(host.type, track.embedding[k].pcoords);
      Point3 p = Point3::Zero();
      for (std::size_t j = 0; j < w.size(); ++j)
        p += w[j] * half.nodes[static_cast<std::size_t>(host.nodes[j])];
      EXPECT_LT((p - half.nodes[static_cast<std::size_t>(track.nodes[k])]).norm(), 1e-6) << name << " " << k;
    }
  // Landmarks: those on the left or on the plane.
  std::size_t keptLandmarks = 0;
  for (const auto& l : full.landmarks)
    keptLandmarks += plane.SignedDistance(l.position) >= -tol;
  EXPECT_EQ(half.landmarks.size(), keptLandmarks);

  // The symmetry boundary and its plane survive the .vtu round trip.
  const fs::path dir = Scratch("RoundTrip");
  WriteFEMesh(half, (dir / "half.vtu").string());
  const FEMesh back = ReadFEMesh((dir / "half.vtu").string());
  ASSERT_TRUE(IsHalfModel(back));
  const Plane again = SymmetryPlaneOf(back);
  EXPECT_GT(again.normal.dot(plane.normal), 1 - 1e-12);
  EXPECT_LT(std::abs(plane.SignedDistance(again.point)), 1e-9);
  EXPECT_FALSE(IsHalfModel(full));
  EXPECT_THROW(LeftHalfModel(half), std::invalid_argument); // already a half
}

TEST(HalfModel, ModelsThatCannotBeCutAreRefused)
{
  // Two hexahedra side by side across x = 0.5 with the "plane" nodes at x = 0.25: not cut along it.
  FEMesh mesh;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        mesh.nodes.emplace_back(i * 0.5 - 0.5, j, k);
  const auto id = [](int i, int j, int k) { return (k * 2 + j) * 3 + i; };
  for (int i = 0; i < 2; ++i)
  {
    Element e;
    e.nodes = {id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0),
               id(i, 0, 1), id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1)};
    e.layer = TissueLayer::Dermis;
    mesh.elements.push_back(e);
  }
  mesh.nodeSets["midsagittal"] = {id(1, 0, 0), id(1, 1, 0), id(1, 0, 1), id(1, 1, 1)};
  EXPECT_NO_THROW(LeftHalfModel(mesh)); // cut along x = 0: one element each side
  FEMesh moved = mesh;
  for (auto n : moved.nodeSets["midsagittal"])
    moved.nodes[static_cast<std::size_t>(n)].x() = 0.3;         // plane x = 0.3
  moved.nodes[static_cast<std::size_t>(id(0, 0, 0))].x() = 0.6; // the right element now reaches across it
  try
  {
    LeftHalfModel(moved);
    ADD_FAILURE() << "a straddling element was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("straddles"), std::string::npos) << e.what();
  }
  FEMesh skew = mesh;
  skew.nodes[static_cast<std::size_t>(id(1, 1, 1))].x() = 0.2;
  try
  {
    LeftHalfModel(skew);
    ADD_FAILURE() << "a non-planar plane set was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("off the set's plane"), std::string::npos) << e.what();
  }
  // A right-side muscle asked of a half model.
  const FEMesh half = LeftHalfModel(Atlas());
  try
  {
    sim::CheckActivations(half, {{"ZygomaticusMajor_R", 1.0}});
    ADD_FAILURE() << "a right-side muscle was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("right side"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("ZygomaticusMajor_L"), std::string::npos) << e.what();
  }
}

// The exported .inp declares the symmetry: CalculiX, reading it as written, keeps the plane nodes
// in the plane under an oblique gravity load that pulls everything towards the patient's right.
TEST(HalfModel, ExportedInpSymmetryIsEnforcedByCalculiX)
{
  const FEMesh half = LeftHalfModel(Atlas());
  const fs::path dir = Scratch("Inp");
  WriteFEMesh(half, (dir / "half.inp").string());
  const std::string inp = Slurp(dir / "half.inp");
  EXPECT_NE(inp.find("*TRANSFORM, NSET=symmetryBoundary, TYPE=R"), std::string::npos);
  EXPECT_NE(inp.find("*BOUNDARY\nsymmetryBoundary, 1, 1\n"), std::string::npos);
  std::string holdMuscles; // muscle nodes are embedded by the simulation deck, not by the export
  const std::regex muscleSet("\\*NSET, NSET=(muscle_[A-Za-z0-9_]+)");
  for (auto it = std::sregex_iterator(inp.begin(), inp.end(), muscleSet); it != std::sregex_iterator(); ++it)
    holdMuscles += (*it)[1].str() + ", 1, 3\n";
  const std::string deck = inp + R"(*MATERIAL, NAME=TISSUE
*ELASTIC
0.02, 0.45
*DENSITY
1e-9
*SOLID SECTION, ELSET=ESOLID, MATERIAL=TISSUE
*MATERIAL, NAME=FIBRE
*ELASTIC
0.5, 0.3
*SOLID SECTION, ELSET=ECABLE, MATERIAL=FIBRE
0.25
*BOUNDARY
skull, 1, 3
)" + holdMuscles + R"(*STEP
*STATIC
*DLOAD
ESOLID, GRAV, 9810., -0.6, -0.48, -0.64
*NODE FILE
U
*END STEP
)";
  sim::RunOptions run;
  run.threads = 1;
  const sim::CalculiXRun r = sim::RunCalculiX(deck, run);
  ASSERT_TRUE(r.converged) << r.message << "\n" << r.log.substr(0, 2000);
  const sim::FrdBlock* disp = sim::LastBlock(r.results, "DISP");
  ASSERT_NE(disp, nullptr);
  std::vector<Point3> u(half.nodes.size(), Point3::Zero());
  for (const auto& [id, v] : disp->values)
    u[static_cast<std::size_t>(id - 1)] = Point3(v[0], v[1], v[2]);
  const auto [normal, inPlane] = PlaneMotion(half, u);
  double largest = 0;
  for (const auto& v : u)
    largest = std::max(largest, v.norm());
  std::printf("exported half .inp under oblique gravity: plane nodes |u.n| max %.3g mm, in-plane max %.3f mm; largest "
              "|u| %.3f mm\n",
              normal, inPlane, largest);
  EXPECT_LT(normal, 1e-6);
  EXPECT_GT(inPlane, 0.01);
  EXPECT_GT(largest, 0.01);
}

// FEBio: the plane faces form a surface with the "symmetry plane" constraint.
TEST(HalfModel, FEBioAndGmshExportsDeclareTheSymmetryBoundary)
{
  const FEMesh half = LeftHalfModel(Atlas());
  const fs::path dir = Scratch("FEBio");
  WriteFEMesh(half, (dir / "half.feb").string());
  const std::string feb = Slurp(dir / "half.feb");
  const auto faces = SymmetryBoundaryFaces(half);
  // Independent count: hexahedron faces with four plane nodes (the atlas's plane faces are quads).
  std::set<std::int32_t> planeNodes(half.nodeSets.at(kSymmetryBoundarySet).begin(),
                                    half.nodeSets.at(kSymmetryBoundarySet).end());
  std::size_t expected = 0;
  static const int hexFaces[6][4] = {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                     {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  for (const auto& e : half.elements)
    if (e.type == ElementType::Hexahedron)
      for (const auto& f : hexFaces)
        expected += std::all_of(std::begin(f), std::end(f), [&](int k) { return planeNodes.count(e.nodes[k]) > 0; });
  EXPECT_GT(expected, 100u);
  EXPECT_EQ(faces.size(), expected);
  const std::regex quad("<quad4 id=\"\\d+\">(\\d+),(\\d+),(\\d+),(\\d+)</quad4>");
  // Only the symmetry surface's faces (the lips' facing surfaces are surfaces too).
  const std::size_t from = feb.find("<Surface name=\"symmetryBoundary\">");
  ASSERT_NE(from, std::string::npos);
  const std::string symmetrySurface = feb.substr(from, feb.find("</Surface>", from) - from);
  std::size_t quads = 0;
  const Plane plane = SymmetryPlaneOf(half);
  for (auto it = std::sregex_iterator(symmetrySurface.begin(), symmetrySurface.end(), quad);
       it != std::sregex_iterator(); ++it)
  {
    ++quads;
    std::vector<Point3> p;
    for (int k = 1; k <= 4; ++k)
    {
      const int n = std::stoi((*it)[k].str()) - 1;
      EXPECT_EQ(planeNodes.count(n), 1u);
      p.push_back(half.nodes[static_cast<std::size_t>(n)]);
    }
    // Outward = towards the removed right half, i.e. against the plane normal.
    EXPECT_LT((p[2] - p[0]).cross(p[3] - p[1]).dot(plane.normal), 0);
  }
  EXPECT_EQ(quads, expected);
  EXPECT_NE(feb.find("<constraint type=\"symmetry plane\" surface=\"symmetryBoundary\">"), std::string::npos);
  EXPECT_LT(feb.find("</Mesh>"), feb.find("<Constraints>"));

  WriteFEMesh(half, (dir / "half.msh").string());
  const std::string msh = Slurp(dir / "half.msh");
  EXPECT_TRUE(std::regex_search(msh, std::regex("\n0 \\d+ \"symmetryBoundary\"\n")));
  const int gmsh = std::system(
    ("gmsh -check '" + (dir / "half.msh").string() + "' > '" + (dir / "gmsh.log").string() + "' 2>&1").c_str());
  EXPECT_EQ(gmsh, 0) << Slurp(dir / "gmsh.log");
  // Gmsh reports what it found as Error or Warning lines (its exit code stays 0 for some of them).
  const std::string log = Slurp(dir / "gmsh.log");
  EXPECT_NE(log.find("Checking for duplicate nodes"), std::string::npos) << log;
  EXPECT_EQ(log.find("Error"), std::string::npos) << log;
  EXPECT_EQ(log.find("already exists in the mesh"), std::string::npos) << log;
}

// Issue 14's half-face simulation: both zygomatici majores on the full atlas against the left one on
// the half with the symmetry condition; the landmark displacements agree and the plane nodes stay in
// the plane while moving in it.
TEST(HalfModel, HalfAtlasSimulatesTheSymmetricSmileLikeTheFullModel)
{
  const FEMesh& full = Atlas();
  const FEMesh half = LeftHalfModel(full);
  sim::ActivationOptions fullOptions, halfOptions;
  fullOptions.deck.activations = {{"ZygomaticusMajor_L", 1.0}, {"ZygomaticusMajor_R", 1.0}};
  fullOptions.deck.slidingNodes = sim::LipSupportNodes(full);
  halfOptions.deck.activations = {{"ZygomaticusMajor_L", 1.0}};
  halfOptions.deck.slidingNodes = sim::LipSupportNodes(half);
  // The agreement does not depend on the element type; C3D8 needs far fewer Newton iterations.
  fullOptions.deck.hexahedronType = halfOptions.deck.hexahedronType = "C3D8";
  fullOptions.run.threads = halfOptions.run.threads = 1;

  const sim::ActivationResult h = sim::SimulateMuscleActivation(half, halfOptions);
  ASSERT_TRUE(h.run.converged) << h.run.message;
  EXPECT_GT(h.deck.symmetryNodes, 0u);
  const sim::ActivationResult f = sim::SimulateMuscleActivation(full, fullOptions);
  ASSERT_TRUE(f.run.converged) << f.run.message;
  EXPECT_EQ(f.deck.symmetryNodes, 0u);

  const auto [normal, inPlane] = PlaneMotion(half, h.displacements);
  EXPECT_LT(normal, 1e-6);
  EXPECT_GT(inPlane, 1e-3);

  std::printf("ccx: full model %.1f s (%zu solids, %d increments), half model %.1f s (%zu solids, %d increments): "
              "ratio %.2f; plane nodes |u.n| max %.2g mm, in-plane max %.3f mm\n",
              f.run.seconds, f.deck.solids, f.run.increments, h.run.seconds, h.deck.solids, h.run.increments,
              h.run.seconds / f.run.seconds, normal, inPlane);
  double largest = 0;
  for (const auto& m : f.landmarks)
    largest = std::max(largest, m.displacement.norm());
  ASSERT_GT(largest, 0.05);
  std::size_t compared = 0;
  for (const auto& hm : h.landmarks)
    for (const auto& fm : f.landmarks)
      if (fm.name == hm.name)
      {
        const double diff = (hm.displacement - fm.displacement).norm();
        std::printf("  %-20s full (%7.3f %7.3f %7.3f)  half (%7.3f %7.3f %7.3f)  difference %.4f mm = %.2f %% of |u|\n",
                    fm.name.c_str(), fm.displacement.x(), fm.displacement.y(), fm.displacement.z(), hm.displacement.x(),
                    hm.displacement.y(), hm.displacement.z(), diff,
                    100 * diff / std::max(fm.displacement.norm(), 1e-12));
        // 5 % of the landmark's motion; for landmarks that barely move (an eye corner in a smile,
        // a hundredth of the mouth corner's motion) 5 % of a tenth of the largest motion.
        EXPECT_LE(diff, 0.05 * std::max(fm.displacement.norm(), 0.1 * largest)) << fm.name;
        ++compared;
      }
  EXPECT_EQ(compared, half.landmarks.size());
  EXPECT_GE(compared, 3u);
}
