// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Helpers shared by the FE I/O tests: fresh scratch folders, exact mesh comparison, running tools.
#pragma once

#include "mmrepFEMesh.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mmrep::testing
{

// An empty folder for the current test under the build tree.
inline std::filesystem::path ScratchDir(const std::string& suite)
{
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::path(MMREP_BINARY_DIR) / "Testing" / suite / info->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string ReadText(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs a shell command with stdout and stderr captured to files; returns the exit status.
struct CommandResult
{
  int status = -1;
  std::string out, err;
};
inline CommandResult Run(const std::string& command, const std::filesystem::path& dir)
{
  const auto outFile = dir / "command.stdout", errFile = dir / "command.stderr";
  const std::string full = command + " > '" + outFile.string() + "' 2> '" + errFile.string() + "'";
  const int raw = std::system(full.c_str());
  CommandResult result;
  result.status = raw == -1 ? -1 : WEXITSTATUS(raw);
  result.out = ReadText(outFile);
  result.err = ReadText(errFile);
  return result;
}

inline bool SameBits(const Point3& a, const Point3& b)
{
  return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0;
}

// Everything must match exactly: bit patterns of doubles, orders, names.
inline void ExpectSameMesh(const FEMesh& expected, const FEMesh& actual)
{
  ASSERT_EQ(expected.nodes.size(), actual.nodes.size());
  for (std::size_t i = 0; i < expected.nodes.size(); ++i)
    EXPECT_TRUE(SameBits(expected.nodes[i], actual.nodes[i])) << "node " << i;
  ASSERT_EQ(expected.elements.size(), actual.elements.size());
  for (std::size_t i = 0; i < expected.elements.size(); ++i)
  {
    const auto &e = expected.elements[i], &a = actual.elements[i];
    EXPECT_EQ(e.type, a.type) << "element " << i;
    EXPECT_EQ(e.layer, a.layer) << "element " << i;
    for (int k = 0; k < NodeCount(e.type); ++k)
      EXPECT_EQ(e.nodes[k], a.nodes[k]) << "element " << i << " node " << k;
  }
  EXPECT_EQ(expected.nodeSets, actual.nodeSets);
  EXPECT_EQ(expected.elementSets, actual.elementSets);
  ASSERT_EQ(expected.muscles.size(), actual.muscles.size());
  for (const auto& [name, m] : expected.muscles)
  {
    ASSERT_EQ(actual.muscles.count(name), 1u) << name;
    const auto& a = actual.muscles.at(name);
    EXPECT_EQ(m.nodes, a.nodes) << name;
    EXPECT_EQ(m.cables, a.cables) << name;
    EXPECT_EQ(m.maximumForce, a.maximumForce) << name;
    ASSERT_EQ(m.embedding.size(), a.embedding.size()) << name;
    for (std::size_t k = 0; k < m.embedding.size(); ++k)
    {
      EXPECT_EQ(m.embedding[k].element, a.embedding[k].element) << name << " " << k;
      EXPECT_EQ(std::memcmp(m.embedding[k].pcoords.data(), a.embedding[k].pcoords.data(), 3 * sizeof(double)), 0)
        << name << " " << k;
    }
  }
  ASSERT_EQ(expected.landmarks.size(), actual.landmarks.size());
  for (std::size_t k = 0; k < expected.landmarks.size(); ++k)
  {
    EXPECT_EQ(expected.landmarks[k].name, actual.landmarks[k].name);
    EXPECT_TRUE(SameBits(expected.landmarks[k].position, actual.landmarks[k].position)) << k;
  }
}

} // namespace mmrep::testing
