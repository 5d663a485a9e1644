// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// ITK <-> VTK <-> OpenMesh conversions (all template instantiations live in this file).
#include "mmrepBridge.h"

#include <itkTriangleCell.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkMatrix3x3.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkTypeTraits.h>

#include <cstring>
#include <map>
#include <vector>
#include <stdexcept>
#include <string>

namespace mmrep
{

template <typename TPixel> vtkSmartPointer<vtkImageData> ITKToVTKImage(const itk::Image<TPixel, 3>* image)
{
  if (image == nullptr)
  {
    throw std::invalid_argument("ITKToVTKImage: null image");
  }
  using ImageType = itk::Image<TPixel, 3>;
  const typename ImageType::RegionType region = image->GetBufferedRegion();
  if (region != image->GetLargestPossibleRegion())
  {
    throw std::invalid_argument("ITKToVTKImage: image is not fully buffered");
  }
  const auto index = region.GetIndex();
  const auto size = region.GetSize();
  auto out = vtkSmartPointer<vtkImageData>::New();
  // Keeping the ITK start index as the VTK extent start makes both map index -> point alike:
  // x = origin + D * (spacing .* ijk).
  out->SetExtent(static_cast<int>(index[0]), static_cast<int>(index[0] + size[0]) - 1, static_cast<int>(index[1]),
                 static_cast<int>(index[1] + size[1]) - 1, static_cast<int>(index[2]),
                 static_cast<int>(index[2] + size[2]) - 1);
  out->SetOrigin(image->GetOrigin()[0], image->GetOrigin()[1], image->GetOrigin()[2]);
  out->SetSpacing(image->GetSpacing()[0], image->GetSpacing()[1], image->GetSpacing()[2]);
  double direction[9];
  for (unsigned r = 0; r < 3; ++r)
  {
    for (unsigned c = 0; c < 3; ++c)
    {
      direction[3 * r + c] = image->GetDirection()[r][c];
    }
  }
  out->SetDirectionMatrix(direction);
  out->AllocateScalars(vtkTypeTraits<TPixel>::VTKTypeID(), 1);
  // Both toolkits store x fastest, then y, then z.
  std::memcpy(out->GetScalarPointer(), image->GetBufferPointer(), region.GetNumberOfPixels() * sizeof(TPixel));
  out->GetPointData()->GetScalars()->SetName("scalars");
  return out;
}

template <typename TPixel> typename itk::Image<TPixel, 3>::Pointer VTKToITKImage(vtkImageData* image)
{
  if (image == nullptr)
  {
    throw std::invalid_argument("VTKToITKImage: null image");
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (scalars == nullptr || scalars->GetNumberOfComponents() != 1)
  {
    throw std::invalid_argument("VTKToITKImage: image needs single-component point scalars");
  }
  using ImageType = itk::Image<TPixel, 3>;
  int extent[6];
  image->GetExtent(extent);
  typename ImageType::IndexType index;
  typename ImageType::SizeType size;
  typename ImageType::PointType origin;
  typename ImageType::SpacingType spacing;
  typename ImageType::DirectionType direction;
  for (unsigned a = 0; a < 3; ++a)
  {
    index[a] = extent[2 * a];
    size[a] = static_cast<itk::SizeValueType>(extent[2 * a + 1] - extent[2 * a] + 1);
    origin[a] = image->GetOrigin()[a];
    spacing[a] = image->GetSpacing()[a];
    if (spacing[a] <= 0)
    {
      throw std::invalid_argument("VTKToITKImage: spacing must be positive (axis " + std::to_string(a) + ")");
    }
    for (unsigned c = 0; c < 3; ++c)
    {
      direction[a][c] = image->GetDirectionMatrix()->GetElement(a, c);
    }
  }
  if (vnl_determinant(direction.GetVnlMatrix()) == 0)
  {
    throw std::invalid_argument("VTKToITKImage: singular direction matrix");
  }
  auto out = ImageType::New();
  out->SetRegions(typename ImageType::RegionType(index, size));
  out->SetOrigin(origin);
  out->SetSpacing(spacing);
  out->SetDirection(direction);
  out->Allocate();
  const vtkIdType n = scalars->GetNumberOfTuples();
  if (static_cast<itk::SizeValueType>(n) != out->GetLargestPossibleRegion().GetNumberOfPixels())
  {
    throw std::invalid_argument("VTKToITKImage: scalar count does not match the extent");
  }
  TPixel* buffer = out->GetBufferPointer();
  if (scalars->GetDataType() == vtkTypeTraits<TPixel>::VTKTypeID())
  {
    std::memcpy(buffer, scalars->GetVoidPointer(0), static_cast<std::size_t>(n) * sizeof(TPixel));
  }
  else
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      buffer[i] = static_cast<TPixel>(scalars->GetComponent(i, 0));
    }
  }
  return out;
}

template vtkSmartPointer<vtkImageData> ITKToVTKImage<short>(const itk::Image<short, 3>*);
template vtkSmartPointer<vtkImageData> ITKToVTKImage<unsigned char>(const itk::Image<unsigned char, 3>*);
template vtkSmartPointer<vtkImageData> ITKToVTKImage<float>(const itk::Image<float, 3>*);
template itk::Image<short, 3>::Pointer VTKToITKImage<short>(vtkImageData*);
template itk::Image<unsigned char, 3>::Pointer VTKToITKImage<unsigned char>(vtkImageData*);
template itk::Image<float, 3>::Pointer VTKToITKImage<float>(vtkImageData*);

// ---- ITK meshes -------------------------------------------------------------------------------

vtkSmartPointer<vtkPolyData> ITKMeshToPolyData(const SurfaceMesh* mesh)
{
  if (mesh == nullptr)
  {
    throw std::invalid_argument("ITKMeshToPolyData: null mesh");
  }
  // ITK point identifiers may be sparse; VTK ids are 0..n-1 in identifier order. Filters such as
  // our Marching Cubes number them 0..n-1 already: then the map is skipped (large surfaces).
  const auto* itkPoints = mesh->GetPoints();
  const vtkIdType pointCount = itkPoints ? static_cast<vtkIdType>(itkPoints->Size()) : 0;
  bool dense = true;
  std::map<SurfaceMesh::PointIdentifier, vtkIdType> vtkId;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(pointCount);
  if (itkPoints != nullptr)
  {
    vtkIdType next = 0;
    for (auto it = itkPoints->Begin(); it != itkPoints->End(); ++it, ++next)
    {
      dense = dense && it->Index() == static_cast<SurfaceMesh::PointIdentifier>(next);
      points->SetPoint(next, it->Value()[0], it->Value()[1], it->Value()[2]);
    }
    if (!dense)
    {
      next = 0;
      for (auto it = itkPoints->Begin(); it != itkPoints->End(); ++it)
        vtkId[it->Index()] = next++;
    }
  }
  vtkNew<vtkCellArray> triangles;
  if (mesh->GetCells() != nullptr)
  {
    triangles->AllocateExact(mesh->GetCells()->Size(), 3 * mesh->GetCells()->Size());
    for (auto it = mesh->GetCells()->Begin(); it != mesh->GetCells()->End(); ++it)
    {
      const SurfaceMesh::CellType* cell = it->Value();
      if (cell->GetType() != itk::CellGeometryEnum::TRIANGLE_CELL)
      {
        throw std::invalid_argument("ITKMeshToPolyData: cell " + std::to_string(it->Index()) + " is not a triangle");
      }
      vtkIdType ids[3];
      int k = 0;
      for (auto p = cell->PointIdsBegin(); p != cell->PointIdsEnd(); ++p)
      {
        if (dense)
        {
          if (*p >= static_cast<SurfaceMesh::PointIdentifier>(pointCount))
            throw std::invalid_argument("ITKMeshToPolyData: cell " + std::to_string(it->Index()) +
                                        " uses an unknown point");
          ids[k++] = static_cast<vtkIdType>(*p);
          continue;
        }
        const auto found = vtkId.find(*p);
        if (found == vtkId.end())
        {
          throw std::invalid_argument("ITKMeshToPolyData: cell " + std::to_string(it->Index()) +
                                      " uses an unknown point");
        }
        ids[k++] = found->second;
      }
      triangles->InsertNextCell(3, ids);
    }
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(triangles);
  return out;
}

SurfaceMesh::Pointer PolyDataToITKMesh(vtkPolyData* surface)
{
  if (surface == nullptr)
  {
    throw std::invalid_argument("PolyDataToITKMesh: null surface");
  }
  if (surface->GetNumberOfVerts() + surface->GetNumberOfLines() + surface->GetNumberOfStrips() > 0)
  {
    throw std::invalid_argument("PolyDataToITKMesh: surface has vertex, line or strip cells (polygons only)");
  }
  auto mesh = SurfaceMesh::New();
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    SurfaceMesh::PointType q;
    q[0] = p[0];
    q[1] = p[1];
    q[2] = p[2];
    mesh->SetPoint(static_cast<SurfaceMesh::PointIdentifier>(i), q);
  }
  using TriangleType = itk::TriangleCell<SurfaceMesh::CellType>;
  vtkCellArray* polys = surface->GetPolys();
  vtkNew<vtkIdList> ids;
  polys->InitTraversal();
  SurfaceMesh::CellIdentifier cellId = 0;
  while (polys->GetNextCell(ids))
  {
    if (ids->GetNumberOfIds() != 3)
    {
      throw std::invalid_argument("PolyDataToITKMesh: polygon " + std::to_string(cellId) + " has " +
                                  std::to_string(ids->GetNumberOfIds()) + " points (triangles only)");
    }
    SurfaceMesh::CellAutoPointer cell;
    cell.TakeOwnership(new TriangleType);
    for (unsigned k = 0; k < 3; ++k)
    {
      cell->SetPointId(k, static_cast<SurfaceMesh::PointIdentifier>(ids->GetId(k)));
    }
    mesh->SetCell(cellId++, cell);
  }
  return mesh;
}

// ---- OpenMesh ---------------------------------------------------------------------------------

TriMesh PolyDataToOpenMesh(vtkPolyData* surface, std::size_t* skippedFaces)
{
  if (surface == nullptr)
  {
    throw std::invalid_argument("PolyDataToOpenMesh: null surface");
  }
  if (skippedFaces != nullptr)
  {
    *skippedFaces = 0;
  }
  TriMesh mesh;
  std::vector<TriMesh::VertexHandle> vertices;
  vertices.reserve(static_cast<std::size_t>(surface->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    vertices.push_back(mesh.add_vertex(TriMesh::Point(p[0], p[1], p[2])));
  }
  vtkCellArray* polys = surface->GetPolys();
  vtkNew<vtkIdList> ids;
  polys->InitTraversal();
  vtkIdType cell = 0;
  while (polys->GetNextCell(ids))
  {
    if (ids->GetNumberOfIds() != 3)
    {
      throw std::invalid_argument("PolyDataToOpenMesh: polygon " + std::to_string(cell) + " has " +
                                  std::to_string(ids->GetNumberOfIds()) + " points (triangles only)");
    }
    const TriMesh::FaceHandle f =
      mesh.add_face(vertices[ids->GetId(0)], vertices[ids->GetId(1)], vertices[ids->GetId(2)]);
    if (!f.is_valid())
    {
      if (skippedFaces == nullptr)
      {
        throw std::runtime_error("PolyDataToOpenMesh: triangle " + std::to_string(cell) +
                                 " is non-manifold or degenerate; OpenMesh cannot represent it");
      }
      ++*skippedFaces;
    }
    ++cell;
  }
  return mesh;
}

vtkSmartPointer<vtkPolyData> OpenMeshToPolyData(const TriMesh& mesh)
{
  // Deleted elements (status flags) are skipped and the survivors renumbered in order;
  // garbage_collection() would reorder them.
  const bool vertexStatus = mesh.has_vertex_status();
  const bool faceStatus = mesh.has_face_status();
  std::vector<vtkIdType> vtkId(mesh.n_vertices(), -1);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto v : mesh.all_vertices())
  {
    if (vertexStatus && mesh.status(v).deleted())
    {
      continue;
    }
    const TriMesh::Point& p = mesh.point(v);
    vtkId[v.idx()] = points->InsertNextPoint(p[0], p[1], p[2]);
  }
  vtkNew<vtkCellArray> triangles;
  for (const auto f : mesh.all_faces())
  {
    if (faceStatus && mesh.status(f).deleted())
    {
      continue;
    }
    vtkIdType ids[3];
    int k = 0;
    for (const auto v : mesh.fv_range(f))
    {
      if (k == 3 || vtkId[v.idx()] < 0)
      {
        throw std::invalid_argument("OpenMeshToPolyData: face " + std::to_string(f.idx()) +
                                    " is not a triangle of live vertices");
      }
      ids[k++] = vtkId[v.idx()];
    }
    triangles->InsertNextCell(3, ids);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(triangles);
  return out;
}

} // namespace mmrep
