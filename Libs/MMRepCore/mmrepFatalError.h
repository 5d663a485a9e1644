// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Errors that cannot unwind: a callback from a C library that must not return (Xlib's handler of a
// lost display connection). The run's owner (the CLI framework) installs a handler that says why in
// its one line, removes what the run staged and ends the process; without one, the line is printed
// and the process ends with exit code 1.
#pragma once

#include <functional>
#include <string>

namespace mmrep
{

// The handler must not return (it ends the process); if it does, FatalError ends it.
void SetFatalErrorHandler(std::function<void(const std::string& message)> handler);

[[noreturn]] void FatalError(const std::string& message);

} // namespace mmrep
