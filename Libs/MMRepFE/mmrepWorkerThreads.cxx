// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepWorkerThreads.h"

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace mmrep
{

unsigned WorkerThreads(unsigned most)
{
  unsigned n = std::thread::hardware_concurrency();
  if (const char* text = std::getenv("ITK_GLOBAL_DEFAULT_NUMBER_OF_THREADS"))
  {
    char* end = nullptr;
    const long v = std::strtol(text, &end, 10);
    if (end != text && *end == '\0' && v > 0)
      n = static_cast<unsigned>(std::min<long>(v, 1 << 16));
  }
  return std::max(1u, std::min(n, std::max(1u, most)));
}

} // namespace mmrep
