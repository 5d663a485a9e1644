// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFEMesh.h"

#include <numeric>
#include <stdexcept>
#include <string>

namespace mmrep
{

int NodeCount(ElementType type)
{
  switch (type)
  {
    case ElementType::Cable:
      return 2;
    case ElementType::Tetrahedron:
      return 4;
    case ElementType::Hexahedron:
      return 8;
    case ElementType::Wedge:
      return 6;
  }
  throw std::invalid_argument("unknown element type " + std::to_string(static_cast<int>(type)));
}

const char* ElementTypeName(ElementType type)
{
  switch (type)
  {
    case ElementType::Cable:
      return "cable";
    case ElementType::Tetrahedron:
      return "tetrahedron";
    case ElementType::Hexahedron:
      return "hexahedron";
    case ElementType::Wedge:
      return "wedge";
  }
  return "unknown";
}

const char* TissueLayerName(TissueLayer layer)
{
  switch (layer)
  {
    case TissueLayer::None:
      return "none";
    case TissueLayer::Epidermis:
      return "epidermis";
    case TissueLayer::Dermis:
      return "dermis";
    case TissueLayer::Hypodermis:
      return "hypodermis";
  }
  return "unknown";
}

std::size_t FEMesh::SolidElementCount() const
{
  std::size_t n = 0;
  for (const auto& e : elements)
    n += e.type != ElementType::Cable;
  return n;
}

std::vector<std::int32_t> FEMesh::SolidElementsOfLayer(TissueLayer layer) const
{
  std::vector<std::int32_t> ids;
  for (std::size_t i = 0; i < elements.size(); ++i)
    if (elements[i].type != ElementType::Cable && elements[i].layer == layer)
      ids.push_back(static_cast<std::int32_t>(i));
  return ids;
}

void FEMesh::SetMirrorPartners(std::int32_t a, std::int32_t b)
{
  if (mirror.empty())
    return;
  const std::size_t known = mirror.size();
  if (known < nodes.size())
  {
    mirror.resize(nodes.size());
    std::iota(mirror.begin() + static_cast<std::ptrdiff_t>(known), mirror.end(), static_cast<std::int32_t>(known));
  }
  mirror.at(static_cast<std::size_t>(a)) = b;
  mirror.at(static_cast<std::size_t>(b)) = a;
}

void FEMesh::Validate() const
{
  const auto nodeCount = static_cast<std::int64_t>(nodes.size());
  const auto elementCount = static_cast<std::int64_t>(elements.size());
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (!nodes[i].allFinite())
      throw std::invalid_argument("node " + std::to_string(i) + " has a non-finite coordinate");
  for (std::size_t i = 0; i < elements.size(); ++i)
  {
    const auto& e = elements[i];
    const int n = NodeCount(e.type);
    for (int k = 0; k < n; ++k)
      if (e.nodes[k] < 0 || e.nodes[k] >= nodeCount)
        throw std::invalid_argument("element " + std::to_string(i) + " refers to node " + std::to_string(e.nodes[k]) +
                                    " of " + std::to_string(nodeCount));
  }
  if (!mirror.empty() && mirror.size() != nodes.size())
    throw std::invalid_argument("mirror map has " + std::to_string(mirror.size()) + " entries for " +
                                std::to_string(nodes.size()) + " nodes");
  for (std::size_t i = 0; i < mirror.size(); ++i)
    if (mirror[i] < 0 || mirror[i] >= nodeCount ||
        mirror[static_cast<std::size_t>(mirror[i])] != static_cast<std::int32_t>(i))
      throw std::invalid_argument("mirror map: node " + std::to_string(i) + " has partner " +
                                  std::to_string(mirror[i]) + " whose partner is not node " + std::to_string(i));
  for (const auto& [name, ids] : nodeSets)
    for (auto id : ids)
      if (id < 0 || id >= nodeCount)
        throw std::invalid_argument("node set '" + name + "' refers to node " + std::to_string(id));
  for (const auto& [name, ids] : elementSets)
    for (auto id : ids)
      if (id < 0 || id >= elementCount)
        throw std::invalid_argument("element set '" + name + "' refers to element " + std::to_string(id));
  for (const auto& [name, m] : muscles)
  {
    for (auto id : m.nodes)
      if (id < 0 || id >= nodeCount)
        throw std::invalid_argument("muscle '" + name + "' refers to node " + std::to_string(id));
    if (!m.cables.empty() && m.cables.size() + 1 != m.nodes.size())
      throw std::invalid_argument("muscle '" + name + "' has " + std::to_string(m.cables.size()) + " cables for " +
                                  std::to_string(m.nodes.size()) + " points");
    for (std::size_t k = 0; k < m.cables.size(); ++k)
    {
      const auto c = m.cables[k];
      if (c < 0 || c >= elementCount || elements[c].type != ElementType::Cable || elements[c].nodes[0] != m.nodes[k] ||
          elements[c].nodes[1] != m.nodes[k + 1])
        throw std::invalid_argument("muscle '" + name + "' cable " + std::to_string(k) +
                                    " does not join its track points");
    }
    if (!m.embedding.empty() && m.embedding.size() != m.nodes.size())
      throw std::invalid_argument("muscle '" + name + "' embedding size differs from its points");
    for (const auto& emb : m.embedding)
      if (emb.element < 0 || emb.element >= elementCount || elements[emb.element].type == ElementType::Cable)
        throw std::invalid_argument("muscle '" + name + "' is embedded in a non-solid element");
  }
}

void FEMesh::UpdateLayerSets()
{
  for (auto layer : {TissueLayer::Epidermis, TissueLayer::Dermis, TissueLayer::Hypodermis})
  {
    auto ids = SolidElementsOfLayer(layer);
    if (ids.empty())
      elementSets.erase(TissueLayerName(layer));
    else
      elementSets[TissueLayerName(layer)] = std::move(ids);
  }
}

} // namespace mmrep
