// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepBoundaryFaces.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>

#include <algorithm>
#include <map>

namespace mmrep
{

const std::vector<LocalFace>& LocalFaces(ElementType type)
{
  static const std::vector<LocalFace> hex{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                          {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  static const std::vector<LocalFace> wedge{{0, 1, 2, -1}, {3, 5, 4, -1}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
  static const std::vector<LocalFace> tet{{0, 1, 3, -1}, {1, 2, 3, -1}, {2, 0, 3, -1}, {0, 2, 1, -1}};
  static const std::vector<LocalFace> none;
  switch (type)
  {
    case ElementType::Hexahedron:
      return hex;
    case ElementType::Wedge:
      return wedge;
    case ElementType::Tetrahedron:
      return tet;
    default:
      return none;
  }
}

std::vector<BoundaryFace> BoundaryFaces(const FEMesh& mesh, const std::vector<char>* nodeMask)
{
  // Each face counted under its sorted node ids (-1 first for triangles); the ordered map keeps
  // the output deterministic, and the face keeps the local order of its first element.
  std::map<std::array<std::int32_t, 4>, std::pair<int, BoundaryFace>> faces;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
  {
    const Element& element = mesh.elements[e];
    const auto& table = LocalFaces(element.type);
    for (std::size_t f = 0; f < table.size(); ++f)
    {
      BoundaryFace face;
      face.element = static_cast<std::int32_t>(e);
      face.face = static_cast<int>(f);
      for (int k = 0; k < 4; ++k)
        face.nodes[k] = table[f][k] < 0 ? -1 : element.nodes[static_cast<std::size_t>(table[f][k])];
      auto key = face.nodes;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      if (entry.first++ == 0)
        entry.second = face;
    }
  }
  std::vector<BoundaryFace> out;
  for (const auto& [key, entry] : faces)
  {
    if (entry.first != 1)
      continue;
    const BoundaryFace& face = entry.second;
    if (nodeMask != nullptr &&
        !std::all_of(face.nodes.begin(), face.nodes.begin() + face.NodeCount(),
                     [&](std::int32_t id) { return (*nodeMask)[static_cast<std::size_t>(id)] != 0; }))
      continue;
    out.push_back(face);
  }
  return out;
}

std::vector<char> NodeSetMask(const FEMesh& mesh, const std::string& set)
{
  std::vector<char> mask(mesh.nodes.size(), 0);
  if (const auto it = mesh.nodeSets.find(set); it != mesh.nodeSets.end())
    for (const auto n : it->second)
      mask[static_cast<std::size_t>(n)] = 1;
  return mask;
}

namespace
{
vtkSmartPointer<vtkPolyData> Surface(const FEMesh& mesh, const std::vector<char>* nodeMask, bool triangles)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.nodes.size()));
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.nodes[i].data());
  vtkNew<vtkCellArray> cells;
  for (const auto& face : BoundaryFaces(mesh, nodeMask))
  {
    const auto& n = face.nodes;
    if (triangles)
    {
      const vtkIdType t1[3] = {n[0], n[1], n[2]};
      cells->InsertNextCell(3, t1);
      if (face.NodeCount() == 4)
      {
        const vtkIdType t2[3] = {n[0], n[2], n[3]};
        cells->InsertNextCell(3, t2);
      }
      continue;
    }
    const vtkIdType ids[4] = {n[0], n[1], n[2], n[3]};
    cells->InsertNextCell(face.NodeCount(), ids);
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(cells);
  return surface;
}
} // namespace

vtkSmartPointer<vtkPolyData> BoundarySurface(const FEMesh& mesh, const std::vector<char>* nodeMask)
{
  return Surface(mesh, nodeMask, true);
}

vtkSmartPointer<vtkPolyData> BoundaryPolygons(const FEMesh& mesh, const std::vector<char>* nodeMask)
{
  return Surface(mesh, nodeMask, false);
}

} // namespace mmrep
