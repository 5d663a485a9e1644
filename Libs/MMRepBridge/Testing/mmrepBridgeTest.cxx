// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Conversions keep geometry: ITK and VTK map every voxel index to the same physical point,
// meshes keep vertices and faces in order through ITK and OpenMesh.
#include "mmrepBridge.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSphereSource.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace
{

using ShortImage = itk::Image<short, 3>;

template <typename TImage> std::size_t PixelCount(const TImage* image)
{
  return image->GetLargestPossibleRegion().GetNumberOfPixels();
}

template <typename TImage> typename TImage::Pointer MakeImage()
{
  auto image = TImage::New();
  typename TImage::IndexType start = {{3, -2, 5}}; // non-zero start index
  typename TImage::SizeType size = {{9, 7, 5}};
  image->SetRegions(typename TImage::RegionType(start, size));
  typename TImage::SpacingType spacing;
  spacing[0] = 0.7;
  spacing[1] = 1.3;
  spacing[2] = 2.1;
  image->SetSpacing(spacing);
  typename TImage::PointType origin;
  origin[0] = -12.5;
  origin[1] = 40.25;
  origin[2] = 7.0;
  image->SetOrigin(origin);
  // Rotation by 30 degrees about the axis (1,1,1)/sqrt(3) (Rodrigues).
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6), u = 1 / std::sqrt(3.0);
  typename TImage::DirectionType d;
  for (unsigned i = 0; i < 3; ++i)
  {
    for (unsigned j = 0; j < 3; ++j)
    {
      d[i][j] = (i == j ? c : 0) + (1 - c) * u * u;
    }
  }
  d[0][1] -= s * u;
  d[0][2] += s * u;
  d[1][0] += s * u;
  d[1][2] -= s * u;
  d[2][0] -= s * u;
  d[2][1] += s * u;
  image->SetDirection(d);
  image->Allocate();
  for (std::size_t i = 0; i < PixelCount(image.GetPointer()); ++i)
  {
    image->GetBufferPointer()[i] = static_cast<typename TImage::PixelType>((i * 7) % 200);
  }
  return image;
}

template <typename TPixel> void CheckImageRoundTrip()
{
  using ImageType = itk::Image<TPixel, 3>;
  typename ImageType::Pointer image = MakeImage<ImageType>();
  vtkSmartPointer<vtkImageData> vtk = mmrep::ITKToVTKImage<TPixel>(image);
  const auto region = image->GetLargestPossibleRegion();
  int checked = 0;
  for (int k = 0; k < 5; k += 2)
  {
    for (int j = 0; j < 7; j += 3)
    {
      for (int i = 0; i < 9; i += 4)
      {
        typename ImageType::IndexType idx = {
          {region.GetIndex()[0] + i, region.GetIndex()[1] + j, region.GetIndex()[2] + k}};
        typename ImageType::PointType itkPoint;
        image->TransformIndexToPhysicalPoint(idx, itkPoint);
        const int ijk[3] = {static_cast<int>(idx[0]), static_cast<int>(idx[1]), static_cast<int>(idx[2])};
        double vtkPoint[3];
        vtk->TransformIndexToPhysicalPoint(ijk, vtkPoint);
        for (int a = 0; a < 3; ++a)
        {
          EXPECT_NEAR(itkPoint[a], vtkPoint[a], 1e-9);
        }
        // The VTK point found at that physical location holds the ITK voxel value.
        const vtkIdType id = vtk->FindPoint(vtkPoint);
        ASSERT_GE(id, 0);
        EXPECT_EQ(vtk->GetPointData()->GetScalars()->GetComponent(id, 0), static_cast<double>(image->GetPixel(idx)));
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 27);

  typename ImageType::Pointer back = mmrep::VTKToITKImage<TPixel>(vtk);
  EXPECT_EQ(back->GetLargestPossibleRegion(), image->GetLargestPossibleRegion());
  for (unsigned a = 0; a < 3; ++a)
  {
    EXPECT_DOUBLE_EQ(back->GetSpacing()[a], image->GetSpacing()[a]);
    EXPECT_DOUBLE_EQ(back->GetOrigin()[a], image->GetOrigin()[a]);
    for (unsigned c = 0; c < 3; ++c)
    {
      EXPECT_DOUBLE_EQ(back->GetDirection()[a][c], image->GetDirection()[a][c]);
    }
  }
  for (std::size_t i = 0; i < PixelCount(image.GetPointer()); ++i)
  {
    ASSERT_EQ(back->GetBufferPointer()[i], image->GetBufferPointer()[i]) << i;
  }
}

vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(20);
  sphere->SetPhiResolution(13);
  sphere->SetCenter(1.5, -2.25, 30.125);
  sphere->SetRadius(11.0);
  sphere->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(sphere->GetOutput());
  return out;
}

void ExpectSameSurface(vtkPolyData* a, vtkPolyData* b)
{
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  ASSERT_EQ(a->GetNumberOfPolys(), b->GetNumberOfPolys());
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_EQ(a->GetPoint(i)[k], b->GetPoint(i)[k]) << "point " << i;
    }
  }
  vtkNew<vtkIdList> ia, ib;
  a->GetPolys()->InitTraversal();
  b->GetPolys()->InitTraversal();
  vtkIdType cell = 0;
  while (a->GetPolys()->GetNextCell(ia))
  {
    ASSERT_TRUE(b->GetPolys()->GetNextCell(ib));
    ASSERT_EQ(ia->GetNumberOfIds(), ib->GetNumberOfIds());
    for (vtkIdType k = 0; k < ia->GetNumberOfIds(); ++k)
    {
      ASSERT_EQ(ia->GetId(k), ib->GetId(k)) << "triangle " << cell;
    }
    ++cell;
  }
}

} // namespace

TEST(Bridge, ShortImageGeometryAndPixelsPreserved)
{
  CheckImageRoundTrip<short>();
}
TEST(Bridge, UCharImageGeometryAndPixelsPreserved)
{
  CheckImageRoundTrip<unsigned char>();
}
TEST(Bridge, FloatImageGeometryAndPixelsPreserved)
{
  CheckImageRoundTrip<float>();
}

TEST(Bridge, VTKImageOfOtherScalarTypeIsCast)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 3, 2);
  image->SetSpacing(0.5, 0.25, 2.0);
  image->SetOrigin(1, 2, 3);
  image->AllocateScalars(VTK_DOUBLE, 1);
  auto* values = static_cast<double*>(image->GetScalarPointer());
  for (int i = 0; i < 24; ++i)
  {
    values[i] = i * 10.75 - 50.0;
  }
  ShortImage::Pointer itkImage = mmrep::VTKToITKImage<short>(image);
  ASSERT_EQ(itkImage->GetLargestPossibleRegion().GetNumberOfPixels(), 24u);
  for (int i = 0; i < 24; ++i)
  {
    EXPECT_EQ(itkImage->GetBufferPointer()[i], static_cast<short>(values[i]));
  }
  EXPECT_DOUBLE_EQ(itkImage->GetSpacing()[1], 0.25);
  EXPECT_DOUBLE_EQ(itkImage->GetOrigin()[2], 3.0);
  vtkNew<vtkImageData> noScalars;
  noScalars->SetDimensions(2, 2, 2);
  EXPECT_THROW(mmrep::VTKToITKImage<short>(noScalars), std::invalid_argument);
}

TEST(Bridge, ITKMeshRoundTripKeepsVerticesAndFaces)
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  mmrep::SurfaceMesh::Pointer mesh = mmrep::PolyDataToITKMesh(sphere);
  ASSERT_EQ(mesh->GetNumberOfPoints(), static_cast<std::size_t>(sphere->GetNumberOfPoints()));
  ASSERT_EQ(mesh->GetNumberOfCells(), static_cast<std::size_t>(sphere->GetNumberOfPolys()));
  // Spot-check the ITK side directly.
  mmrep::SurfaceMesh::PointType p5;
  ASSERT_TRUE(mesh->GetPoint(5, &p5));
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_EQ(p5[k], sphere->GetPoint(5)[k]);
  }
  mmrep::SurfaceMesh::CellAutoPointer cell;
  ASSERT_TRUE(mesh->GetCell(7, cell));
  vtkNew<vtkIdList> ids;
  sphere->GetCellPoints(7, ids);
  auto pid = cell->PointIdsBegin();
  for (int k = 0; k < 3; ++k, ++pid)
  {
    EXPECT_EQ(static_cast<vtkIdType>(*pid), ids->GetId(k));
  }
  vtkSmartPointer<vtkPolyData> back = mmrep::ITKMeshToPolyData(mesh);
  ExpectSameSurface(sphere, back);
}

TEST(Bridge, OpenMeshRoundTripKeepsVerticesAndFaces)
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  mmrep::TriMesh mesh = mmrep::PolyDataToOpenMesh(sphere);
  ASSERT_EQ(mesh.n_vertices(), static_cast<std::size_t>(sphere->GetNumberOfPoints()));
  ASSERT_EQ(mesh.n_faces(), static_cast<std::size_t>(sphere->GetNumberOfPolys()));
  // A closed sphere: Euler characteristic 2 and no boundary edges.
  EXPECT_EQ(
    static_cast<long>(mesh.n_vertices()) - static_cast<long>(mesh.n_edges()) + static_cast<long>(mesh.n_faces()), 2);
  for (const auto e : mesh.edges())
  {
    ASSERT_FALSE(mesh.is_boundary(e));
  }
  vtkSmartPointer<vtkPolyData> back = mmrep::OpenMeshToPolyData(mesh);
  ExpectSameSurface(sphere, back);
}

TEST(Bridge, OpenMeshRejectsOrCountsNonManifoldFaces)
{
  // Three triangles on one edge (0,1): the third cannot be added to a half-edge mesh.
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(0, -1, 0);
  points->InsertNextPoint(0, 0, 1);
  vtkNew<vtkCellArray> tris;
  const vtkIdType t0[3] = {0, 1, 2}, t1[3] = {1, 0, 3}, t2[3] = {0, 1, 4};
  tris->InsertNextCell(3, t0);
  tris->InsertNextCell(3, t1);
  tris->InsertNextCell(3, t2);
  vtkNew<vtkPolyData> fan;
  fan->SetPoints(points);
  fan->SetPolys(tris);
  EXPECT_THROW(mmrep::PolyDataToOpenMesh(fan), std::runtime_error);
  std::size_t skipped = 0;
  mmrep::TriMesh mesh = mmrep::PolyDataToOpenMesh(fan, &skipped);
  EXPECT_EQ(skipped, 1u);
  EXPECT_EQ(mesh.n_faces(), 2u);
  EXPECT_EQ(mesh.n_vertices(), 5u);
}

TEST(Bridge, OpenMeshDeletedElementsAreDropped)
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  mmrep::TriMesh mesh = mmrep::PolyDataToOpenMesh(sphere);
  mesh.request_face_status();
  mesh.request_edge_status();
  mesh.request_vertex_status();
  mesh.delete_face(mesh.face_handle(4), false); // keep its (still used) vertices
  vtkSmartPointer<vtkPolyData> back = mmrep::OpenMeshToPolyData(mesh);
  EXPECT_EQ(back->GetNumberOfPoints(), sphere->GetNumberOfPoints());
  ASSERT_EQ(back->GetNumberOfPolys(), sphere->GetNumberOfPolys() - 1);
  // Faces after the deleted one shift down by one and keep their vertices.
  vtkNew<vtkIdList> a, b;
  sphere->GetCellPoints(5, a);
  back->GetCellPoints(4, b);
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_EQ(a->GetId(k), b->GetId(k));
  }
}
