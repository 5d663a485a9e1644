// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The executables interrupted as a user (Ctrl-C) or a job system (SIGTERM) does: the run stops at
// its next progress poll with exit code 128 + signal, removes its staging folder and temporary files
// (CalculiX's job folder in $TMPDIR included), leaves the inputs untouched; leftovers of runs that
// died without cleaning up are removed by the next run.
#include "mmrepModuleRunner.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

extern char** environ;

namespace
{
namespace fs = std::filesystem;
using mmrep::testing::Slurp;

const std::string kSampleData = MMREP_SAMPLE_DATA;

// Starts build/bin/<module> with TMPDIR set, reads its stdout until a line contains `trigger`,
// then sends `signal`; returns the exit code (128 + signal number when killed by it) and stdout.
struct Interrupted
{
  int exitCode = -1;
  bool triggered = false;
  std::string out;
};

Interrupted RunAndInterrupt(const std::string& module, const std::vector<std::string>& args, const fs::path& tmpdir,
                            const std::string& trigger, int signal)
{
  int fds[2];
  EXPECT_EQ(::pipe(fds), 0);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  std::vector<std::string> strings = {std::string(MMREP_BINARY_DIR) + "/bin/" + module};
  strings.insert(strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : strings)
    argv.push_back(s.data());
  argv.push_back(nullptr);
  std::vector<std::string> env = {"TMPDIR=" + tmpdir.string()};
  for (char** e = environ; *e; ++e)
    if (std::string(*e).rfind("TMPDIR=", 0) != 0)
      env.emplace_back(*e);
  std::vector<char*> envp;
  for (auto& s : env)
    envp.push_back(s.data());
  envp.push_back(nullptr);
  pid_t pid = -1;
  EXPECT_EQ(::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data()), 0);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  Interrupted result;
  char buffer[4096];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;)
  {
    result.out.append(buffer, static_cast<std::size_t>(n));
    if (!result.triggered && result.out.find(trigger) != std::string::npos)
    {
      result.triggered = true;
      ::kill(pid, signal);
    }
  }
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 256 + WTERMSIG(status); // 256+: died of it
  return result;
}

// A pid that is certainly not running any more.
pid_t DeadPid()
{
  const pid_t pid = ::fork();
  if (pid == 0)
    ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

fs::path FreshFolder(const std::string& name)
{
  const fs::path dir = fs::temp_directory_path() / ("mmrep-interrupt-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "tmp");
  return dir;
}

std::vector<std::string> Entries(const fs::path& dir)
{
  std::vector<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    names.push_back(fs::relative(e.path(), dir).string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ModuleInterrupt, FaceModelPipelineStopsOnSIGTERMAndCleansUp)
{
  const fs::path dir = FreshFolder("pipeline");
  const std::string ct = kSampleData + "/cthead.nrrd", points = kSampleData + "/cthead.ControlPoints.mrk.json";
  const std::string ctBytes = Slurp(ct), pointBytes = Slurp(points);
  // What a killed earlier run left: its staging folder and a half-replaced old result.
  const pid_t dead = DeadPid();
  fs::create_directories(dir / (".speaker.partial-" + std::to_string(dead)));
  std::ofstream(dir / (".speaker.partial-" + std::to_string(dead)) / "model.vtu") << "partial";
  fs::create_directories(dir / (".speaker.old-" + std::to_string(dead)));
  // A live process's staging folder (ours) must not be touched.
  const fs::path live = dir / (".speaker.partial-" + std::to_string(::getpid()) + "-other");
  fs::create_directories(live);

  const auto run =
    RunAndInterrupt("FaceModelPipeline", {ct, points, "--outputDirectory", (dir / "speaker").string(), "--noPictures"},
                    dir / "tmp", "Stage: registration", SIGTERM);
  ASSERT_TRUE(run.triggered) << run.out;
  EXPECT_EQ(run.exitCode, 143) << run.out;
  EXPECT_EQ(run.out.find("Results in"), std::string::npos);
  // Nothing left but the live process's folder and the empty TMPDIR; the inputs untouched.
  EXPECT_EQ(Entries(dir), (std::vector<std::string>{live.filename().string(), "tmp"}));
  EXPECT_EQ(Slurp(ct), ctBytes);
  EXPECT_EQ(Slurp(points), pointBytes);
  fs::remove_all(dir);
}

TEST(ModuleInterrupt, SIGINTStopsAModuleWithExitCode130AndNoOutput)
{
  const fs::path dir = FreshFolder("surfaces");
  // A stale temporary output of a dead run beside the outputs is removed by the next run.
  const fs::path stale = dir / ("skin.mmrep-tmp-" + std::to_string(DeadPid()) + "-0.vtp");
  std::ofstream(stale) << "partial";
  const auto run = RunAndInterrupt(
    "SkinSkullSurfaces", {kSampleData + "/cthead.nrrd", (dir / "skin.vtp").string(), (dir / "skull.vtp").string()},
    dir / "tmp", "<filter-progress>", SIGINT);
  ASSERT_TRUE(run.triggered) << run.out;
  EXPECT_EQ(run.exitCode, 130) << run.out;
  EXPECT_EQ(Entries(dir), (std::vector<std::string>{"tmp"}));
  fs::remove_all(dir);
}

TEST(ModuleInterrupt, SimulateMuscleActivationStopsCalculiXAndRemovesItsJobFolder)
{
  const fs::path dir = FreshFolder("simulation");
  const std::string atlas = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu";
  // 0.1 is reported just before CalculiX starts; the job folder is then in TMPDIR.
  const auto run = RunAndInterrupt("SimulateMuscleActivation",
                                   {atlas, (dir / "smile.vtu").string(), "--muscles", "ZygomaticusMajor_L"},
                                   dir / "tmp", "<filter-progress>0.1</filter-progress>", SIGTERM);
  ASSERT_TRUE(run.triggered) << run.out;
  EXPECT_EQ(run.exitCode, 143) << run.out;
  EXPECT_EQ(Entries(dir), (std::vector<std::string>{"tmp"}));
  fs::remove_all(dir);
}

} // namespace
