// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Reader for the nodal results of CalculiX's ASCII result file (.frd).
//
// Only what a static solve needs: every nodal result block (name such as DISP, its step time and
// per-node values). Blocks in the short (5-digit node) or long (10-digit) ASCII format are read;
// binary .frd files are refused.
#pragma once

#include <Eigen/Core>

#include <istream>
#include <map>
#include <string>
#include <vector>

namespace mmrep::simulation
{

struct FrdBlock
{
  std::string name;                          // e.g. "DISP"
  double time = 0;                           // step time of the block (100CL record)
  int step = 0;                              // step number
  int components = 0;                        // values per node written in the file
  std::map<int, std::vector<double>> values; // node id (as in the deck) -> values
};

// Throws std::runtime_error naming `source` on malformed content.
std::vector<FrdBlock> ReadFrd(std::istream& in, const std::string& source);
std::vector<FrdBlock> ReadFrdFile(const std::string& path);

// The last block with this name (the final increment of a static step), or nullptr.
const FrdBlock* LastBlock(const std::vector<FrdBlock>& blocks, const std::string& name);

} // namespace mmrep::simulation
