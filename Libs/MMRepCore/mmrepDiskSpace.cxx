// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepDiskSpace.h"

#include <filesystem>
#include <sys/statvfs.h>
#include <system_error>

namespace mmrep
{
bool DiskFull(const std::string& path)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path where(path);
  if (!fs::is_directory(where, ec))
    where = where.has_parent_path() ? where.parent_path() : fs::path(".");
  struct statvfs device
  {
  };
  return ::statvfs(where.c_str(), &device) == 0 && device.f_blocks > 0 && device.f_bavail == 0;
}

std::string WriteFailureReason(const std::string& path)
{
  return DiskFull(path) ? " (no space left on the device)" : " (is the disk full?)";
}
} // namespace mmrep
