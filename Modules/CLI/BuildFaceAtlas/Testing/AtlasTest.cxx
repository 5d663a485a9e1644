// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Tests of the shipped face atlas (Resources/Atlas) and of its reproducible build from the CT.
// The rebuild test checks the module reproduces the shipped files bit for bit; the other tests
// check the shipped atlas's properties against independent references (VTK).
#include "mmrepFEMeshIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepModuleRunner.h"
#include "mmrepSurfaceIO.h"

#include <gtest/gtest.h>

#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkCellLocator.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkGenericCell.h>
#include <vtkMeshQuality.h>
#include <vtkPointData.h>
#include <vtkStaticCellLocator.h>
#include <vtkStaticPointLocator.h>
#include <vtkUnstructuredGrid.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vtkIdList.h>
#include <fstream>
#include <set>
#include <string>

namespace
{
const std::string kAtlasDir = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas";
const std::string kMesh = kAtlasDir + "/FaceAtlas.vtu";

const mmrep::FEMesh& Shipped()
{
  static const mmrep::FEMesh mesh = mmrep::ReadFEMesh(kMesh);
  return mesh;
}

// The atlas's symmetry plane: the least-squares plane of the mid-sagittal nodes (they must be on it).
struct FittedPlane
{
  Eigen::Vector3d point, normal;
  double maxResidual = 0;
  Eigen::Vector3d Mirror(const Eigen::Vector3d& p) const { return p - 2 * normal.dot(p - point) * normal; }
};

FittedPlane MidsagittalPlane(const mmrep::FEMesh& mesh)
{
  const auto& mid = mesh.nodeSets.at("midsagittal");
  Eigen::MatrixXd a(mid.size(), 3);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (auto n : mid)
    mean += mesh.nodes[n];
  mean /= static_cast<double>(mid.size());
  for (std::size_t k = 0; k < mid.size(); ++k)
    a.row(k) = (mesh.nodes[mid[k]] - mean).transpose();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinV);
  FittedPlane p;
  p.point = mean;
  p.normal = svd.matrixV().col(2).normalized();
  if (p.normal.x() < 0)
    p.normal = -p.normal; // towards the patient's left (+x in LPS)
  for (auto n : mid)
    p.maxResidual = std::max(p.maxResidual, std::abs(p.normal.dot(mesh.nodes[n] - mean)));
  return p;
}

vtkSmartPointer<vtkUnstructuredGrid> SolidGrid(const mmrep::FEMesh& mesh)
{
  mmrep::FEMesh solids;
  solids.nodes = mesh.nodes;
  for (const auto& e : mesh.elements)
    if (e.type != mmrep::ElementType::Cable)
      solids.elements.push_back(e);
  return mmrep::ToVTK(solids);
}

double DistanceTo(vtkStaticCellLocator* locator, const Eigen::Vector3d& p)
{
  double x[3] = {p.x(), p.y(), p.z()}, closest[3], d2 = 0;
  vtkIdType cell;
  int sub;
  locator->FindClosestPoint(x, closest, cell, sub, d2);
  return std::sqrt(d2);
}

vtkSmartPointer<vtkStaticCellLocator> Locator(vtkDataSet* data)
{
  auto l = vtkSmartPointer<vtkStaticCellLocator>::New();
  l->SetDataSet(data);
  l->BuildLocator();
  return l;
}

const std::vector<std::string> kMuscles{"OrbicularisOrisPeripheralisUpper",
                                        "OrbicularisOrisPeripheralisLower",
                                        "OrbicularisOrisMarginalisUpper",
                                        "OrbicularisOrisMarginalisLower",
                                        "ZygomaticusMajor",
                                        "Risorius",
                                        "LevatorLabiiSuperioris",
                                        "LevatorLabiiSuperiorisAlaequeNasi",
                                        "LevatorAnguliOris",
                                        "DepressorAnguliOris",
                                        "DepressorLabiiInferioris",
                                        "Mentalis",
                                        "Buccinator"};
} // namespace

// The documented command rebuilds the shipped atlas exactly (deterministic construction).
TEST(AtlasModule, RebuildMatchesShipped)
{
  mmrep::testing::ScratchDirectory dir("atlas-rebuild");
  const auto run = mmrep::testing::RunModuleExecutable(
    "BuildFaceAtlas", {std::string(MMREP_SAMPLE_DATA) + "/cthead.nrrd", dir / "FaceAtlas.vtu", "--landmarks",
                       dir / "FaceAtlasLandmarks.mrk.json", "--referenceSkin", dir / "FaceAtlasSkin.vtp",
                       "--referenceSkull", dir / "FaceAtlasSkull.vtp", "--returnparameterfile", dir / "ret.txt"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto rebuilt = mmrep::ReadFEMesh(dir / "FaceAtlas.vtu");
  const auto& shipped = Shipped();
  ASSERT_EQ(rebuilt.nodes.size(), shipped.nodes.size());
  ASSERT_EQ(rebuilt.elements.size(), shipped.elements.size());
  for (std::size_t n = 0; n < shipped.nodes.size(); ++n)
    ASSERT_EQ((rebuilt.nodes[n] - shipped.nodes[n]).cwiseAbs().maxCoeff(), 0.0) << "node " << n;
  for (std::size_t e = 0; e < shipped.elements.size(); ++e)
  {
    ASSERT_EQ(rebuilt.elements[e].nodes, shipped.elements[e].nodes) << "element " << e;
    ASSERT_EQ(rebuilt.elements[e].layer, shipped.elements[e].layer) << "element " << e;
  }
  EXPECT_EQ(rebuilt.nodeSets, shipped.nodeSets);
  EXPECT_EQ(rebuilt.mirror, shipped.mirror);
  EXPECT_EQ(rebuilt.elementSets, shipped.elementSets);
  ASSERT_EQ(rebuilt.muscles.size(), shipped.muscles.size());
  for (const auto& [name, m] : shipped.muscles)
  {
    ASSERT_TRUE(rebuilt.muscles.count(name)) << name;
    EXPECT_EQ(rebuilt.muscles.at(name).nodes, m.nodes) << name;
    EXPECT_EQ(rebuilt.muscles.at(name).cables, m.cables) << name;
  }
  ASSERT_EQ(rebuilt.landmarks.size(), shipped.landmarks.size());
  for (std::size_t k = 0; k < shipped.landmarks.size(); ++k)
    EXPECT_EQ(rebuilt.landmarks[k].position, shipped.landmarks[k].position) << shipped.landmarks[k].name;
  // The other shipped files are the same bytes.
  for (const std::string f :
       {"FaceAtlas.vtu", "FaceAtlasLandmarks.mrk.json", "FaceAtlasSkin.vtp", "FaceAtlasSkull.vtp"})
    EXPECT_TRUE(mmrep::testing::Slurp(dir / f) == mmrep::testing::Slurp(kAtlasDir + "/" + f)) << f << " differs";
  // Return values agree with the mesh.
  const auto ret = mmrep::testing::ReadReturnParameters(dir / "ret.txt");
  EXPECT_EQ(std::stoul(ret.at("nodeCount")), shipped.nodes.size());
  EXPECT_EQ(std::stoul(ret.at("elementCount")), shipped.SolidElementCount());
  EXPECT_EQ(std::stoul(ret.at("lipsNodeCount")), shipped.nodeSets.at("lips").size());
  EXPECT_EQ(std::stoul(ret.at("invertedElements")), 0u);
  EXPECT_GE(std::stod(ret.at("minScaledJacobian")), 0.5);
}

// Quality measured independently with vtkMeshQuality: hexahedra only, none inverted, SJ >= 0.5.
TEST(AtlasShipped, QualityWithVtkMeshQuality)
{
  const auto& mesh = Shipped();
  auto grid = SolidGrid(mesh);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    ASSERT_EQ(grid->GetCellType(c), VTK_HEXAHEDRON);
  auto q = vtkSmartPointer<vtkMeshQuality>::New();
  q->SetInputData(grid);
  q->SetHexQualityMeasureToScaledJacobian();
  q->Update();
  auto sj = vtkDataSet::SafeDownCast(q->GetOutput())->GetCellData()->GetArray("Quality");
  ASSERT_NE(sj, nullptr);
  double minSJ = 1e300;
  for (vtkIdType c = 0; c < sj->GetNumberOfTuples(); ++c)
    minSJ = std::min(minSJ, sj->GetTuple1(c));
  EXPECT_GE(minSJ, 0.5);
  auto qj = vtkSmartPointer<vtkMeshQuality>::New();
  qj->SetInputData(grid);
  qj->SetHexQualityMeasureToJacobian();
  qj->Update();
  auto jac = vtkDataSet::SafeDownCast(qj->GetOutput())->GetCellData()->GetArray("Quality");
  std::size_t inverted = 0;
  for (vtkIdType c = 0; c < jac->GetNumberOfTuples(); ++c)
    inverted += jac->GetTuple1(c) <= 0 ? 1 : 0;
  EXPECT_EQ(inverted, 0u);
  // Three layers, equally many elements each.
  for (const char* layer : {"epidermis", "dermis", "hypodermis"})
    EXPECT_EQ(mesh.elementSets.at(layer).size(), mesh.SolidElementCount() / 3) << layer;
}

// Every node's mirror image is a node; sets and muscles map onto their mirrors.
TEST(AtlasShipped, MirrorSymmetric)
{
  const auto& mesh = Shipped();
  const auto plane = MidsagittalPlane(mesh);
  EXPECT_LT(plane.maxResidual, 1e-9);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (const auto& p : mesh.nodes)
    points->InsertNextPoint(p.data());
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  auto locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  std::vector<std::int32_t> mirrorOf(mesh.nodes.size());
  double worst = 0;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
  {
    const Eigen::Vector3d m = plane.Mirror(mesh.nodes[n]);
    const vtkIdType id = locator->FindClosestPoint(m.data());
    mirrorOf[n] = static_cast<std::int32_t>(id);
    worst = std::max(worst, (mesh.nodes[id] - m).norm());
  }
  EXPECT_LT(worst, 1e-6);
  // Sets are mirror images of themselves, node for node up to coincidence (the mouth slit's twins
  // coincide, so a closest point names either of two nodes): each node stands for the lowest index
  // at its position.
  std::vector<std::int32_t> canonical(mesh.nodes.size());
  auto near = vtkSmartPointer<vtkIdList>::New();
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
  {
    locator->FindPointsWithinRadius(1e-9, mesh.nodes[n].data(), near);
    canonical[n] = static_cast<std::int32_t>(n);
    for (vtkIdType k = 0; k < near->GetNumberOfIds(); ++k)
      canonical[n] = std::min(canonical[n], static_cast<std::int32_t>(near->GetId(k)));
  }
  for (const auto& [name, set] : mesh.nodeSets)
  {
    std::set<std::int32_t> s, mirrored;
    for (auto n : set)
    {
      s.insert(canonical[static_cast<std::size_t>(n)]);
      mirrored.insert(canonical[static_cast<std::size_t>(mirrorOf[n])]);
    }
    EXPECT_EQ(s, mirrored) << "node set " << name;
  }
  for (const auto& [name, track] : mesh.muscles)
  {
    ASSERT_GT(name.size(), 2u);
    const std::string base = name.substr(0, name.size() - 2), side = name.substr(name.size() - 2);
    ASSERT_TRUE(side == "_L" || side == "_R") << name;
    const std::string other = base + (side == "_L" ? "_R" : "_L");
    ASSERT_TRUE(mesh.muscles.count(other)) << name;
    const auto& o = mesh.muscles.at(other);
    ASSERT_EQ(o.nodes.size(), track.nodes.size()) << name;
    // Positions (muscles meeting at the modiolus have coincident points, so indices may differ).
    for (std::size_t k = 0; k < track.nodes.size(); ++k)
      EXPECT_LT((plane.Mirror(mesh.nodes[track.nodes[k]]) - mesh.nodes[o.nodes[k]]).norm(), 1e-6)
        << name << " point " << k;
  }
  // Mirrored elements: each hexahedron's mirrored node set is a hexahedron of the mesh.
  std::set<std::vector<std::int32_t>> hexes;
  for (const auto& e : mesh.elements)
    if (e.type == mmrep::ElementType::Hexahedron)
    {
      std::vector<std::int32_t> v;
      for (auto n : e.nodes)
        v.push_back(canonical[static_cast<std::size_t>(n)]);
      std::sort(v.begin(), v.end());
      hexes.insert(v);
    }
  for (const auto& e : mesh.elements)
    if (e.type == mmrep::ElementType::Hexahedron)
    {
      std::vector<std::int32_t> v;
      for (auto n : e.nodes)
        v.push_back(canonical[static_cast<std::size_t>(mirrorOf[n])]);
      std::sort(v.begin(), v.end());
      ASSERT_TRUE(hexes.count(v));
    }
}

// Skin nodes on the (symmetrised) reference skin, skull nodes on the reference bone.
TEST(AtlasShipped, SkinAndSkullNodesOnReferenceSurfaces)
{
  const auto& mesh = Shipped();
  auto skin = mmrep::ReadSurface(kAtlasDir + "/FaceAtlasSkin.vtp");
  auto skull = mmrep::ReadSurface(kAtlasDir + "/FaceAtlasSkull.vtp");
  auto skinLoc = Locator(skin), skullLoc = Locator(skull);
  double worstSkin = 0, worstSkull = 0;
  for (auto n : mesh.nodeSets.at("skin"))
    worstSkin = std::max(worstSkin, DistanceTo(skinLoc, mesh.nodes[n]));
  // Issue 4: 0.1 mm, measured to the triangles. Skull nodes on the mid-sagittal plane are reported
  // apart: the builder moves any that the plane keeps off the bone to the set `inner`.
  const auto& mid = mesh.nodeSets.at("midsagittal");
  double worstSkullOnPlane = 0;
  std::size_t farOnPlane = 0;
  for (auto n : mesh.nodeSets.at("skull"))
  {
    const double d = DistanceTo(skullLoc, mesh.nodes[n]);
    if (std::binary_search(mid.begin(), mid.end(), n))
    {
      worstSkullOnPlane = std::max(worstSkullOnPlane, d);
      farOnPlane += d >= 0.1;
    }
    else
    {
      worstSkull = std::max(worstSkull, d);
    }
  }
  std::cout << "skin worst " << worstSkin << " mm, skull worst off the plane " << worstSkull << " mm, on the plane "
            << worstSkullOnPlane << " mm (" << farOnPlane << " nodes >= 0.1 mm)\n";
  EXPECT_LT(worstSkin, 0.1);
  EXPECT_LT(worstSkull, 0.1);
  EXPECT_LT(worstSkullOnPlane, 0.1);
  EXPECT_EQ(farOnPlane, 0u);
  // Sets: skin = outer face, skull + inner = inner face, disjoint; most inner nodes follow the bone.
  const auto& sk = mesh.nodeSets.at("skull");
  const auto& in = mesh.nodeSets.at("inner");
  EXPECT_EQ(sk.size() + in.size(), mesh.nodeSets.at("skin").size());
  std::vector<std::int32_t> both;
  std::set_intersection(sk.begin(), sk.end(), in.begin(), in.end(), std::back_inserter(both));
  EXPECT_TRUE(both.empty());
  // About half the inner face follows the bone (the rest: mouth, orbits, cheeks over the oral
  // cavity, nose, and bone nearer than the minimum thickness).
  EXPECT_GT(sk.size(), 2 * in.size() / 5);
}

// Muscles: every named muscle on both sides; each point inside a hexahedron (found by VTK's cell
// locator) and its stored embedding reproduces the point.
TEST(AtlasShipped, MusclesEmbeddedInsideTheMesh)
{
  const auto& mesh = Shipped();
  for (const auto& m : kMuscles)
  {
    EXPECT_TRUE(mesh.muscles.count(m + "_L")) << m;
    EXPECT_TRUE(mesh.muscles.count(m + "_R")) << m;
    EXPECT_TRUE(mesh.elementSets.count(m + "_L")) << m;
  }
  auto grid = SolidGrid(mesh);
  auto locator = vtkSmartPointer<vtkCellLocator>::New();
  locator->SetDataSet(grid);
  locator->BuildLocator();
  auto cell = vtkSmartPointer<vtkGenericCell>::New();
  for (const auto& [name, track] : mesh.muscles)
  {
    ASSERT_GE(track.nodes.size(), 3u) << name;
    ASSERT_EQ(track.embedding.size(), track.nodes.size()) << name;
    for (std::size_t k = 0; k < track.nodes.size(); ++k)
    {
      const Eigen::Vector3d p = mesh.nodes[track.nodes[k]];
      double x[3] = {p.x(), p.y(), p.z()}, pc[3], w[8];
      const vtkIdType found = locator->FindCell(x, 1e-9, cell, pc, w);
      EXPECT_GE(found, 0) << name << " point " << k << " is outside the mesh";
      const auto& e = track.embedding[k];
      ASSERT_GE(e.element, 0);
      grid->GetCell(e.element, cell);
      double closest[3], pcoords[3], d2;
      int sub;
      const int inside = cell->EvaluatePosition(x, closest, sub, pcoords, d2, w);
      EXPECT_EQ(inside, 1) << name << " point " << k << " not in its embedding element";
      double back[3];
      double stored[3] = {e.pcoords[0], e.pcoords[1], e.pcoords[2]};
      cell->EvaluateLocation(sub, stored, back, w);
      EXPECT_LT((Eigen::Vector3d(back[0], back[1], back[2]) - p).norm(), 1e-6) << name << " point " << k;
    }
  }
}

// Landmarks: the five control points, in order, on the skin, in anatomically consistent places;
// the shipped .mrk.json holds the same points.
TEST(AtlasShipped, LandmarksOnTheSkin)
{
  const auto& mesh = Shipped();
  const std::vector<std::string> names{"LeftEyeInnerCorner", "LeftEyeOuterCorner", "LeftLipCorner", "UpperLipCenter",
                                       "LowerLipCenter"};
  ASSERT_EQ(mesh.landmarks.size(), names.size());
  auto skin = mmrep::ReadSurface(kAtlasDir + "/FaceAtlasSkin.vtp");
  auto loc = Locator(skin);
  for (std::size_t k = 0; k < names.size(); ++k)
  {
    EXPECT_EQ(mesh.landmarks[k].name, names[k]);
    EXPECT_LT(DistanceTo(loc, mesh.landmarks[k].position), 0.1) << names[k];
  }
  const auto file = mmrep::ReadLandmarks(kAtlasDir + "/FaceAtlasLandmarks.mrk.json");
  ASSERT_EQ(file.size(), names.size());
  for (std::size_t k = 0; k < names.size(); ++k)
  {
    EXPECT_EQ(file[k].name, names[k]);
    EXPECT_LT((file[k].position - mesh.landmarks[k].position).norm(), 1e-6) << names[k];
  }
  const auto plane = MidsagittalPlane(mesh);
  auto lateral = [&](std::size_t k) { return plane.normal.dot(mesh.landmarks[k].position - plane.point); };
  const auto& P = [&](std::size_t k) { return mesh.landmarks[k].position; };
  EXPECT_NEAR(lateral(3), 0, 1e-6); // lip centres on the plane
  EXPECT_NEAR(lateral(4), 0, 1e-6);
  EXPECT_GT(P(3).z(), P(4).z());          // upper lip above lower lip (LPS z superior)
  EXPECT_GT(lateral(0), 5);               // eye corners on the left
  EXPECT_GT(lateral(1), lateral(0) + 15); // outer corner lateral of the inner one (eye width)
  EXPECT_LT(lateral(1), lateral(0) + 45);
  EXPECT_GT(lateral(2), 15); // mouth half-width
  EXPECT_LT(lateral(2), 35);
  EXPECT_GT(P(0).z(), P(3).z() + 30);                      // eyes well above the mouth
  EXPECT_NEAR(P(2).z(), 0.5 * (P(3).z() + P(4).z()), 8.0); // mouth corner near the lip line
}

// The lips set: skin nodes of both lips and the mouth corners, symmetric, a few hundred nodes.
TEST(AtlasShipped, LipsSet)
{
  const auto& mesh = Shipped();
  const auto& lips = mesh.nodeSets.at("lips");
  const auto& skin = mesh.nodeSets.at("skin");
  EXPECT_GE(lips.size(), 200u);
  EXPECT_LE(lips.size(), 800u);
  EXPECT_TRUE(std::includes(skin.begin(), skin.end(), lips.begin(), lips.end()));
  // Contains the lip landmarks' neighbourhood: the nearest skin node of each lip landmark is a lips node.
  for (std::size_t k : {2u, 3u, 4u})
  {
    std::int32_t best = -1;
    for (auto n : skin)
      if (best < 0 ||
          (mesh.nodes[n] - mesh.landmarks[k].position).norm() < (mesh.nodes[best] - mesh.landmarks[k].position).norm())
        best = n;
    EXPECT_TRUE(std::binary_search(lips.begin(), lips.end(), best)) << mesh.landmarks[k].name;
  }
}

// Solver formats: .inp (CalculiX/Abaqus), .feb, .msh carry the layers and muscles as sets.
TEST(AtlasShipped, ExportsToSolverFormats)
{
  const auto& mesh = Shipped();
  mmrep::testing::ScratchDirectory dir("atlas-export");
  for (const std::string ext : {"inp", "feb", "msh"})
  {
    const std::string path = dir / ("atlas." + ext);
    mmrep::WriteFEMesh(mesh, path);
    const std::string text = mmrep::testing::Slurp(path);
    for (const std::string set : {"layer_epidermis", "layer_dermis", "layer_hypodermis", "muscle_ZygomaticusMajor_L",
                                  "muscle_OrbicularisOrisPeripheralisUpper_R", "lips", "skull", "midsagittal"})
      EXPECT_NE(text.find(set), std::string::npos) << ext << " lacks " << set;
  }
  // .inp: one C3D8 line per hexahedron.
  std::ifstream inp(dir / "atlas.inp");
  std::size_t hexLines = 0;
  bool inHex = false;
  for (std::string line; std::getline(inp, line);)
  {
    if (!line.empty() && line[0] == '*')
    {
      inHex = line.find("C3D8") != std::string::npos;
      continue;
    }
    hexLines += inHex ? 1 : 0;
  }
  EXPECT_EQ(hexLines, mesh.SolidElementCount());
}
