// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Whether the disk a file is written to has no free block left: a writer that failed there failed for that.
#pragma once

#include <string>

namespace mmrep
{
// True when the file system holding `path` (a file, written or not, or a folder) has no block left for
// unprivileged writes. False when it cannot tell (the folder is gone, a file system without block counts).
bool DiskFull(const std::string& path);

// " (no space left on the device)" when DiskFull(path), else " (is the disk full?)": the end of a message
// about a write that failed.
std::string WriteFailureReason(const std::string& path);
} // namespace mmrep
