// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Files shipped with the modules, found relative to the module's own shared library (dladdr), so
// that an installed or relocated tree works without any absolute path compiled in.
#include "mmrepCLI.h"

#include <dlfcn.h>

#include <filesystem>

namespace mmrep::cli
{

std::string ModuleResourcePath(const std::string& relativePath)
{
  namespace fs = std::filesystem;
  Dl_info info{};
  // This function is linked into each module's library: its address names that library.
  if (::dladdr(reinterpret_cast<void*>(&ModuleResourcePath), &info) == 0 || info.dli_fname == nullptr)
    throw ModuleError("cannot locate the module's library to find '" + relativePath + "'");
  std::error_code ec;
  fs::path library = fs::canonical(info.dli_fname, ec);
  if (ec)
    library = fs::absolute(info.dli_fname);
  return (library.parent_path() / relativePath).lexically_normal().string();
}

} // namespace mmrep::cli
