// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepNodeElements.h"

#include <numeric>

namespace mmrep
{

NodeElements::NodeElements(const FEMesh& mesh)
{
  auto solid = [](const Element& e) { return e.type != ElementType::Cable; };
  const std::size_t n = mesh.nodes.size();
  offsets.assign(n + 1, 0);
  for (const Element& e : mesh.elements)
    if (solid(e))
      for (int k = 0; k < NodeCount(e.type); ++k)
        ++offsets[e.nodes[k] + 1];
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  adjacent.assign(offsets.back(), 0);
  std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) // ascending element ids per node
    if (solid(mesh.elements[e]))
      for (int k = 0; k < NodeCount(mesh.elements[e].type); ++k)
      {
        const auto node = static_cast<std::size_t>(mesh.elements[e].nodes[k]);
        if (fill[node] == offsets[node] || adjacent[fill[node] - 1] != e) // a node listed twice in one element
          adjacent[fill[node]++] = e;
      }
  // Nodes listed twice in an element leave unused slots: compact.
  std::vector<std::size_t> compact;
  std::vector<std::size_t> newOffsets(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (std::size_t k = offsets[i]; k < fill[i]; ++k)
      compact.push_back(adjacent[k]);
    newOffsets[i + 1] = compact.size();
  }
  adjacent = std::move(compact);
  offsets = std::move(newOffsets);
}

} // namespace mmrep
