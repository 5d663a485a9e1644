// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "FaceModelOutputDirectory.h"

#include "mmrepCLI.h"

#include <system_error>
#include <unistd.h>

namespace fs = std::filesystem;
using mmrep::cli::ModuleError;

FaceModelOutputDirectory::FaceModelOutputDirectory(const std::string& path)
{
  final_ = fs::path(path).lexically_normal();
  if (final_.filename().empty())
    final_ = final_.parent_path();                    // "out/" -> "out"
  mmrep::cli::CheckOutputPath(final_.string(), true); // never over or around an input
  std::error_code ec;
  if (fs::exists(final_, ec) && !fs::is_directory(final_, ec))
    throw ModuleError(final_.string() + ": exists and is not a directory");
  // The folder is replaced as a whole: never the current folder or one around it, never a folder
  // of other files (only an earlier result, recognised by its report).
  const fs::path absolute = fs::absolute(final_, ec).lexically_normal();
  const fs::path around = fs::current_path(ec).lexically_relative(absolute);
  if (!around.empty() && *around.begin() != "..")
    throw ModuleError("--outputDirectory '" + final_.string() +
                      "' is the current folder or holds it: name a new folder for the results (it is replaced "
                      "as a whole)");
  if (fs::is_directory(final_, ec) && !fs::is_empty(final_, ec) && !fs::exists(final_ / "report.md", ec))
    throw ModuleError("--outputDirectory '" + final_.string() +
                      "' holds other files (no report.md of an earlier result): name a new folder for the results "
                      "(it is replaced as a whole)");
  const fs::path parent = final_.has_parent_path() ? final_.parent_path() : fs::path(".");
  for (fs::path p = parent; !p.empty() && !fs::exists(p, ec); p = p.parent_path())
    createdParent_ = p; // the outermost folder this run creates, removed again when nothing is published
  fs::create_directories(parent, ec);
  if (ec)
    throw ModuleError(parent.string() + ": cannot create the output directory's parent (" + ec.message() + ")");
  mmrep::cli::RemoveStaleOutputs(parent.string(), "." + final_.filename().string() + ".partial-");
  mmrep::cli::RemoveStaleOutputs(parent.string(), "." + final_.filename().string() + ".old-");
  staging_ = parent / ("." + final_.filename().string() + ".partial-" + std::to_string(::getpid()));
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec) || ec)
    throw ModuleError(final_.string() + ": cannot create the output directory here (" +
                      (ec ? ec.message() : std::string("unknown error")) + ")");
  mmrep::cli::NameStagedPath(staging_.string(), final_.string());
}

FaceModelOutputDirectory::~FaceModelOutputDirectory()
{
  if (!committed_)
  {
    std::error_code ec;
    fs::remove_all(staging_, ec);
    // Parents this run created, innermost first, while empty.
    for (fs::path p = staging_.parent_path(); !createdParent_.empty() && !p.empty(); p = p.parent_path())
    {
      if (!fs::remove(p, ec) || p == createdParent_)
        break;
    }
  }
}

void FaceModelOutputDirectory::Commit()
{
  // Inside a module run the folder appears only once every step succeeded (return parameters too).
  mmrep::cli::CheckWrittenFolder(staging_.string(), final_.string());
  const fs::path final = final_, staging = staging_;
  committed_ = mmrep::cli::DeferPublication(
    final_.string(), [final, staging] { Publish(final, staging); },
    [staging] {
      std::error_code ec;
      fs::remove_all(staging, ec);
    });
  if (!committed_)
  {
    Publish(final_, staging_);
    committed_ = true;
  }
}

void FaceModelOutputDirectory::Publish(const fs::path& final_, const fs::path& staging_)
{
  std::error_code ec;
  fs::path old;
  if (fs::exists(final_, ec))
  {
    old = final_.parent_path() / ("." + final_.filename().string() + ".old-" + std::to_string(::getpid()));
    fs::rename(final_, old, ec);
    if (ec)
      throw ModuleError(final_.string() + ": cannot replace the existing directory (" + ec.message() + ")");
  }
  fs::rename(staging_, final_, ec);
  if (ec)
  {
    if (!old.empty())
      fs::rename(old, final_, ec);
    throw ModuleError(final_.string() + ": cannot move the results into place");
  }
  if (!old.empty())
    fs::remove_all(old, ec);
}
