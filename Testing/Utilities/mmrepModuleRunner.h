// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Test helper: runs a module executable from build/bin and captures what a user would see.
#pragma once

#include <unistd.h>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace mmrep::testing
{

struct ModuleRun
{
  int exitCode = -1;
  std::string out; // stdout
  std::string err; // stderr
  std::vector<std::string> ErrLines() const
  {
    std::vector<std::string> lines;
    std::istringstream s(err);
    for (std::string l; std::getline(s, l);)
      if (!l.empty())
        lines.push_back(l);
    return lines;
  }
};

inline std::string Quote(const std::string& s)
{
  std::string q = "'";
  for (char c : s)
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline std::string Slurp(const std::filesystem::path& p)
{
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// Runs build/bin/<module> with the arguments (each quoted), optionally under xvfb-run when there
// is no X display and the module renders pictures.
inline ModuleRun RunModuleExecutable(const std::string& module, const std::vector<std::string>& args,
                                     bool needsDisplay = false)
{
  namespace fs = std::filesystem;
  static int counter = 0;
  const fs::path dir =
    fs::temp_directory_path() / ("mmrep-run-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::create_directories(dir);
  std::string cmd;
  const char* display = std::getenv("DISPLAY");
  if (needsDisplay && (display == nullptr || *display == '\0'))
    // Our own auth file: xvfb-run then makes no temporary folder, whose cleanup fails now and then
    // when two tests run it at once (ctest -j2). The screen leaves room for several 600-px views.
    // Server numbers searched from one of this process's own: concurrent xvfb-run -a calls that all
    // start at 99 can pick the same free number, and one module then loses its server.
    cmd = "xvfb-run -a -n " + std::to_string(100 + ::getpid() % 20000) + " -f " + Quote((dir / "Xauthority").string()) +
          " -s \"-screen 0 2560x1600x24 -noreset\" ";
  cmd += Quote(std::string(MMREP_BINARY_DIR) + "/bin/" + module);
  for (const auto& a : args)
    cmd += " " + Quote(a);
  cmd += " > " + Quote((dir / "out").string()) + " 2> " + Quote((dir / "err").string()) + " < /dev/null";
  ModuleRun run;
  const int status = std::system(cmd.c_str());
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.out = Slurp(dir / "out");
  run.err = Slurp(dir / "err");
  fs::remove_all(dir);
  return run;
}

// Reads a Slicer return parameter file: `name = value` lines.
inline std::map<std::string, std::string> ReadReturnParameters(const std::filesystem::path& file)
{
  std::map<std::string, std::string> values;
  std::istringstream s(Slurp(file));
  for (std::string line; std::getline(s, line);)
  {
    const auto eq = line.find(" = ");
    if (eq != std::string::npos)
      values[line.substr(0, eq)] = line.substr(eq + 3);
  }
  return values;
}

// A comma-separated vector return value ("x,y,z") as numbers.
inline std::vector<double> ReturnVector(const std::map<std::string, std::string>& values, const std::string& name)
{
  std::vector<double> v;
  std::istringstream s(values.at(name));
  for (std::string item; std::getline(s, item, ',');)
    v.push_back(std::stod(item));
  return v;
}

// A PNG picture of some content: the PNG signature and more than 10 kB.
inline bool IsPNG(const std::filesystem::path& path)
{
  const std::string bytes = Slurp(path);
  return bytes.size() > 10000 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

// A fresh empty directory under the system temp folder, removed at the end of the scope.
class ScratchDirectory
{
public:
  explicit ScratchDirectory(const std::string& name)
  {
    static int counter = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("mmrep-" + name + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  std::vector<std::string> Entries() const
  {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_))
      names.push_back(e.path().filename().string());
    return names;
  }

private:
  std::filesystem::path path_;
};

} // namespace mmrep::testing
