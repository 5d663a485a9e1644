// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Conversions between the toolkits: ITK images <-> vtkImageData (origin, spacing and direction
// kept), ITK triangle meshes <-> vtkPolyData, and vtkPolyData <-> OpenMesh triangle meshes.
// Every conversion copies the data; point and face order are preserved.
#pragma once

#include <itkImage.h>
#include <itkMesh.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstddef>

namespace mmrep
{

// ---- images ----
// Instantiated for short, unsigned char and float pixels.
template <typename TPixel> vtkSmartPointer<vtkImageData> ITKToVTKImage(const itk::Image<TPixel, 3>* image);
// Any single-component VTK scalar type is converted (static_cast) to TPixel.
// Throws std::invalid_argument for null/multi-component input or a singular direction.
template <typename TPixel> typename itk::Image<TPixel, 3>::Pointer VTKToITKImage(vtkImageData* image);

extern template vtkSmartPointer<vtkImageData> ITKToVTKImage<short>(const itk::Image<short, 3>*);
extern template vtkSmartPointer<vtkImageData> ITKToVTKImage<unsigned char>(const itk::Image<unsigned char, 3>*);
extern template vtkSmartPointer<vtkImageData> ITKToVTKImage<float>(const itk::Image<float, 3>*);
extern template itk::Image<short, 3>::Pointer VTKToITKImage<short>(vtkImageData*);
extern template itk::Image<unsigned char, 3>::Pointer VTKToITKImage<unsigned char>(vtkImageData*);
extern template itk::Image<float, 3>::Pointer VTKToITKImage<float>(vtkImageData*);

// ---- ITK triangle meshes ----
using SurfaceMesh = itk::Mesh<double, 3>;
// Triangle cells become VTK triangles (other cell types are rejected with std::invalid_argument).
vtkSmartPointer<vtkPolyData> ITKMeshToPolyData(const SurfaceMesh* mesh);
// Requires a polygon-only triangle surface (run vtkTriangleFilter first otherwise).
SurfaceMesh::Pointer PolyDataToITKMesh(vtkPolyData* surface);

// ---- OpenMesh ----
// Double-precision points so that a VTK -> OpenMesh -> VTK round trip is exact.
struct OpenMeshTraits : public OpenMesh::DefaultTraits
{
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshTraits>;

// Vertex i = VTK point i; faces in cell order. OpenMesh cannot hold non-manifold faces: when
// skippedFaces is null such a face throws std::runtime_error, otherwise it is skipped and counted.
TriMesh PolyDataToOpenMesh(vtkPolyData* surface, std::size_t* skippedFaces = nullptr);
// Deleted elements (status flags) are dropped; the others keep their relative order.
vtkSmartPointer<vtkPolyData> OpenMeshToPolyData(const TriMesh& mesh);

} // namespace mmrep
