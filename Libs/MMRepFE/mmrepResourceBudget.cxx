// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepResourceBudget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace mmrep
{

std::uint64_t MemoryBudgetBytes()
{
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
  std::uint64_t budget =
    pages > 0 && pageSize > 0 ? static_cast<std::uint64_t>(pages) * pageSize / 2 : std::uint64_t(1) << 32;
  rlimit limit{};
  for (int resource : {RLIMIT_AS, RLIMIT_DATA})
    if (::getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur / 2 < budget)
      budget = limit.rlim_cur / 2;
  return budget;
}

double CheckMemoryNeed(const std::string& what, const std::vector<double>& counts, double bytesPerItem,
                       const std::string& items)
{
  double bytes = bytesPerItem;
  std::string shape;
  for (double c : counts)
  {
    bytes *= c;
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", c);
    shape += (shape.empty() ? "" : " x ") + std::string(text);
  }
  const double budget = static_cast<double>(MemoryBudgetBytes());
  if (!(bytes <= budget)) // also refuses NaN
  {
    char text[160];
    const double gib = bytes / 1073741824.0;
    std::snprintf(text, sizeof text,
                  gib < 1000 ? ", %.3g GiB: more than the memory budget of %.3g GiB"
                             : ", %.3e GiB: more than the memory budget of %.3g GiB",
                  gib, budget / 1073741824.0);
    throw std::runtime_error(what + " " + shape + " " + items + text + " (half of the memory or of ulimit -v)");
  }
  return bytes;
}

void CheckVTKXMLCounts(const std::string& path, double bytesPerPoint, double bytesPerCell)
{
  std::ifstream file(path, std::ios::binary);
  std::string head(1 << 16, '\0');
  file.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(file.gcount()));
  if (const auto appended = head.find("<AppendedData"); appended != std::string::npos)
    head.resize(appended);
  double points = 0, cells = 0;
  static const std::regex count(R"re((NumberOf(?:Points|Cells|Polys|Strips|Lines|Verts))\s*=\s*"\s*([^"]*)")re");
  for (std::sregex_iterator it(head.begin(), head.end(), count), end; it != end; ++it)
  {
    const std::string value = (*it)[2];
    char* stop = nullptr;
    const double n = std::strtod(value.c_str(), &stop);
    if (stop == value.c_str() || !(n >= 0))
      throw std::runtime_error("'" + path + "': " + (*it)[1].str() + "=\"" + value + "\" is not a count");
    ((*it)[1] == "NumberOfPoints" ? points : cells) += n;
  }
  try
  {
    CheckMemoryNeed("the file declares", {points}, bytesPerPoint, "points");
    CheckMemoryNeed("the file declares", {cells}, bytesPerCell, "cells");
  }
  catch (const std::exception& e)
  {
    throw std::runtime_error("'" + path + "': " + e.what());
  }
}

} // namespace mmrep
