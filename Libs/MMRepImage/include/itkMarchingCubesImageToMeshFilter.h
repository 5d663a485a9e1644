// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#ifndef itkMarchingCubesImageToMeshFilter_h
#define itkMarchingCubesImageToMeshFilter_h

#include "itkImageToMeshFilter.h"
#include "itkMarchingCubesSliceWriter.h"
#include "itkMarchingCubesTables.h"

namespace itk
{
/** \class MarchingCubesImageToMeshFilter
 * \brief Iso-surface of a 3-D scalar image as a triangle mesh, in physical coordinates.
 *
 * Voxels whose value is >= IsoValue are inside. The output has one point per voxel edge whose two ends are on
 * different sides (shared by all triangles using it), placed by linear interpolation along the edge,
 * t = (IsoValue - s0) / (s1 - s0) from the lower-index end, then mapped through the image origin, spacing and
 * direction. This is the convention of vtkFlyingEdges3D and vtkMarchingCubes, so the points coincide with theirs.
 *
 * Triangles come from the Marching Cubes case table of itkMarchingCubesTables.h (same triangles per case as
 * VTK's table): the surface is watertight, and triangle normals (right-hand rule) point from inside to outside,
 * i.e. towards decreasing values.
 *
 * PadBoundary (off by default) treats everything outside the image as outside, so surfaces touching the image
 * border are closed: the image is surrounded by one layer of voxels whose value is the image minimum if that is
 * below IsoValue (as a constant pad with the background would do), else the lowest value of the pixel type
 * (an exception if even that is not below IsoValue). The closing points lie between the border voxels and
 * that layer.
 *
 * The algorithm follows the structure of Flying Edges (Schroeder et al. 2015): pass 1 classifies the x-edges of
 * every row; pass 2 counts, per row, the intersected edges it owns and the triangles of its voxels; a prefix sum
 * over rows gives every row fixed point and triangle id ranges; pass 3 writes points and triangles. Passes 1-3 run
 * in parallel over slabs of z-slices and the ids do not depend on the split, so the output is identical for any
 * number of threads or work units.
 *
 * Triangles are itk::CompactTriangleCell objects allocated as one block (see itkCompactTriangleCell.h), unless
 * CompactCells is off, in which case they are ordinary itk::TriangleCell objects (much slower to create).
 * The output mesh must use VectorContainer points and cells containers (the default itk::Mesh traits).
 */
template <typename TInputImage, typename TOutputMesh>
class ITK_TEMPLATE_EXPORT MarchingCubesImageToMeshFilter : public ImageToMeshFilter<TInputImage, TOutputMesh>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(MarchingCubesImageToMeshFilter);

  using Self = MarchingCubesImageToMeshFilter;
  using Superclass = ImageToMeshFilter<TInputImage, TOutputMesh>;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;

  itkNewMacro(Self);
  itkTypeMacro(MarchingCubesImageToMeshFilter, ImageToMeshFilter);

  using InputImageType = TInputImage;
  using InputPixelType = typename InputImageType::PixelType;
  using OutputMeshType = TOutputMesh;
  using PointType = typename OutputMeshType::PointType;
  using CellType = typename OutputMeshType::CellType;
  using PointIdentifier = typename OutputMeshType::PointIdentifier;
  using CellIdentifier = typename OutputMeshType::CellIdentifier;

  static_assert(TInputImage::ImageDimension == 3, "MarchingCubesImageToMeshFilter needs a 3-D image");
  static_assert(TOutputMesh::PointDimension == 3, "MarchingCubesImageToMeshFilter needs a 3-D mesh");

  /** Surface value: voxels with value >= IsoValue are inside. */
  itkSetMacro(IsoValue, double);
  itkGetConstMacro(IsoValue, double);

  /** Close surfaces that touch the image border (outside the image counts as outside). Default off. */
  itkSetMacro(PadBoundary, bool);
  itkGetConstMacro(PadBoundary, bool);
  itkBooleanMacro(PadBoundary);

  /** Store triangles as one block of itk::CompactTriangleCell (default on) or as itk::TriangleCell objects. */
  itkSetMacro(CompactCells, bool);
  itkGetConstMacro(CompactCells, bool);
  itkBooleanMacro(CompactCells);

protected:
  MarchingCubesImageToMeshFilter();
  ~MarchingCubesImageToMeshFilter() override = default;

  void GenerateInputRequestedRegion() override;
  void GenerateData() override;
  void PrintSelf(std::ostream& os, Indent indent) const override;

private:
  // Runs the three passes on a dense nx*ny*nz block of values whose voxel (0,0,0) has continuous index `start`.
  void Contour(const InputPixelType* values, const std::array<SizeValueType, 3>& size,
               const std::array<double, 3>& start);
  // Continuous index relative to `start` -> physical point, from the input's origin, spacing and direction.
  MarchingCubesDetail::IndexToPhysical IndexToPhysicalMap(const std::array<double, 3>& start);

  double m_IsoValue{0.0};
  bool m_PadBoundary{false};
  bool m_CompactCells{true};
};
} // namespace itk

#ifndef ITK_MANUAL_INSTANTIATION
#include "itkMarchingCubesImageToMeshFilter.hxx"
#endif

#endif
