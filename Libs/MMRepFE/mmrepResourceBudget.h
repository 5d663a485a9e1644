// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Memory budget: what an input's header or a parameter would make a module allocate is checked
// before the allocation, so a 4 kB file declaring 2048^3 voxels, or a grid spacing of 1e-6 mm,
// is refused at once with a line naming the file or parameter instead of exhausting the machine.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mmrep
{

// Bytes one input or grid may need: half the physical memory, and half the address-space limit
// when one is set (ulimit -v).
std::uint64_t MemoryBudgetBytes();

// counts[0] x counts[1] x ... x bytesPerItem, computed in floating point so that no product can
// wrap around (a derived size of 1e30 stays 1e30). Throws std::runtime_error
// "<what> <a x b x c> <items>, <N> GiB: more than the memory budget of <B> GiB …" when over the
// budget or not finite; returns the bytes otherwise.
double CheckMemoryNeed(const std::string& what, const std::vector<double>& counts, double bytesPerItem,
                       const std::string& items = "voxels");

// A VTK XML file (.vtu, .vtp) declares its point and cell counts in <Piece> attributes before the
// data, which may be compressed: the counts are read from the text and checked against the budget
// (`bytesPerPoint`, `bytesPerCell`: what the reader and our copy keep per item). Throws
// std::runtime_error naming the file.
void CheckVTKXMLCounts(const std::string& path, double bytesPerPoint, double bytesPerCell);

} // namespace mmrep
