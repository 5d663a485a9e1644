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
  const fs::path parent = final_.has_parent_path() ? final_.parent_path() : fs::path(".");
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
}

FaceModelOutputDirectory::~FaceModelOutputDirectory()
{
  if (!committed_)
  {
    std::error_code ec;
    fs::remove_all(staging_, ec);
  }
}

void FaceModelOutputDirectory::Commit()
{
  // Inside a module run the folder appears only once every step succeeded (return parameters too).
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
