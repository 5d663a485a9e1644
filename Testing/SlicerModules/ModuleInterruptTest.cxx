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

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

extern char** environ;

namespace
{
namespace fs = std::filesystem;
using mmrep::testing::Slurp;

const std::string kSampleData = MMREP_SAMPLE_DATA;

// Starts build/bin/<module> with TMPDIR set, reads its stdout until a line contains `trigger`,
// then sends `signal`; returns the exit code (128 + signal number when killed by it), stdout and stderr.
struct Interrupted
{
  int exitCode = -1;
  bool triggered = false;
  std::string out, err;
};

// How the run is interrupted beyond the trigger and signal: `environment` entries are added to the
// child's environment; when `waitForFile` is given the signal is sent only once that file exists (a
// stand-in child's sign of life); `target` receives the signal instead of the module (its X server).
struct Interruption
{
  std::vector<std::string> environment;
  fs::path waitForFile;
  pid_t target = 0;
};

Interrupted RunAndInterrupt(const std::string& module, const std::vector<std::string>& args, const fs::path& tmpdir,
                            const std::string& trigger, int signal, const Interruption& how = {})
{
  const fs::path errFile = fs::temp_directory_path() / ("mmrep-interrupt-stderr-" + std::to_string(::getpid()));
  int fds[2];
  EXPECT_EQ(::pipe(fds), 0);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  std::vector<std::string> strings = {std::string(MMREP_BINARY_DIR) + "/bin/" + module};
  strings.insert(strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : strings)
    argv.push_back(s.data());
  argv.push_back(nullptr);
  std::vector<std::string> env = {"TMPDIR=" + tmpdir.string()};
  env.insert(env.end(), how.environment.begin(), how.environment.end());
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
      for (int i = 0; !how.waitForFile.empty() && !fs::exists(how.waitForFile) && i < 600; ++i)
        ::usleep(50000);
      ::kill(how.target > 0 ? how.target : pid, signal);
    }
  }
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 256 + WTERMSIG(status); // 256+: died of it
  result.err = Slurp(errFile);
  fs::remove(errFile);
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

// An X server of the test's own (Xvfb), stopped at the end of the scope.
class XServer
{
public:
  XServer()
  {
    number_ = 300 + ::getpid() % 20000;
    while (fs::exists("/tmp/.X11-unix/X" + std::to_string(number_)) ||
           fs::exists("/tmp/.X" + std::to_string(number_) + "-lock"))
      ++number_;
    const std::string display = ":" + std::to_string(number_);
    std::string xvfb = "Xvfb", screen = "-screen", zero = "0", size = "2560x1600x24", nolisten = "-nolisten",
                tcp = "tcp", shown = display;
    char* argv[] = {xvfb.data(), shown.data(),    screen.data(), zero.data(),
                    size.data(), nolisten.data(), tcp.data(),    nullptr};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    EXPECT_EQ(::posix_spawnp(&pid_, "Xvfb", &actions, nullptr, argv, environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    for (int i = 0; i < 200 && !fs::exists("/tmp/.X11-unix/X" + std::to_string(number_)); ++i)
      ::usleep(50000);
  }
  ~XServer() { Stop(); }
  std::string Display() const { return ":" + std::to_string(number_); }
  pid_t Pid() const { return pid_; }
  void Stop()
  {
    if (pid_ > 0)
    {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
      pid_ = -1;
    }
  }

private:
  int number_ = 0;
  pid_t pid_ = -1;
};

// Pictures are rendered after the model is staged (progress 0.87–0.95): a signal then is handled
// like one at any other time.
TEST(ModuleInterrupt, FaceModelPipelineStopsOnSIGTERMWhilePicturesAreRendered)
{
  const fs::path dir = FreshFolder("pictures");
  XServer x;
  const auto run =
    RunAndInterrupt("FaceModelPipeline",
                    {kSampleData + "/cthead.nrrd", kSampleData + "/cthead.ControlPoints.mrk.json", "--outputDirectory",
                     (dir / "speaker").string()},
                    dir / "tmp", "<filter-progress>0.87</filter-progress>", SIGTERM, {{"DISPLAY=" + x.Display()}});
  ASSERT_TRUE(run.triggered) << run.out << run.err;
  EXPECT_EQ(run.exitCode, 143) << run.err;
  EXPECT_EQ(run.err, "FaceModelPipeline: interrupted by SIGTERM, nothing written\n");
  EXPECT_EQ(Entries(dir), (std::vector<std::string>{"tmp"}));
  fs::remove_all(dir);
}

// The X server ending while the pictures are rendered (xvfb-run stopped, a closed session): VTK
// would abort the process and leave the staging folder; the run ends with one line, nothing left.
TEST(ModuleInterrupt, FaceModelPipelineEndsCleanlyWhenItsXServerEndsDuringThePictures)
{
  const fs::path dir = FreshFolder("xserver");
  XServer x;
  const auto run = RunAndInterrupt("FaceModelPipeline",
                                   {kSampleData + "/cthead.nrrd", kSampleData + "/cthead.ControlPoints.mrk.json",
                                    "--outputDirectory", (dir / "speaker").string()},
                                   dir / "tmp", "<filter-progress>0.87</filter-progress>", SIGTERM,
                                   {{"DISPLAY=" + x.Display()}, {}, x.Pid()});
  ASSERT_TRUE(run.triggered) << run.out << run.err;
  EXPECT_EQ(run.exitCode, 1) << run.err;
  EXPECT_NE(run.err.find("FaceModelPipeline: error: the X display '" + x.Display() + "' closed"), std::string::npos)
    << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_EQ(run.err.find(".partial-"), std::string::npos) << run.err;
  EXPECT_EQ(Entries(dir), (std::vector<std::string>{"tmp"}));
  fs::remove_all(dir);
}

// A CalculiX that ignores SIGTERM (a hung solver) must not outlive the module nor keep it running.
TEST(ModuleInterrupt, SimulateMuscleActivationKillsAHungCalculiX)
{
  const fs::path dir = FreshFolder("hung");
  const fs::path ccx = dir / "hung-ccx.sh", pidFile = dir / "ccx.pid";
  std::ofstream(ccx) << "#!/bin/sh\ntrap '' TERM\necho $$ > '" << pidFile.string() << ".new'\nmv '" << pidFile.string()
                     << ".new' '" << pidFile.string() << "'\nwhile :; do :; done\n";
  fs::permissions(ccx, fs::perms::owner_all);
  const std::string atlas = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu";
  const auto start = std::chrono::steady_clock::now();
  const auto run = RunAndInterrupt(
    "SimulateMuscleActivation", {atlas, (dir / "smile.vtu").string(), "--muscles", "ZygomaticusMajor_L"}, dir / "tmp",
    "<filter-progress>0.1</filter-progress>", SIGTERM, {{"MMREP_CCX=" + ccx.string()}, pidFile});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(run.triggered) << run.out;
  EXPECT_EQ(run.exitCode, 143) << run.out;
  EXPECT_LT(seconds, 60.0);
  pid_t pid = 0;
  std::ifstream(pidFile) >> pid;
  ASSERT_GT(pid, 0);
  EXPECT_NE(::kill(pid, 0), 0) << "the hung ccx " << pid << " survived the module";
  fs::remove(ccx);
  fs::remove(pidFile);
  EXPECT_EQ(Entries(dir), (std::vector<std::string>{"tmp"}));
  fs::remove_all(dir);
}

} // namespace
