// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// All-or-nothing output files: write a temporary sibling, rename it over the final path on success.
#include "mmrepCLIInternal.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace fs = std::filesystem;

namespace mmrep::cli
{

std::string FileExtension(const std::string& path)
{
  const std::string name = detail::Lower(fs::path(path).filename().string());
  // Compound extensions whose last part alone does not say the format.
  for (const char* twoPart : {".nii.gz", ".mrk.json", ".seg.nrrd"})
  {
    const std::string ext = twoPart;
    if (name.size() > ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0)
      return ext;
  }
  const auto dot = name.rfind('.');
  if (dot == std::string::npos || dot == 0)
    return {};
  if (name.compare(dot, std::string::npos, ".gz") == 0) // .vtk.gz, .nrrd.gz, ...
  {
    const auto previous = name.rfind('.', dot - 1);
    if (previous != std::string::npos && previous > 0)
      return name.substr(previous);
  }
  return name.substr(dot);
}

void RemoveStaleOutputs(const std::string& folder, const std::string& prefix)
{
  std::error_code ec;
  for (fs::directory_iterator it(folder.empty() ? "." : folder, ec), end; !ec && it != end; it.increment(ec))
  {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0)
      continue;
    std::size_t digits = prefix.size();
    while (digits < name.size() && name[digits] >= '0' && name[digits] <= '9')
      ++digits;
    if (digits == prefix.size() || (digits < name.size() && name[digits] != '-' && name[digits] != '.'))
      continue;
    const long pid = std::stol(name.substr(prefix.size(), digits - prefix.size()));
    if (pid <= 0 || pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)
      continue;
    std::error_code removeError;
    fs::remove_all(it->path(), removeError); // best effort
  }
}

AtomicOutput::AtomicOutput(std::string finalPath) : final_(std::move(finalPath))
{
  if (final_.empty())
    throw ModuleError("output file name is empty");
  const fs::path target(final_);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw ModuleError("cannot write '" + final_ + "': folder '" + folder.string() + "' does not exist");
  if (::access(folder.c_str(), W_OK) != 0)
    throw ModuleError("cannot write '" + final_ + "': folder '" + folder.string() + "' is not writable");
  if (fs::is_directory(target, ec))
    throw ModuleError("cannot write '" + final_ + "': it is a folder");
  CheckOutputPath(final_, false);

  // Same folder (so the rename is atomic), same extension (so writers pick the same format).
  static std::atomic<unsigned> counter{0};
  const std::string ext = FileExtension(final_);
  const std::string name = target.filename().string();
  const std::string stem = name.substr(0, name.size() - ext.size());
  RemoveStaleOutputs(folder.string(), stem + ".mmrep-tmp-");
  temp_ = (folder / (stem + ".mmrep-tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
                     name.substr(name.size() - ext.size())))
            .string();
  NameStagedPath(temp_, final_);
}

AtomicOutput::~AtomicOutput()
{
  if (!committed_)
  {
    std::error_code ec;
    fs::remove(temp_, ec); // best effort: nothing useful to do if it fails
  }
}

void AtomicOutput::Commit()
{
  Commit(false);
}

void AtomicOutput::CommitEvenIfRunFails()
{
  Commit(true);
}

void AtomicOutput::Commit(bool evenIfRunFails)
{
  if (committed_)
    return;
  std::error_code ec;
  if (!fs::exists(temp_, ec))
    throw ModuleError("cannot write '" + final_ + "': nothing was written");
  CheckWrittenFile(temp_, final_);
  // Inside a module run the rename waits until every step succeeded (mmrepOutputSafety.cxx).
  const std::string temp = temp_, final = final_;
  if (DeferPublication(
        final_,
        [temp, final] {
          std::error_code e;
          fs::rename(temp, final, e);
          if (e)
            throw ModuleError("cannot write '" + final + "': " + e.message());
        },
        [temp] {
          std::error_code e;
          fs::remove(temp, e);
        },
        evenIfRunFails))
  {
    committed_ = true;
    return;
  }
  fs::rename(temp_, final_, ec);
  if (ec)
    throw ModuleError("cannot write '" + final_ + "': " + ec.message());
  committed_ = true;
  detail::OutputCommitted();
}

void AtomicOutput::WriteText(const std::string& text) const
{
  std::ofstream f(temp_, std::ios::binary);
  f << text;
  f.close(); // a full disk shows when the buffer is written out
  if (!f)
    throw ModuleError("cannot write '" + final_ + "' (is the disk full?)");
}

} // namespace mmrep::cli
