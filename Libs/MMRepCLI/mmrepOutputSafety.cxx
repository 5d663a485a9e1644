// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Output safety of a module run: no output may be, contain or lie inside an input, no two outputs
// may share a path, and outputs are published together only once the whole run succeeded.
//
// Which parameters are outputs comes from the XML: channel="output", an output <directory>, the
// return-parameter file. Parameters without a channel (a `string` naming a report or an optional
// input) are checked when the module opens them as an output (AtomicOutput, an output folder).
#include "mmrepCLIInternal.h"

#include <filesystem>
#include <mutex>
#include <optional>
#include <set>
#include <system_error>
#include <unistd.h>

namespace fs = std::filesystem;

namespace mmrep::cli
{
namespace
{
enum class Role
{
  Input,
  Output,
  Unknown // no channel: the module says what it is by opening it
};

struct PathParameter
{
  std::string description; // "'skinMask' (--skinMask)"
  std::string value;       // as given
  fs::path resolved;       // absolute, symlinks resolved where they exist
  Role role;
};

struct Publication
{
  std::string finalPath;
  std::function<void()> publish, discard;
  bool evenOnFailure;
};

struct RunState
{
  bool active = false;
  std::vector<PathParameter> paths;
  std::vector<fs::path> outputs; // opened so far, resolved
  std::vector<Publication> pending;
};

std::mutex mutex;
RunState state;

fs::path Resolve(const std::string& path)
{
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec)
    p = fs::absolute(path, ec).lexically_normal();
  // "out/" and "out" are one path.
  if (p.has_filename() == false && p.has_parent_path())
    p = p.parent_path();
  return p;
}

// True when `inner` lies strictly inside the folder `outer`.
bool IsInside(const fs::path& inner, const fs::path& outer)
{
  auto o = outer.begin(), i = inner.begin();
  for (; o != outer.end(); ++o, ++i)
    if (i == inner.end() || *i != *o)
      return false;
  return i != inner.end();
}

bool IsDirectory(const fs::path& p)
{
  std::error_code ec;
  return fs::is_directory(p, ec);
}

bool PathLike(const Parameter& p)
{
  static const std::set<std::string> tags = {"file",  "directory", "image",     "geometry", "transform",
                                             "table", "pointfile", "pointlist", "string"};
  return tags.count(p.tag) && !p.multiple;
}

Role RoleOf(const Parameter& p)
{
  if (p.channel == "input")
    return Role::Input;
  if (p.channel == "output" || p.tag == "directory")
    return Role::Output;
  return Role::Unknown;
}

// "input 'x' (--x)", "output 'y' (argument 2)", "'z' (--z)" (no channel), "the return parameter file (…)".
std::string Named(const PathParameter& p)
{
  if (p.description.rfind("the ", 0) == 0 || p.role == Role::Unknown)
    return p.description;
  return (p.role == Role::Input ? "input " : "output ") + p.description;
}

// Refuses `output` (a file, or a folder when `folder`) that is, contains or lies inside another
// parameter's path. `self` is the parameter naming it, when known.
void CheckAgainstParameters(const fs::path& output, const std::string& culprit, bool folder, const PathParameter* self)
{
  bool selfSeen = self != nullptr;
  for (const PathParameter& q : state.paths)
  {
    if (&q == self)
      continue;
    if (q.resolved == output)
    {
      if (!selfSeen && q.role != Role::Input) // the parameter naming this output itself
      {
        selfSeen = true;
        continue;
      }
      throw ModuleError(culprit + " and " + Named(q) + " are the same path '" + q.value + "'; give each its own");
    }
    if (folder && IsInside(q.resolved, output))
      throw ModuleError(culprit + " is a folder that holds " + Named(q) + " ('" + q.value +
                        "'), which the results would replace; choose another folder");
    if (q.role == Role::Input && IsInside(output, q.resolved) && IsDirectory(q.resolved))
      throw ModuleError(culprit + " lies inside the input folder " + q.description + " ('" + q.value +
                        "'); write the results elsewhere");
  }
}

// A known output's folder must exist and be writable before any work (a folder output is created).
void CheckWritableFolder(const PathParameter& p, bool folder)
{
  if (folder)
    return;
  const fs::path parent = p.resolved.parent_path();
  if (!IsDirectory(parent))
    throw ModuleError(p.description + ": cannot write '" + p.value + "': folder '" + parent.string() +
                      "' does not exist");
  if (::access(parent.c_str(), W_OK) != 0)
    throw ModuleError(p.description + ": cannot write '" + p.value + "': folder '" + parent.string() +
                      "' is not writable");
}
} // namespace

namespace detail
{
void BeginOutputTransaction(const ModuleDescription& description,
                            const std::map<std::string, std::vector<std::string>>& values,
                            const std::string& returnParameterFile)
{
  std::lock_guard<std::mutex> lock(mutex);
  state = RunState{};
  state.active = true;
  std::vector<const Parameter*> folders;
  for (const Parameter& p : description.parameters)
  {
    const auto it = values.find(p.name);
    if (!PathLike(p) || it == values.end() || it->second.empty() || it->second.front().empty())
      continue;
    state.paths.push_back({Describe(p), it->second.front(), Resolve(it->second.front()), RoleOf(p)});
    folders.push_back(p.tag == "directory" ? &p : nullptr);
  }
  if (!returnParameterFile.empty())
  {
    state.paths.push_back({"the return parameter file (--returnparameterfile)", returnParameterFile,
                           Resolve(returnParameterFile), Role::Output});
    folders.push_back(nullptr);
  }
  for (std::size_t i = 0; i < state.paths.size(); ++i)
  {
    const PathParameter& p = state.paths[i];
    if (p.role == Role::Input)
      continue;
    // An unknown-role parameter equal to an input is refused too: it may be an output (a report).
    for (std::size_t j = 0; j < state.paths.size(); ++j)
    {
      const PathParameter& q = state.paths[j];
      if (j == i || q.resolved != p.resolved || (p.role == Role::Unknown && q.role == Role::Unknown))
        continue;
      throw ModuleError(Named(p) + " and " + Named(q) + " are the same path '" + p.value + "'; give each its own");
    }
    if (p.role == Role::Output)
    {
      CheckAgainstParameters(p.resolved, Named(p), folders[i] != nullptr, &p);
      CheckWritableFolder(p, folders[i] != nullptr);
    }
  }
}

void PublishOutputs()
{
  std::vector<Publication> pending;
  {
    std::lock_guard<std::mutex> lock(mutex);
    pending.swap(state.pending);
    state = RunState{};
  }
  for (std::size_t i = 0; i < pending.size(); ++i)
  {
    try
    {
      pending[i].publish();
    }
    catch (...)
    {
      for (std::size_t k = i + 1; k < pending.size(); ++k)
        pending[k].discard();
      throw;
    }
  }
}

void DiscardOutputs()
{
  std::vector<Publication> pending;
  {
    std::lock_guard<std::mutex> lock(mutex);
    pending.swap(state.pending);
    state = RunState{};
  }
  for (Publication& p : pending)
  {
    try
    {
      if (p.evenOnFailure)
        p.publish();
      else
        p.discard();
    }
    catch (...) // the run already failed: its own error is the one to report
    {
    }
  }
}
} // namespace detail

void CheckOutputPath(const std::string& path, bool folder)
{
  std::lock_guard<std::mutex> lock(mutex);
  if (!state.active)
    return;
  const fs::path resolved = Resolve(path);
  for (const fs::path& o : state.outputs)
    if (o == resolved)
      throw ModuleError("two outputs are the same path '" + path + "'; give each its own");
  // Parameters without a channel are known as outputs only now: two naming this path (an input
  // and this output, or two outputs) are refused, naming both.
  std::vector<const PathParameter*> naming;
  for (const PathParameter& q : state.paths)
    if (q.resolved == resolved)
      naming.push_back(&q);
  if (naming.size() > 1)
    throw ModuleError(naming[0]->description + " and " + naming[1]->description + " are the same path '" + path +
                      "', which this run writes; give each its own");
  const PathParameter* self = naming.empty() ? nullptr : naming.front();
  CheckAgainstParameters(resolved, self ? "output " + self->description : "output '" + path + "'", folder, self);
  state.outputs.push_back(resolved);
}

bool DeferPublication(const std::string& finalPath, std::function<void()> publish, std::function<void()> discard,
                      bool evenOnFailure)
{
  std::lock_guard<std::mutex> lock(mutex);
  if (!state.active)
    return false;
  state.pending.push_back({finalPath, std::move(publish), std::move(discard), evenOnFailure});
  return true;
}

} // namespace mmrep::cli
