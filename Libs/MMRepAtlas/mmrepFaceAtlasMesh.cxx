// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Steps 5-6 and 8 of the atlas: the left half's nodes through the layers, the mirrored world mesh
// of hexahedra, and its node sets.
#include "mmrepFaceAtlasStages.h"

#include <algorithm>

namespace mmrep
{
namespace
{
// The lips set reaches this far past the lip corner (mm), inside the finer mouth region (6 mm).
constexpr double kLipsPastCorner = 5.0;
} // namespace

void PlaceLeftHalfNodes(const FaceColumns& columns, FaceGrid& grid)
{
  const int rows = grid.Rows(), cols = grid.Cols();
  grid.local.assign(grid.LeftNodeCount(), Eigen::Vector3d::Zero());
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
    {
      const int q = i * cols + j;
      for (int k = 0; k < 4; ++k)
      {
        Eigen::Vector3d p = columns.outer[q] + grid.levels[k] * columns.thickness[q] * columns.dir[q];
        if (j == 0)
          p.x() = 0;
        grid.local[grid.LeftNode(i, j, k)] = p;
      }
    }
}

void WriteNodesFromLeftHalf(const FaceGrid& grid, const FaceFrame& frame, FEMesh& mesh)
{
  const int rows = grid.Rows(), cols = grid.Cols();
  // Nodes on the plane (column 0) are shared: the right half starts at column 1.
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < rows; ++i)
      for (int j = side; j < cols; ++j)
        for (int k = 0; k < 4; ++k)
        {
          Eigen::Vector3d p = grid.local[grid.LeftNode(i, j, k)];
          if (side == 1)
            p.x() = -p.x();
          mesh.nodes[grid.Node(i, j, k, side)] = frame.ToWorld(p);
        }
}

FEMesh MirroredFaceMesh(const FaceGrid& grid, const FaceFrame& frame)
{
  const int rows = grid.Rows(), cols = grid.Cols();
  FEMesh mesh;
  mesh.nodes.resize(grid.LeftNodeCount() + rows * (cols - 1) * 4);
  WriteNodesFromLeftHalf(grid, frame, mesh);
  mesh.mirror = grid.MirrorMap();
  mesh.elements.resize(2 * grid.LeftElementCount());
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i + 1 < rows; ++i)
      for (int j = 0; j + 1 < cols; ++j)
        for (int layer = 0; layer < 3; ++layer)
        {
          Element& e = mesh.elements[grid.Element(i, j, layer, side)];
          e.type = ElementType::Hexahedron;
          e.layer = static_cast<TissueLayer>(layer + 1);
          e.nodes = grid.Hexahedron(i, j, layer, side);
        }
  return mesh;
}

void AddFaceNodeSets(const FaceGrid& grid, const FaceColumns& columns, const FaceMouthRegion& mouth,
                     const FaceLandmarkSet& lm, FEMesh& mesh)
{
  const int rows = grid.Rows(), cols = grid.Cols();
  auto& skinSet = mesh.nodeSets["skin"];
  auto& skullSet = mesh.nodeSets["skull"];
  auto& innerSet = mesh.nodeSets["inner"];
  auto& midSet = mesh.nodeSets["midsagittal"];
  auto& lipsSet = mesh.nodeSets["lips"];
  // Lips: the skin between the subnasale and the labiomental fold, out past the corner (an
  // ellipse in the (theta, phi) parameterisation, so the set follows the mouth's outline).
  const double lipsLateral = lm.lipCorner.theta + kLipsPastCorner / mouth.rho;
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < rows; ++i)
      for (int j = side; j < cols; ++j)
      {
        const int q = i * cols + j;
        skinSet.push_back(grid.Node(i, j, 0, side));
        (columns.onBone[q] ? skullSet : innerSet).push_back(grid.Node(i, j, 3, side));
        if (j == 0)
          for (int k = 0; k < 4; ++k)
            midSet.push_back(grid.Node(i, j, k, side));
        if (mouth.Ellipse(grid, i, j, lipsLateral) <= 1.0 && grid.phi[i] <= mouth.mouthHi &&
            grid.phi[i] >= mouth.mouthLo)
          lipsSet.push_back(grid.Node(i, j, 0, side));
      }
  for (auto* set : {&skinSet, &skullSet, &innerSet, &midSet, &lipsSet})
    std::sort(set->begin(), set->end());
}

} // namespace mmrep
