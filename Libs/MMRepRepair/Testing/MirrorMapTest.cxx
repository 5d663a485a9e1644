// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The mirror map stored in the FE model (FEMesh::mirror, written by the atlas builder): on the
// shipped atlas it is an involution of mirror images about the fitted mid-sagittal plane, it
// survives the .vtu and .vtk formats, and the repair moving mirror partners by it gives the same
// bytes as its geometric fallback (the pairing it replaced, kept for meshes without a map).
#include "mmrepAtlasTangles.h"
#include "mmrepFEMeshIO.h"
#include "mmrepHalfModel.h"
#include "mmrepMeshRepair.h"
#include "mmrepPlane.h"

#include <gtest/gtest.h>

#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <filesystem>
#include <set>

namespace
{
using namespace mmrep;

const FEMesh& Atlas()
{
  static const FEMesh atlas = ReadFEMesh(MMREP_SOURCE_DIR "/Resources/Atlas/FaceAtlas.vtu");
  return atlas;
}

TEST(MirrorMap, ShippedAtlasPairsMirrorImages)
{
  const FEMesh& atlas = Atlas();
  ASSERT_TRUE(atlas.HasMirrorMap());
  ASSERT_EQ(atlas.mirror.size(), atlas.nodes.size());
  const Plane plane = FitPlaneToNodeSet(atlas, "midsagittal");
  std::set<std::int32_t> self;
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < atlas.nodes.size(); ++i)
  {
    const auto j = static_cast<std::size_t>(atlas.mirror[i]);
    ASSERT_LT(j, atlas.nodes.size());
    ASSERT_EQ(atlas.mirror[j], static_cast<std::int32_t>(i)) << "not an involution at node " << i;
    // The atlas is built exactly symmetric in its local frame: world mirror images to rounding.
    ASSERT_LT((plane.Mirror(atlas.nodes[i]) - atlas.nodes[j]).norm(), 1e-9) << "node " << i << " <-> " << j;
    if (j == i)
      self.insert(static_cast<std::int32_t>(i));
    else
      ++pairs;
  }
  // Nodes on the plane are exactly the mid-sagittal set (grid column 0, its mouth-slit twins and
  // the muscle points on the midline); every other node (jaw axis included) has a partner.
  const auto& mid = atlas.nodeSets.at("midsagittal");
  EXPECT_EQ(self, std::set<std::int32_t>(mid.begin(), mid.end()));
  EXPECT_EQ(pairs + self.size(), atlas.nodes.size());
  const auto& axis = atlas.nodeSets.at("jawAxis");
  ASSERT_EQ(axis.size(), 2u);
  EXPECT_EQ(atlas.mirror[static_cast<std::size_t>(axis[0])], axis[1]);
  // Muscle tracks: point k of <muscle>_L mirrors point k of <muscle>_R.
  for (const auto& [name, track] : atlas.muscles)
    if (name.size() > 2 && name.compare(name.size() - 2, 2, "_L") == 0)
    {
      const auto& right = atlas.muscles.at(name.substr(0, name.size() - 2) + "_R").nodes;
      ASSERT_EQ(right.size(), track.nodes.size()) << name;
      for (std::size_t k = 0; k < right.size(); ++k)
        EXPECT_EQ(atlas.mirror[static_cast<std::size_t>(track.nodes[k])], right[k]) << name << " point " << k;
    }
}

TEST(MirrorMap, SurvivesWriteAndRead)
{
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mmrep-mirror-map-test";
  std::filesystem::create_directories(dir);
  for (const char* name : {"atlas.vtu", "atlas.vtk"})
  {
    WriteFEMesh(Atlas(), (dir / name).string());
    const FEMesh back = ReadFEMesh((dir / name).string());
    EXPECT_EQ(back.mirror, Atlas().mirror) << name;
  }
  // A map that is no involution is refused on reading, with the reason.
  auto grid = ToVTK(Atlas());
  auto* array = grid->GetPointData()->GetArray("MMRep.Mirror");
  ASSERT_NE(array, nullptr);
  array->SetComponent(0, 0, Atlas().mirror[5]);
  try
  {
    FromVTK(grid);
    ADD_FAILURE() << "a broken mirror map was accepted";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("mirror map"), std::string::npos) << e.what();
  }
  // A half model has no mirror partners left: it carries no map.
  EXPECT_FALSE(LeftHalfModel(Atlas()).HasMirrorMap());
  std::filesystem::remove_all(dir);
}

TEST(MirrorMap, RepairByStoredMapEqualsGeometricPairing)
{
  static const auto c = mmrep::testing::LoadTangleContext(MMREP_SOURCE_DIR "/Resources/Atlas/FaceAtlas.vtu",
                                                          MMREP_SOURCE_DIR "/Resources/Atlas/FaceAtlasSkin.vtp",
                                                          MMREP_SOURCE_DIR "/Resources/Atlas/FaceAtlasSkull.vtp");
  ASSERT_TRUE(c.mesh.HasMirrorMap());
  FEMesh stored = mmrep::testing::TangleMesh(c, mmrep::testing::RandomTangle(2));
  ASSERT_TRUE(stored.HasMirrorMap());
  FEMesh geometric = stored;
  geometric.mirror.clear(); // as a file written before the map existed
  const RepairReport a = RepairMesh(stored, mmrep::testing::TangleRepairOptions(c));
  const RepairReport b = RepairMesh(geometric, mmrep::testing::TangleRepairOptions(c));
  EXPECT_TRUE(a.symmetricPairs);
  EXPECT_TRUE(b.symmetricPairs);
  EXPECT_GT(a.movedNodes, 0u);
  EXPECT_EQ(a.movedNodes, b.movedNodes);
  ASSERT_EQ(stored.nodes.size(), geometric.nodes.size());
  for (std::size_t i = 0; i < stored.nodes.size(); ++i)
    ASSERT_TRUE(std::equal(stored.nodes[i].data(), stored.nodes[i].data() + 3, geometric.nodes[i].data()))
      << "node " << i;
  // A map that does not pair mirror images about the given plane (here: the plane moved) is not
  // trusted: the nodes move one by one, as for any asymmetric input.
  FEMesh shifted = mmrep::testing::TangleMesh(c, mmrep::testing::RandomTangle(2));
  RepairOptions options = mmrep::testing::TangleRepairOptions(c);
  options.symmetryPlane.point += 0.5 * options.symmetryPlane.normal;
  EXPECT_FALSE(RepairMesh(shifted, options).symmetricPairs);
}

} // namespace
