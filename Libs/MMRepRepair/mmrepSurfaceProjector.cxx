#include "mmrepSurfaceProjector.h"

#include <vtkSMPTools.h>

#include <Eigen/Geometry>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace mmrep
{

SurfaceProjector::SurfaceProjector(vtkPolyData* surface)
{
  if (surface == nullptr || surface->GetNumberOfCells() == 0)
    throw std::invalid_argument("surface to project onto has no cells");
  surface_ = surface;
  locator_ = vtkSmartPointer<vtkStaticCellLocator>::New();
  locator_->SetDataSet(surface_);
  BuildLocatorSequentially(locator_);
  cell_ = vtkSmartPointer<vtkGenericCell>::New();
}

Point3 SurfaceProjector::Project(const Point3& p) const
{
  double closest[3];
  vtkIdType cellId = -1;
  int subId = 0;
  double dist2 = 0;
  locator_->FindClosestPoint(p.data(), closest, cell_, cellId, subId, dist2);
  return Point3(closest[0], closest[1], closest[2]);
}

double SurfaceProjector::Distance(const Point3& p) const
{
  return (Project(p) - p).norm();
}

Point3 SurfaceProjector::Normal(const Point3& p) const
{
  double closest[3];
  vtkIdType cellId = -1;
  int subId = 0;
  double dist2 = 0;
  locator_->FindClosestPoint(p.data(), closest, cell_, cellId, subId, dist2);
  vtkPoints* points = cell_->GetPoints();
  if (cellId < 0 || points->GetNumberOfPoints() < 3)
    return Point3::Zero();
  Point3 a, b, c;
  points->GetPoint(0, a.data());
  points->GetPoint(1, b.data());
  points->GetPoint(2, c.data());
  const Point3 n = (b - a).cross(c - a);
  return n.norm() > 0 ? Point3(n.normalized()) : Point3::Zero();
}

namespace
{
// Faces of each solid type in VTK node order (local indices; -1 ends a triangle).
const std::vector<std::array<int, 4>>& Faces(ElementType type)
{
  static const std::vector<std::array<int, 4>> hex{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                   {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  static const std::vector<std::array<int, 4>> wedge{{0, 1, 2, -1}, {3, 5, 4, -1}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
  static const std::vector<std::array<int, 4>> tet{{0, 1, 3, -1}, {1, 2, 3, -1}, {2, 0, 3, -1}, {0, 2, 1, -1}};
  static const std::vector<std::array<int, 4>> none;
  switch (type)
  {
    case ElementType::Hexahedron: return hex;
    case ElementType::Wedge: return wedge;
    case ElementType::Tetrahedron: return tet;
    default: return none;
  }
}
} // namespace

void BuildLocatorSequentially(vtkAbstractCellLocator* locator)
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{std::string("Sequential")}, [&] { locator->BuildLocator(); });
}

vtkSmartPointer<vtkPolyData> BoundarySurface(const FEMesh& mesh, const std::vector<char>* nodeMask)
{
  // Count each face by its sorted node ids; ordered map keeps the output deterministic.
  std::map<std::array<std::int32_t, 4>, std::pair<int, std::array<std::int32_t, 4>>> faces;
  for (const Element& e : mesh.elements)
    for (const auto& f : Faces(e.type))
    {
      std::array<std::int32_t, 4> ids{};
      for (int k = 0; k < 4; ++k)
        ids[k] = f[k] < 0 ? -1 : e.nodes[f[k]];
      auto key = ids;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      if (entry.first++ == 0)
        entry.second = ids;
    }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.nodes.size()));
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.nodes[i].data());
  vtkNew<vtkCellArray> triangles;
  for (const auto& [key, entry] : faces)
  {
    if (entry.first != 1)
      continue;
    const auto& ids = entry.second;
    const int n = ids[3] < 0 ? 3 : 4;
    if (nodeMask != nullptr &&
        !std::all_of(ids.begin(), ids.begin() + n, [&](std::int32_t id) { return (*nodeMask)[id] != 0; }))
      continue;
    const vtkIdType t1[3] = {ids[0], ids[1], ids[2]};
    triangles->InsertNextCell(3, t1);
    if (n == 4)
    {
      const vtkIdType t2[3] = {ids[0], ids[2], ids[3]};
      triangles->InsertNextCell(3, t2);
    }
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(triangles);
  return surface;
}

} // namespace mmrep
