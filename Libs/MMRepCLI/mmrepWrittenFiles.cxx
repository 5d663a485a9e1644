// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// A written output is checked before it is published: writers that meet a full disk often return as if
// all went well (buffered streams, MetaIO, libpng), so the file is judged by what is on the disk: not
// empty, its format's last record present, and the device not left without a free block. The staging
// names of outputs are replaced by the names the user gave in every message.
#include "mmrepCLIInternal.h"
#include "mmrepDiskSpace.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>

namespace fs = std::filesystem;

namespace mmrep::cli
{
namespace
{
std::mutex namesMutex;
std::map<std::string, std::string>& StagedNames()
{
  static std::map<std::string, std::string> names; // staged path -> the path the user gave
  return names;
}

std::string Tail(const fs::path& path, std::size_t bytes)
{
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (!in || ec)
    return {};
  const auto n = static_cast<std::uintmax_t>(std::min<std::uintmax_t>(size, bytes));
  in.seekg(static_cast<std::streamoff>(size - n));
  std::string tail(static_cast<std::size_t>(n), '\0');
  in.read(tail.data(), static_cast<std::streamsize>(n));
  return tail;
}

bool EndsWithToken(const fs::path& path, const std::string& token)
{
  std::string tail = Tail(path, 4096);
  while (!tail.empty() && std::isspace(static_cast<unsigned char>(tail.back())))
    tail.pop_back();
  return tail.size() >= token.size() && tail.compare(tail.size() - token.size(), token.size(), token) == 0;
}

// What the format's last record must be; empty when the format has none to check here (the volume and
// surface writers of MMRepIO check their own formats by reading them back).
std::string MissingEnd(const fs::path& staged, const std::string& ext)
{
  if (ext == ".vtu" || ext == ".vtp" || ext == ".vti" || ext == ".vts")
    return EndsWithToken(staged, "</VTKFile>") ? "" : "its closing </VTKFile>";
  if (ext == ".feb")
    return EndsWithToken(staged, "</febio_spec>") ? "" : "its closing </febio_spec>";
  if (ext == ".html")
    return EndsWithToken(staged, "</html>") ? "" : "its closing </html>";
  if (ext == ".svg")
    return EndsWithToken(staged, "</svg>") ? "" : "its closing </svg>";
  if (ext == ".msh")
  {
    std::string tail = Tail(staged, 256);
    while (!tail.empty() && std::isspace(static_cast<unsigned char>(tail.back())))
      tail.pop_back();
    const auto line = tail.find_last_of('\n');
    return tail.compare(line == std::string::npos ? 0 : line + 1, 4, "$End") == 0 ? "" : "its closing $End… section";
  }
  if (ext == ".png")
  {
    static const std::string iend("\0\0\0\0IEND\xAE\x42\x60\x82", 12);
    return Tail(staged, 12) == iend ? "" : "its IEND chunk";
  }
  if (ext == ".json" || ext == ".mrk.json")
  {
    std::ifstream in(staged, std::ios::binary);
    return nlohmann::json::accept(in) ? "" : "a complete JSON document";
  }
  return {};
}
} // namespace

void NameStagedPath(const std::string& staged, const std::string& shown)
{
  std::lock_guard<std::mutex> lock(namesMutex);
  StagedNames()[staged] = shown;
}

void RemoveStagedOutputs()
{
  std::vector<std::string> staged;
  {
    std::lock_guard<std::mutex> lock(namesMutex);
    for (const auto& entry : StagedNames())
      staged.push_back(entry.first);
  }
  for (const auto& path : staged)
  {
    std::error_code ec;
    fs::remove_all(path, ec); // best effort: published outputs are no longer at their staging name
  }
}

std::string WithShownNames(std::string text)
{
  std::lock_guard<std::mutex> lock(namesMutex);
  // Longest first, so a staged folder's name does not cut the name of a file staged inside it.
  std::vector<std::pair<std::string, std::string>> names(StagedNames().begin(), StagedNames().end());
  std::sort(names.begin(), names.end(), [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
  for (const auto& [staged, shown] : names)
    for (std::size_t at; !staged.empty() && (at = text.find(staged)) != std::string::npos;)
      text.replace(at, staged.size(), shown);
  return text;
}

void CheckWrittenFile(const std::string& staged, const std::string& shown)
{
  const fs::path path(staged);
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    return; // a folder output is checked file by file by its owner
  const auto size = fs::file_size(path, ec);
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  // A write that met a full disk leaves no free block behind it: the file may be cut anywhere.
  if (DiskFull(folder.string()))
    throw ModuleError("cannot write '" + shown + "': the disk is full (no space left in '" +
                      WithShownNames(folder.string()) + "')");
  if (ec || size == 0)
    throw ModuleError("cannot write '" + shown + "': nothing was written (is the disk full?)");
  if (const std::string missing = MissingEnd(path, FileExtension(shown)); !missing.empty())
    throw ModuleError("cannot write '" + shown + "': the file is cut short, " + missing +
                      " is missing (is the disk full?)");
}

void CheckWrittenFolder(const std::string& staged, const std::string& shown)
{
  std::error_code ec;
  std::vector<fs::path> files;
  for (fs::recursive_directory_iterator it(staged, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec))
      files.push_back(it->path());
  std::sort(files.begin(), files.end()); // the first culprit named is the same on every run
  for (const fs::path& f : files)
    CheckWrittenFile(f.string(), (fs::path(shown) / fs::relative(f, staged, ec)).string());
}

} // namespace mmrep::cli
