// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// C libraries under the toolkits (niftilib, libpng) print a failed write on the C stderr and return: while
// such a writer runs, file descriptor 2 goes to /dev/null, so a module still reports the failure in one
// line of its own (the written file is checked instead).
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>

namespace mmrep
{
class SilencedCStandardError
{
public:
  SilencedCStandardError()
  {
    std::fflush(stderr);
    saved_ = ::dup(STDERR_FILENO);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved_ >= 0 && null >= 0)
      ::dup2(null, STDERR_FILENO);
    if (null >= 0)
      ::close(null);
  }
  ~SilencedCStandardError()
  {
    std::fflush(stderr);
    if (saved_ >= 0)
    {
      ::dup2(saved_, STDERR_FILENO);
      ::close(saved_);
    }
  }
  SilencedCStandardError(const SilencedCStandardError&) = delete;
  SilencedCStandardError& operator=(const SilencedCStandardError&) = delete;

private:
  int saved_ = -1;
};
} // namespace mmrep
