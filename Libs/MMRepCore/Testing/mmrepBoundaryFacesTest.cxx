// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Boundary faces against VTK's own face definitions and surface filter.
#include "mmrepBoundaryFaces.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <vtkCellArray.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkHexahedron.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkTetra.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWedge.h>

#include <algorithm>
#include <set>

using namespace mmrep;

namespace
{
// Two unit hexahedra side by side along x (VTK node order), sharing the face x = 1.
FEMesh TwoCubes()
{
  FEMesh m;
  for (int x = 0; x <= 2; ++x)
    for (int y = 0; y <= 1; ++y)
      for (int z = 0; z <= 1; ++z)
        m.nodes.emplace_back(x, y, z);
  auto id = [](int x, int y, int z) { return x * 4 + y * 2 + z; };
  for (int x = 0; x < 2; ++x)
  {
    Element e;
    e.type = ElementType::Hexahedron;
    e.nodes = {id(x, 0, 0), id(x + 1, 0, 0), id(x + 1, 1, 0), id(x, 1, 0),
               id(x, 0, 1), id(x + 1, 0, 1), id(x + 1, 1, 1), id(x, 1, 1)};
    m.elements.push_back(e);
  }
  return m;
}

Point3 Centroid(const FEMesh& m, const Element& e)
{
  Point3 c = Point3::Zero();
  for (int k = 0; k < NodeCount(e.type); ++k)
    c += m.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])] / NodeCount(e.type);
  return c;
}

// Newell normal of a face's nodes.
Point3 Normal(const FEMesh& m, const BoundaryFace& f)
{
  Point3 n = Point3::Zero();
  for (int k = 0; k < f.NodeCount(); ++k)
    n += m.nodes[static_cast<std::size_t>(f.nodes[k])].cross(
      m.nodes[static_cast<std::size_t>(f.nodes[(k + 1) % f.NodeCount()])]);
  return n;
}

std::set<std::set<int>> OurFaces(ElementType type)
{
  std::set<std::set<int>> faces;
  for (const auto& f : LocalFaces(type))
  {
    std::set<int> ids;
    for (int k : f)
      if (k >= 0)
        ids.insert(k);
    faces.insert(ids);
  }
  return faces;
}
} // namespace

TEST(BoundaryFaces, LocalFacesAreVTKFaces)
{
  // vtkCell::GetFace reports the cell's point ids: number them 0..n-1.
  auto faces = [](auto cell, int n) {
    for (int k = 0; k < n; ++k)
    {
      cell->GetPointIds()->SetId(k, k);
      cell->GetPoints()->SetPoint(k, 0, 0, 0);
    }
    std::set<std::set<int>> out;
    for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
    {
      std::set<int> ids;
      vtkCell* face = cell->GetFace(f);
      for (vtkIdType k = 0; k < face->GetNumberOfPoints(); ++k)
        ids.insert(static_cast<int>(face->GetPointId(k)));
      out.insert(ids);
    }
    return out;
  };
  vtkNew<vtkHexahedron> hex;
  vtkNew<vtkWedge> wedge;
  vtkNew<vtkTetra> tet;
  EXPECT_EQ(OurFaces(ElementType::Hexahedron), faces(hex.GetPointer(), 8));
  EXPECT_EQ(OurFaces(ElementType::Wedge), faces(wedge.GetPointer(), 6));
  EXPECT_EQ(OurFaces(ElementType::Tetrahedron), faces(tet.GetPointer(), 4));
  EXPECT_TRUE(LocalFaces(ElementType::Cable).empty());
  // Hexahedron face f is the C3D8 face S(f+1): S1 = nodes 1-2-3-4, S2 = 5-8-7-6, S3 = 1-5-6-2 (1-based).
  const auto& h = LocalFaces(ElementType::Hexahedron);
  EXPECT_EQ(std::set<int>(h[0].begin(), h[0].end()), (std::set<int>{0, 1, 2, 3}));
  EXPECT_EQ(std::set<int>(h[1].begin(), h[1].end()), (std::set<int>{4, 5, 6, 7}));
  EXPECT_EQ(std::set<int>(h[2].begin(), h[2].end()), (std::set<int>{0, 1, 4, 5}));
}

TEST(BoundaryFaces, TwoCubesHaveTenOutwardFacesAsVTKFinds)
{
  const FEMesh m = TwoCubes();
  const auto faces = BoundaryFaces(m);
  ASSERT_EQ(faces.size(), 10u);
  for (const auto& f : faces)
  {
    ASSERT_EQ(f.NodeCount(), 4);
    const Element& e = m.elements[static_cast<std::size_t>(f.element)];
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(f.nodes[k], e.nodes[static_cast<std::size_t>(LocalFaces(e.type)[static_cast<std::size_t>(f.face)][k])]);
    Point3 centre = Point3::Zero();
    for (int k = 0; k < 4; ++k)
      centre += m.nodes[static_cast<std::size_t>(f.nodes[k])] / 4.0;
    const Point3 n = Normal(m, f);
    EXPECT_NEAR(n.norm(), 2.0, 1e-12); // twice the unit face's area
    EXPECT_GT(n.dot(centre - Centroid(m, e)), 0.0) << "face " << f.face << " of element " << f.element;
    EXPECT_FALSE(std::abs(centre.x() - 1.0) < 1e-12 && std::abs(n.x()) > 0) << "the shared face is inside";
  }
  // VTK's surface filter on the same grid.
  vtkNew<vtkPoints> points;
  for (const auto& p : m.nodes)
    points->InsertNextPoint(p.data());
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  for (const auto& e : m.elements)
  {
    vtkIdType ids[8];
    std::copy(e.nodes.begin(), e.nodes.end(), ids);
    grid->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
  }
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(grid);
  surface->Update();
  EXPECT_EQ(surface->GetOutput()->GetNumberOfCells(), 10);
  EXPECT_EQ(BoundaryPolygons(m)->GetNumberOfCells(), 10);
  EXPECT_EQ(BoundarySurface(m)->GetNumberOfCells(), 20);
  EXPECT_EQ(BoundarySurface(m)->GetNumberOfPoints(), 12);
}

TEST(BoundaryFaces, MaskKeepsFacesWithAllNodesMarked)
{
  FEMesh m = TwoCubes();
  m.nodeSets["top"] = {1, 3, 5, 7, 9, 11}; // z = 1
  const auto mask = NodeSetMask(m, "top");
  const auto faces = BoundaryFaces(m, &mask);
  ASSERT_EQ(faces.size(), 2u);
  for (const auto& f : faces)
  {
    EXPECT_EQ(f.face, 1); // the top face S2
    EXPECT_GT(Normal(m, f).z(), 0.0);
  }
  EXPECT_EQ(BoundarySurface(m, &mask)->GetNumberOfCells(), 4);
  EXPECT_EQ(NodeSetMask(m, "absent"), std::vector<char>(m.nodes.size(), 0));
}

TEST(BoundaryFaces, WedgeAndTetrahedronFacesPointOutwards)
{
  FEMesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  Element wedge;
  wedge.type = ElementType::Wedge;
  // A valid VTK wedge: first triangle clockwise seen from the second (README of MMRepFE).
  wedge.nodes = {0, 2, 1, 3, 5, 4};
  m.elements.push_back(wedge);
  FEMesh t;
  t.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Element tet;
  tet.type = ElementType::Tetrahedron;
  tet.nodes = {0, 1, 2, 3};
  t.elements.push_back(tet);
  for (const FEMesh* mesh : {&m, &t})
  {
    const auto faces = BoundaryFaces(*mesh);
    EXPECT_EQ(faces.size(), LocalFaces(mesh->elements[0].type).size());
    for (const auto& f : faces)
    {
      Point3 centre = Point3::Zero();
      for (int k = 0; k < f.NodeCount(); ++k)
        centre += mesh->nodes[static_cast<std::size_t>(f.nodes[k])] / f.NodeCount();
      EXPECT_GT(Normal(*mesh, f).dot(centre - Centroid(*mesh, mesh->elements[0])), 0.0) << "face " << f.face;
    }
  }
}
