// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Determinism across thread counts: a module run on 1 thread and on 2 threads (ITK's filters and the
// project's own pools both follow ITK_GLOBAL_DEFAULT_NUMBER_OF_THREADS, mmrepWorkerThreads.h) writes
// the same bytes. Reports differ only in their measured times, which are removed before comparing.
#include "mmrepModuleRunner.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

namespace
{
namespace fs = std::filesystem;
using namespace mmrep::testing;

const std::string kSampleData = std::string(MMREP_SOURCE_DIR) + "/Resources/SampleData/";
const std::string kAtlasData = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/";

// Runs the module on `threads` threads inside `dir`; returns the exit code (stderr kept in dir/err).
int RunWithThreads(const fs::path& dir, unsigned threads, const std::string& module,
                   const std::vector<std::string>& args)
{
  fs::create_directories(dir);
  std::string cmd =
    "cd " + Quote(dir.string()) + " && ITK_GLOBAL_DEFAULT_NUMBER_OF_THREADS=" + std::to_string(threads) +
    " OMP_NUM_THREADS=" + std::to_string(threads) + " " + Quote(std::string(MMREP_BINARY_DIR) + "/bin/" + module);
  for (const auto& a : args)
    cmd += " " + Quote(a);
  cmd += " > out 2> err < /dev/null";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// A file's bytes, with a report's measured times taken out.
std::string Comparable(const fs::path& file)
{
  std::string bytes = Slurp(file);
  if (file.extension() == ".json" && file.filename().string().find("report") != std::string::npos)
  {
    nlohmann::json j = nlohmann::json::parse(bytes);
    std::function<void(nlohmann::json&)> strip = [&](nlohmann::json& v) {
      if (v.is_object())
      {
        for (auto it = v.begin(); it != v.end();)
          if (it.key().find("econds") != std::string::npos)
            it = v.erase(it);
          else
            strip(*it++);
      }
      else if (v.is_array())
        for (auto& e : v)
          strip(e);
    };
    strip(j);
    return j.dump();
  }
  if (file.filename() == "report.md")
  {
    bytes = std::regex_replace(bytes, std::regex(R"(Whole pipeline: [0-9.]+ s)"), "");
    bytes = bytes.substr(0, bytes.find("## Time (s)")) +
            bytes.substr(std::min(bytes.size(), bytes.find("\n## ", bytes.find("## Time (s)") + 1)));
  }
  return bytes;
}

// Every output file of the two runs: same names, same bytes (times aside).
void ExpectSameOutputs(const fs::path& one, const fs::path& two, std::size_t atLeast)
{
  std::size_t compared = 0;
  for (const auto& e : fs::recursive_directory_iterator(one))
  {
    const fs::path rel = fs::relative(e.path(), one);
    if (e.is_directory() || rel == "out" || rel == "err")
      continue;
    ASSERT_TRUE(fs::exists(two / rel)) << rel << " written with 1 thread, not with 2";
    EXPECT_TRUE(Comparable(e.path()) == Comparable(two / rel)) << rel << " differs between 1 and 2 threads";
    ++compared;
  }
  EXPECT_GE(compared, atLeast);
}

TEST(Determinism, SkinSkullSurfacesAndAtlasRegistrationOneAndTwoThreads)
{
  ScratchDirectory scratch("determinism-stages");
  const fs::path one = scratch.path() / "1", two = scratch.path() / "2";
  for (const auto& [dir, threads] : {std::pair{one, 1u}, std::pair{two, 2u}})
  {
    ASSERT_EQ(RunWithThreads(dir, threads, "SkinSkullSurfaces",
                             {kSampleData + "cthead.nrrd", "skin.vtp", "skull.vtp", "--skinMask", "skin.nrrd"}),
              0)
      << Slurp(dir / "err");
    ASSERT_EQ(RunWithThreads(dir, threads, "AtlasRegistration",
                             {kAtlasData + "FaceAtlas.vtu", "skin.vtp", "skull.vtp",
                              kSampleData + "cthead.ControlPoints.mrk.json", "registered.vtu", "--outputTransform",
                              "transform.nrrd", "--report", "registration.report.json"}),
              0)
      << Slurp(dir / "err");
  }
  ExpectSameOutputs(one, two, 6);
}

TEST(Determinism, FaceModelPipelineOneAndTwoThreads)
{
  ScratchDirectory scratch("determinism-pipeline");
  const fs::path one = scratch.path() / "1", two = scratch.path() / "2";
  for (const auto& [dir, threads] : {std::pair{one, 1u}, std::pair{two, 2u}})
    ASSERT_EQ(RunWithThreads(dir, threads, "FaceModelPipeline",
                             {kSampleData + "cthead.nrrd", kSampleData + "cthead.ControlPoints.mrk.json",
                              "--outputDirectory", "speaker", "--noPictures"}),
              0)
      << Slurp(dir / "err");
  ExpectSameOutputs(one, two, 10);
}

} // namespace
