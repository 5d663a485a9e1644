// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Sliding of the face tissue on the maxilla (see the header).
#include "mmrepBoneSliding.h"

#include "mmrepBoundaryFaces.h"
#include "mmrepHalfModel.h"
#include "mmrepJaw.h"

#include <algorithm>

namespace mmrep::simulation
{
namespace
{
bool AllIn(const BoundaryFace& face, const std::vector<char>& mask)
{
  for (int k = 0; k < face.NodeCount(); ++k)
    if (!mask[static_cast<std::size_t>(face.nodes[static_cast<std::size_t>(k)])])
      return false;
  return true;
}
} // namespace

std::vector<std::int32_t> BoneAnchorNodes(const FEMesh& mesh)
{
  if (!mesh.nodeSets.count(kMaxillaSet))
    return {};
  const std::vector<char> maxilla = NodeSetMask(mesh, kMaxillaSet);
  std::vector<char> anchor(mesh.nodes.size(), 0);
  // The edge of the modelled region: side faces, where the model is cut out of a larger face.
  const std::vector<char> skin = NodeSetMask(mesh, "skin"), symmetry = NodeSetMask(mesh, kSymmetryBoundarySet);
  std::vector<char> deep = NodeSetMask(mesh, "skull"), slit = NodeSetMask(mesh, "upperLipContact");
  const std::vector<char> inner = NodeSetMask(mesh, "inner"), lower = NodeSetMask(mesh, "lowerLipContact");
  for (std::size_t i = 0; i < deep.size(); ++i)
  {
    deep[i] = deep[i] || inner[i];
    slit[i] = slit[i] || lower[i];
  }
  for (const BoundaryFace& face : BoundaryFaces(mesh))
  {
    if (AllIn(face, skin) || AllIn(face, deep) || AllIn(face, slit) || AllIn(face, symmetry))
      continue;
    for (int k = 0; k < face.NodeCount(); ++k)
      anchor[static_cast<std::size_t>(face.nodes[static_cast<std::size_t>(k)])] = 1;
  }
  // The muscles' bone origins: the solids holding the end points of every track.
  for (const auto& [name, track] : mesh.muscles)
    for (std::size_t i : {std::size_t{0}, track.embedding.size() - 1})
      if (i < track.embedding.size() && track.embedding[i].element >= 0)
      {
        const auto& e = mesh.elements[static_cast<std::size_t>(track.embedding[i].element)];
        for (int k = 0; k < NodeCount(e.type); ++k)
          anchor[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])] = 1;
      }
  std::vector<std::int32_t> out;
  for (std::size_t i = 0; i < anchor.size(); ++i)
    if (anchor[i] && maxilla[i])
      out.push_back(static_cast<std::int32_t>(i));
  return out;
}

std::vector<SlidingNode> BoneSlidingNodes(const FEMesh& mesh)
{
  if (!mesh.nodeSets.count(kMaxillaSet))
    return {};
  const std::vector<std::int32_t> anchors = BoneAnchorNodes(mesh);
  const auto normals = SurfaceNodeNormals(mesh, "skull");
  std::vector<SlidingNode> out;
  for (auto n : mesh.nodeSets.at(kMaxillaSet))
  {
    const auto it = normals.find(n);
    if (it == normals.end() || std::binary_search(anchors.begin(), anchors.end(), n))
      continue;
    out.push_back({n, it->second, true});
  }
  return out;
}

} // namespace mmrep::simulation
