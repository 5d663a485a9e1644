// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The solid elements around each node of an FE mesh (compressed rows), as the repair walks them.
#pragma once

#include "mmrepFEMesh.h"

#include <cstddef>
#include <vector>

namespace mmrep
{

struct NodeElements
{
  explicit NodeElements(const FEMesh& mesh);
  // Solid elements of node i: adjacent[offsets[i]] .. adjacent[offsets[i + 1] - 1], ascending, each once.
  std::vector<std::size_t> offsets, adjacent;

  bool InSolid(std::size_t node) const { return offsets[node] != offsets[node + 1]; }
};

} // namespace mmrep
