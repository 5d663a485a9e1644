// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepEmbedding.h"

#include <vtkHexahedron.h>
#include <vtkTetra.h>
#include <vtkWedge.h>

#include <stdexcept>
#include <string>

namespace mmrep
{

std::vector<double> ShapeFunctions(ElementType type, const std::array<double, 3>& pcoords)
{
  std::vector<double> w(static_cast<std::size_t>(NodeCount(type)));
  switch (type)
  {
    case ElementType::Hexahedron:
      vtkHexahedron::InterpolationFunctions(pcoords.data(), w.data());
      break;
    case ElementType::Wedge:
      vtkWedge::InterpolationFunctions(pcoords.data(), w.data());
      break;
    case ElementType::Tetrahedron:
      vtkTetra::InterpolationFunctions(pcoords.data(), w.data());
      break;
    default:
      throw std::invalid_argument("shape functions are defined for solid elements only");
  }
  return w;
}

Point3 EmbeddedPosition(const FEMesh& mesh, const Embedding& embedding)
{
  if (embedding.element < 0 || static_cast<std::size_t>(embedding.element) >= mesh.elements.size())
    throw std::invalid_argument("embedding element " + std::to_string(embedding.element) + " does not exist");
  const Element& e = mesh.elements[static_cast<std::size_t>(embedding.element)];
  if (e.type == ElementType::Cable)
    throw std::invalid_argument("embedding element " + std::to_string(embedding.element) + " is not a solid");
  const std::vector<double> weights = ShapeFunctions(e.type, embedding.pcoords);
  Point3 x = Point3::Zero();
  for (int i = 0; i < NodeCount(e.type); ++i)
    x +=
      weights[static_cast<std::size_t>(i)] * mesh.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(i)])];
  return x;
}

std::size_t FollowEmbeddings(FEMesh& mesh, const std::vector<Point3>& before)
{
  std::vector<char> inSolid(mesh.nodes.size(), 0);
  for (const Element& e : mesh.elements)
    if (e.type != ElementType::Cable)
      for (int k = 0; k < NodeCount(e.type); ++k)
        inSolid[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])] = 1;
  std::size_t moved = 0;
  for (auto& [name, muscle] : mesh.muscles)
    for (std::size_t k = 0; k < muscle.nodes.size() && k < muscle.embedding.size(); ++k)
    {
      const auto node = static_cast<std::size_t>(muscle.nodes[k]);
      const Embedding& embedding = muscle.embedding[k];
      if (inSolid[node] || embedding.element < 0 ||
          static_cast<std::size_t>(embedding.element) >= mesh.elements.size() ||
          mesh.elements[static_cast<std::size_t>(embedding.element)].type == ElementType::Cable)
        continue;
      const Element& e = mesh.elements[static_cast<std::size_t>(embedding.element)];
      bool changed = false;
      for (int i = 0; i < NodeCount(e.type); ++i)
      {
        const auto n = static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(i)]);
        changed = changed || mesh.nodes[n] != before[n];
      }
      if (!changed)
        continue;
      const Point3 x = EmbeddedPosition(mesh, embedding);
      moved += x != mesh.nodes[node];
      mesh.nodes[node] = x;
    }
  return moved;
}

} // namespace mmrep
