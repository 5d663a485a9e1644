// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFatalError.h"

#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace mmrep
{
namespace
{
std::mutex mutex;
std::function<void(const std::string&)>& Handler()
{
  static std::function<void(const std::string&)> handler;
  return handler;
}
} // namespace

void SetFatalErrorHandler(std::function<void(const std::string& message)> handler)
{
  std::lock_guard<std::mutex> lock(mutex);
  Handler() = std::move(handler);
}

void FatalError(const std::string& message)
{
  std::function<void(const std::string&)> handler;
  {
    std::lock_guard<std::mutex> lock(mutex);
    handler = Handler();
  }
  if (handler)
    handler(message);
  std::fprintf(stderr, "error: %s\n", message.c_str());
  std::fflush(stderr);
  std::_Exit(1);
}

} // namespace mmrep
