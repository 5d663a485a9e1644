// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// ccx runner: temporary job folder, live log parsing for progress, convergence checks.
#include "mmrepCalculiXRunner.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace mmrep::simulation
{
namespace fs = std::filesystem;
namespace
{
std::string Quote(const std::string& s)
{
  std::string q = "'";
  for (char c : s)
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

bool IsExecutable(const fs::path& p)
{
  std::error_code ec;
  return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}

// Removes the job folder at the end of the run unless it is to be kept.
class JobDirectory
{
public:
  explicit JobDirectory(bool keep) : keep_(keep)
  {
    std::string pattern = (fs::temp_directory_path() / "mmrep-ccx-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw std::runtime_error("cannot create a temporary folder for CalculiX in " +
                               fs::temp_directory_path().string());
    path_ = pattern;
  }
  ~JobDirectory()
  {
    std::error_code ec;
    if (!keep_)
      fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

private:
  fs::path path_;
  bool keep_;
};
// ccx as a child process whose output is read through a pipe. If the run is left early (an
// exception from the progress callback: an abort), the destructor stops ccx before the job folder
// is removed.
class Child
{
public:
  explicit Child(const std::string& command)
  {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
      throw std::runtime_error("cannot create a pipe for CalculiX");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    std::string shell = "/bin/sh", flag = "-c", cmd = command;
    char* argv[] = {shell.data(), flag.data(), cmd.data(), nullptr};
    const int error = ::posix_spawn(&pid_, "/bin/sh", &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    fd_ = fds[0];
    if (error != 0)
    {
      pid_ = -1;
      throw std::runtime_error("cannot start CalculiX (" + std::string(std::strerror(error)) + ")");
    }
  }
  ~Child()
  {
    if (pid_ > 0)
      Stop();
    if (fd_ >= 0)
      ::close(fd_);
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  int fd() const { return fd_; }
  // SIGTERM, then SIGKILL when ccx has not ended after a grace period (a hung solver ignores
  // nothing but may never reach its next signal check).
  void Stop()
  {
    ::kill(pid_, SIGTERM);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
    int status = 0;
    while (::waitpid(pid_, &status, WNOHANG) == 0)
    {
      if (std::chrono::steady_clock::now() > deadline)
      {
        ::kill(pid_, SIGKILL);
        Wait();
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    pid_ = -1;
  }
  int Wait() // the wait status
  {
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR)
    {
    }
    pid_ = -1;
    return status;
  }

private:
  pid_t pid_ = -1;
  int fd_ = -1;
};
} // namespace

std::string FindCalculiX(const std::string& executable)
{
  std::string wanted = executable;
  if (wanted.empty())
    if (const char* env = std::getenv("MMREP_CCX"); env != nullptr && *env != '\0')
      wanted = env;
  if (!wanted.empty())
  {
    if (wanted.find('/') != std::string::npos)
    {
      if (!IsExecutable(wanted))
        throw std::runtime_error("CalculiX executable '" + wanted + "' does not exist or is not executable");
      return wanted;
    }
  }
  else
    wanted = "ccx";
  if (const char* path = std::getenv("PATH"))
  {
    std::string dirs = path;
    std::size_t start = 0;
    while (start <= dirs.size())
    {
      const std::size_t end = std::min(dirs.find(':', start), dirs.size());
      const fs::path candidate = fs::path(dirs.substr(start, end - start)) / wanted;
      if (end > start && IsExecutable(candidate))
        return candidate.string();
      start = end + 1;
    }
  }
  throw std::runtime_error(
    "CalculiX solver '" + wanted +
    "' not found on PATH: install the Debian package calculix-ccx or set MMREP_CCX to the ccx executable");
}

CalculiXRun RunCalculiX(const std::string& deck, const RunOptions& options)
{
  const std::string ccx = FindCalculiX(options.executable);
  if (options.threads < 1)
    throw std::runtime_error("CalculiX needs at least one thread");
  JobDirectory dir(options.keepDirectory);
  {
    std::ofstream f(dir.path() / "job.inp");
    f << deck;
    if (!f.flush())
      throw std::runtime_error("cannot write the CalculiX deck in " + dir.path().string());
  }
  CalculiXRun run;
  if (options.keepDirectory)
    run.directory = dir.path().string();
  const std::string threads = std::to_string(options.threads);
  // exec: the shell becomes ccx, so that stopping the child stops ccx.
  const std::string cmd = "cd " + Quote(dir.path().string()) + " && OMP_NUM_THREADS=" + threads +
                          " CCX_NPROC_STIFFNESS=" + threads + " CCX_NPROC_EQUATION_SOLVER=" + threads + " exec " +
                          Quote(ccx) + " -i job 2>&1 < /dev/null";
  const auto start = std::chrono::steady_clock::now();
  Child child(cmd);
  double lastFraction = 0;
  char buffer[4096];
  std::string pending;
  bool finished = false;
  int appendNext = 0;
  const auto handleLine = [&](const std::string& line) {
    run.log += line + "\n";
    if (line.find(" iteration ") == 0)
      ++run.iterations;
    else if (line.find("actual step time=") != std::string::npos && options.progress)
    {
      try
      {
        lastFraction = std::stod(line.substr(line.find('=') + 1));
      }
      catch (const std::exception&)
      {
      }
      options.progress(lastFraction);
    }
    else if (line.find("increment size decreased") != std::string::npos ||
             line.find("too slow convergence") != std::string::npos || line.find("divergence") != std::string::npos)
      ++run.cutbacks;
    else if (line.find("Job finished") != std::string::npos)
      finished = true;
    // ccx continues an error message on the following lines, up to an empty line.
    if (appendNext > 0)
    {
      const auto first = line.find_first_not_of(' ');
      if (first == std::string::npos)
        appendNext = 0;
      else
      {
        std::string part = line.substr(first);
        for (std::size_t p; (p = part.find("  ")) != std::string::npos;)
          part.erase(p, 1);
        run.message += " " + part;
        --appendNext;
      }
    }
    if (run.message.empty() && line.find("*ERROR") != std::string::npos)
    {
      run.message = line.substr(line.find("*ERROR"));
      appendNext = 3;
    }
  };
  for (;;)
  {
    // Wake up at least every 0.2 s so the progress callback can abort a long solve.
    pollfd p{child.fd(), POLLIN, 0};
    const int ready = ::poll(&p, 1, 200);
    if (ready < 0 && errno != EINTR)
      break;
    if (ready <= 0)
    {
      if (options.progress)
        options.progress(lastFraction);
      continue;
    }
    const ssize_t n = ::read(child.fd(), buffer, sizeof buffer);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      break;
    pending.append(buffer, static_cast<std::size_t>(n));
    for (std::size_t nl; (nl = pending.find('\n')) != std::string::npos;)
    {
      handleLine(pending.substr(0, nl));
      pending.erase(0, nl + 1);
    }
  }
  if (!pending.empty())
    handleLine(pending);
  const int status = child.Wait();
  if (options.progress) // ccx may have stopped because the run is interrupted (Ctrl-C reaches both)
    options.progress(lastFraction);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  if (run.exitCode == 127)
    throw std::runtime_error("cannot run CalculiX '" + ccx + "' (exit code 127)");

  if (options.keepDirectory)
    std::ofstream(dir.path() / "job.log") << run.log;
  const fs::path frd = dir.path() / "job.frd";
  if (fs::exists(frd))
    run.results = ReadFrdFile(frd.string());
  run.increments = 0;
  for (const auto& b : run.results)
    if (b.name == "DISP")
    {
      ++run.increments;
      run.stepTime = b.time;
    }
  run.converged = run.exitCode == 0 && finished && run.increments > 0 && run.stepTime > 1 - 1e-6;
  const bool solveGaveUp = run.cutbacks > 0 || run.log.find("too many cutbacks") != std::string::npos ||
                           run.log.find("diverge") != std::string::npos;
  run.outcome = run.converged                                 ? CalculiXOutcome::Converged
                : WIFSIGNALED(status)                         ? CalculiXOutcome::Crashed
                : solveGaveUp || run.increments > 0           ? CalculiXOutcome::DidNotConverge
                : run.log.find("*ERROR") != std::string::npos ? CalculiXOutcome::DeckRefused
                                                              : CalculiXOutcome::NoResults;
  if (run.outcome == CalculiXOutcome::Crashed)
    run.message = "CalculiX crashed (" + std::string(::strsignal(WTERMSIG(status))) + ") at step time " +
                  std::to_string(run.stepTime) + (run.message.empty() ? "" : ": " + run.message);
  if (!run.converged && run.message.empty())
  {
    // Last non-empty log line tells what ccx was doing when it stopped.
    std::string last;
    std::size_t end = run.log.size();
    while (last.empty() && end > 0)
    {
      const std::size_t b = run.log.rfind('\n', end - 1);
      const std::size_t from = b == std::string::npos ? 0 : b + 1;
      last = run.log.substr(from, end - from);
      while (!last.empty() && (last.back() == ' ' || last.back() == '\n'))
        last.pop_back();
      last.erase(0, std::min(last.size(), last.find_first_not_of(' ')));
      end = b == std::string::npos ? 0 : b;
    }
    run.message = "CalculiX stopped at step time " + std::to_string(run.stepTime) + " (exit code " +
                  std::to_string(run.exitCode) + "); last log line: " + last;
  }
  if (!run.converged && options.keepDirectory)
    run.message += " (job folder kept: " + run.directory + ")";
  return run;
}

std::string DescribeFailure(const CalculiXRun& run)
{
  switch (run.outcome)
  {
    case CalculiXOutcome::Converged:
      return "";
    case CalculiXOutcome::DidNotConverge:
      return "the CalculiX solve did not converge: " + run.message;
    case CalculiXOutcome::DeckRefused:
      return "CalculiX refused the model's input deck: " + run.message;
    case CalculiXOutcome::Crashed:
      return run.message + " (a fault of the solver, not of the model)";
    case CalculiXOutcome::NoResults:
      break;
  }
  return "CalculiX ended without results (exit code " + std::to_string(run.exitCode) + "): " + run.message;
}

} // namespace mmrep::simulation
