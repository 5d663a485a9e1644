// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The Examples/ pipeline program and the FaceModelPipeline module, each run once on the bundled CT
// and its control points with the shipped atlas: the two models are the same mesh (every node
// within 1e-9 mm, the same elements, layers, sets, muscle tracks and cables, landmarks).
#include "mmrepFEMeshIO.h"
#include "mmrepModuleRunner.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

namespace
{
namespace fs = std::filesystem;

TEST(Examples, PipelineModelEqualsFaceModelPipeline)
{
  const fs::path work = fs::temp_directory_path() / ("mmrep-example-" + std::to_string(::getpid()));
  fs::remove_all(work);
  fs::create_directories(work);
  const std::string ct = std::string(MMREP_SAMPLE_DATA) + "/cthead.nrrd";
  const std::string points = std::string(MMREP_SAMPLE_DATA) + "/cthead.ControlPoints.mrk.json";
  const std::string atlas = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu";

  const auto module =
    mmrep::testing::RunModuleExecutable("FaceModelPipeline", {ct, points, "--atlas", atlas, "--outputDirectory",
                                                              (work / "module").string(), "--noPictures"});
  ASSERT_EQ(module.exitCode, 0) << module.err;
  const auto example = mmrep::testing::RunModuleExecutable("FaceModelPipelineExample",
                                                           {ct, points, atlas, (work / "example.vtu").string()});
  ASSERT_EQ(example.exitCode, 0) << example.err;
  EXPECT_NE(example.out.find("MuscleInferenceFilter: 100%"), std::string::npos) << example.out;
  EXPECT_FALSE(fs::exists(work / "example.vtu.partial.vtu"));

  const auto a = mmrep::ReadFEMesh((work / "module" / "model.vtu").string());
  const auto b = mmrep::ReadFEMesh((work / "example.vtu").string());
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  double worst = 0;
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    worst = std::max(worst, (a.nodes[i] - b.nodes[i]).norm());
  EXPECT_LE(worst, 1e-9) << "largest node difference (mm)";
  std::cout << "largest node difference: " << worst << " mm over " << a.nodes.size() << " nodes" << std::endl;
  // The models moved away from the atlas (built from this CT, so R is near the identity): the
  // comparison is not of two copies of the input.
  const auto input = mmrep::ReadFEMesh(atlas);
  ASSERT_EQ(input.nodes.size(), a.nodes.size());
  double moved = 0;
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    moved = std::max(moved, (input.nodes[i] - a.nodes[i]).norm());
  std::cout << "largest node displacement from the atlas: " << moved << " mm" << std::endl;
  EXPECT_GT(moved, 0.1);

  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (std::size_t i = 0; i < a.elements.size(); ++i)
  {
    EXPECT_EQ(a.elements[i].type, b.elements[i].type) << i;
    EXPECT_EQ(a.elements[i].nodes, b.elements[i].nodes) << i;
    EXPECT_EQ(a.elements[i].layer, b.elements[i].layer) << i;
  }
  EXPECT_EQ(a.nodeSets, b.nodeSets);
  EXPECT_EQ(a.elementSets, b.elementSets);
  ASSERT_EQ(a.muscles.size(), b.muscles.size());
  ASSERT_GT(a.muscles.size(), 0u);
  for (const auto& [name, track] : a.muscles)
  {
    ASSERT_TRUE(b.muscles.count(name)) << name;
    const auto& other = b.muscles.at(name);
    EXPECT_EQ(track.nodes, other.nodes) << name;
    EXPECT_EQ(track.cables, other.cables) << name;
    ASSERT_EQ(track.embedding.size(), other.embedding.size()) << name;
    for (std::size_t k = 0; k < track.embedding.size(); ++k)
    {
      EXPECT_EQ(track.embedding[k].element, other.embedding[k].element) << name << " point " << k;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(track.embedding[k].pcoords[c], other.embedding[k].pcoords[c], 1e-9) << name << " point " << k;
    }
  }
  ASSERT_EQ(a.landmarks.size(), b.landmarks.size());
  for (std::size_t i = 0; i < a.landmarks.size(); ++i)
  {
    EXPECT_EQ(a.landmarks[i].name, b.landmarks[i].name);
    EXPECT_LE((a.landmarks[i].position - b.landmarks[i].position).norm(), 1e-9) << a.landmarks[i].name;
  }
  fs::remove_all(work);
}

} // namespace
