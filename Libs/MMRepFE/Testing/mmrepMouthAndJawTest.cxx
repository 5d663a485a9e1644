// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The mouth slit (close / reopen, facing surfaces, lip gap) and the jaw's rotation, on small meshes
// whose answers are known by hand.
#include "mmrepJaw.h"
#include "mmrepLipContact.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using namespace mmrep;

// Two lips of two unit cubes each along x: upper z in [0, 1], lower z in [-1, 0]. The slit z = 0
// runs over x in [0, 2); the nodes at x = 2 (the corner line) are shared, the four others doubled.
FEMesh TwoLips()
{
  FEMesh mesh;
  auto node = [](int x, int y, int z) { return static_cast<std::int32_t>((z + 1) * 6 + y * 3 + x); };
  for (int z = -1; z <= 1; ++z)
    for (int y = 0; y <= 1; ++y)
      for (int x = 0; x <= 2; ++x)
        mesh.nodes.emplace_back(x, y, z);
  std::map<std::int32_t, std::int32_t> twin;
  for (int y = 0; y <= 1; ++y)
    for (int x = 0; x <= 1; ++x)
    {
      twin[node(x, y, 0)] = static_cast<std::int32_t>(mesh.nodes.size());
      mesh.nodes.push_back(mesh.nodes[static_cast<std::size_t>(node(x, y, 0))]);
    }
  for (int z = -1; z <= 0; ++z)
    for (int x = 0; x <= 1; ++x)
    {
      Element e;
      e.type = ElementType::Hexahedron;
      e.layer = TissueLayer::Dermis;
      e.nodes = {node(x, 0, z),     node(x + 1, 0, z),     node(x + 1, 1, z),     node(x, 1, z),
                 node(x, 0, z + 1), node(x + 1, 0, z + 1), node(x + 1, 1, z + 1), node(x, 1, z + 1)};
      if (z == -1)
        for (auto& n : e.nodes)
          if (twin.count(n))
            n = twin[n];
      (z == 0 ? mesh.elementSets[kUpperLipSet] : mesh.elementSets[kLowerLipSet])
        .push_back(static_cast<std::int32_t>(mesh.elements.size()));
      mesh.elements.push_back(e);
    }
  auto& upper = mesh.nodeSets[kUpperLipContactSet];
  auto& lower = mesh.nodeSets[kLowerLipContactSet];
  for (int y = 0; y <= 1; ++y)
    for (int x = 0; x <= 2; ++x)
    {
      upper.push_back(node(x, y, 0));
      lower.push_back(x == 2 ? node(x, y, 0) : twin[node(x, y, 0)]);
    }
  std::sort(upper.begin(), upper.end());
  std::sort(lower.begin(), lower.end());
  return mesh;
}

TEST(MouthSlit, CloseAndReopenKeepTheLipsTogether)
{
  FEMesh mesh = TwoLips();
  ASSERT_TRUE(HasMouthSlit(mesh));
  const auto original = mesh.elements;
  const ClosedMouth closed = CloseMouth(mesh);
  EXPECT_EQ(closed.twins.size(), 4u);
  EXPECT_EQ(closed.slots.size(), 6u); // the lower cubes use 4 + 2 doubled corners
  // Closed: no element uses a twin, and the lower lip's top corners are the upper lip's bottom ones.
  for (const auto& [u, l] : closed.twins)
    for (const auto& e : mesh.elements)
      EXPECT_EQ(std::count(e.nodes.begin(), e.nodes.end(), l), 0);
  EXPECT_EQ(mesh.elements[0].nodes[4], mesh.elements[2].nodes[0]);
  // A stage moves the shared nodes; reopening puts the twins there and restores the connectivity.
  for (auto& p : mesh.nodes)
    p += Point3(0.1 * p.z(), 0.2, 0.05 * p.x());
  ReopenMouth(mesh, closed);
  for (std::size_t e = 0; e < original.size(); ++e)
    EXPECT_EQ(mesh.elements[e].nodes, original[e].nodes) << e;
  for (const auto& [u, l] : closed.twins)
    EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(u)], mesh.nodes[static_cast<std::size_t>(l)]);
}

TEST(MouthSlit, TwinsPairByIndexOrderWhereverTheyAre)
{
  FEMesh mesh = TwoLips();
  mesh.nodes[18].z() -= 0.5; // a twin moved away (a perturbed model): closing and reopening rejoins it
  const ClosedMouth closed = CloseMouth(mesh);
  ASSERT_EQ(closed.twins.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(closed.twins[i].second, static_cast<std::int32_t>(18 + i)); // twins 18..21 with nodes 6, 7, 9, 10
  EXPECT_EQ(closed.twins[0].first, 6);
  EXPECT_EQ(closed.twins[3].first, 10);
  ReopenMouth(mesh, closed);
  EXPECT_EQ(mesh.nodes[18], mesh.nodes[6]);
  FEMesh uneven = TwoLips();
  uneven.nodeSets[kLowerLipContactSet].pop_back();
  EXPECT_THROW(CloseMouth(uneven), std::invalid_argument);
  FEMesh none = TwoLips();
  none.elementSets.erase(kLowerLipSet);
  EXPECT_FALSE(HasMouthSlit(none));
  EXPECT_TRUE(CloseMouth(none).twins.empty());
}

TEST(MouthSlit, FacingSurfacesPointAtEachOther)
{
  const FEMesh mesh = TwoLips();
  for (const bool upperLip : {true, false})
  {
    const auto faces = LipContactFaces(mesh, upperLip);
    ASSERT_EQ(faces.size(), 2u);
    for (const auto& f : faces)
    {
      const auto p = [&](int c) { return mesh.nodes[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(c)])]; };
      const Point3 normal = (p(2) - p(0)).cross(p(3) - p(1));
      for (int c = 0; c < 4; ++c)
        EXPECT_DOUBLE_EQ(p(c).z(), 0.0);
      // Outward: the upper lip's facing surface points down, the lower lip's up.
      EXPECT_NEAR(normal.normalized().z(), upperLip ? -1.0 : 1.0, 1e-12);
      EXPECT_EQ(f.face, upperLip ? 1 : 2); // C3D8 S1 = bottom (nodes 1-2-3-4), S2 = top
    }
  }
}

TEST(MouthSlit, LipGapIsTheSignedSeparation)
{
  const FEMesh mesh = TwoLips();
  std::vector<Point3> u(mesh.nodes.size(), Point3::Zero());
  EXPECT_NEAR(MeasureLipGap(mesh, u).minimum, 0.0, 1e-12);
  // The lower lip's facing nodes 0.5 below: open by 0.5; 0.3 above: 0.3 inside the upper lip.
  for (std::size_t n = 18; n < 22; ++n)
    u[n] = Point3(0, 0, -0.5);
  LipGap g = MeasureLipGap(mesh, u);
  EXPECT_EQ(g.nodes, 4u);
  EXPECT_NEAR(g.minimum, 0.5, 1e-9);
  EXPECT_NEAR(g.mean, 0.5, 1e-9);
  for (std::size_t n = 18; n < 22; ++n)
    u[n] = Point3(0, 0, 0.3);
  g = MeasureLipGap(mesh, u);
  EXPECT_NEAR(g.minimum, -0.3, 1e-9);
  // In front of the upper lip's edge (beyond its rim): not inside it.
  for (std::size_t n = 18; n < 22; ++n)
    u[n] = Point3(0, -1.5, 0.3);
  EXPECT_GT(MeasureLipGap(mesh, u).minimum, 0.0);
}

// Maxilla above z = 0, mandible below z = -1, condyles on the x axis at the origin's height.
FEMesh Jaw()
{
  FEMesh mesh;
  for (double y : {-40.0, -60.0})
    for (double z : {10.0, 20.0})
      mesh.nodes.emplace_back(0, y, z);
  for (double y : {-60.0, -80.0})
    for (double z : {-30.0, -50.0})
      mesh.nodes.emplace_back(0, y, z);
  mesh.nodes.emplace_back(50, 0, 0);
  mesh.nodes.emplace_back(-50, 0, 0);
  mesh.nodeSets[kMaxillaSet] = {0, 1, 2, 3};
  mesh.nodeSets[kMandibleSet] = {4, 5, 6, 7};
  mesh.nodeSets[kJawAxisSet] = {8, 9};
  return mesh;
}

TEST(Jaw, OpeningRotatesTheMandibleAwayFromTheMaxilla)
{
  const FEMesh mesh = Jaw();
  ASSERT_TRUE(HasJaw(mesh));
  const Eigen::Isometry3d open = JawRotation(mesh, 10.0);
  for (int n = 4; n < 8; ++n)
  {
    const Point3 p = mesh.nodes[static_cast<std::size_t>(n)], q = open * p;
    EXPECT_NEAR(q.x(), 0.0, 1e-12);        // about the x axis
    EXPECT_NEAR(q.norm(), p.norm(), 1e-9); // a rotation about the axis through 0
    EXPECT_NEAR(std::acos(p.normalized().dot(q.normalized())) * 180 / M_PI, 10.0, 1e-9);
  }
  // Anterior is -y here: the chin (y < 0, z < 0) moves down and back, away from the maxilla.
  const Point3 chin = mesh.nodes[7], moved = open * chin;
  EXPECT_LT(moved.z(), chin.z());
  EXPECT_GT(moved.y(), chin.y());
  const Eigen::Isometry3d closing = JawRotation(mesh, -5.0);
  EXPECT_GT((closing * chin).z(), chin.z());
  EXPECT_TRUE(JawRotation(mesh, 0.0).isApprox(Eigen::Isometry3d::Identity()));

  FEMesh noJaw = mesh;
  noJaw.nodeSets.erase(kMandibleSet);
  EXPECT_FALSE(HasJaw(noJaw));
  EXPECT_THROW(JawRotation(noJaw, 10.0), std::invalid_argument);
}

} // namespace
