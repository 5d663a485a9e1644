// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// File-name helpers shared by the readers and writers (internal to MMRepIO).
#pragma once

#include <algorithm>
#include <cctype>
#include <string>

namespace mmrep
{
namespace io
{

inline std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Case-insensitive suffix test ("Head.NII.GZ" ends with ".nii.gz").
inline bool EndsWith(const std::string& path, const std::string& suffix)
{
  const std::string p = Lower(path);
  const std::string s = Lower(suffix);
  return p.size() >= s.size() && p.compare(p.size() - s.size(), s.size(), s) == 0;
}

// Extension without the dot, lower case, after the last '.' of the file name ("" if none).
inline std::string Extension(const std::string& path)
{
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return {};
  }
  return Lower(path.substr(dot + 1));
}

} // namespace io
} // namespace mmrep
