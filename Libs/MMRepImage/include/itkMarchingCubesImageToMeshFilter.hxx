// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#ifndef itkMarchingCubesImageToMeshFilter_hxx
#define itkMarchingCubesImageToMeshFilter_hxx

#include "itkMarchingCubesImageToMeshFilter.h"

#include "itkCompactTriangleCell.h"
#include "itkMarchingCubesSliceWriter.h"
#include "itkMultiThreaderBase.h"
#include "itkTriangleCell.h"
#include "itkVectorContainer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

namespace itk
{
template <typename TInputImage, typename TOutputMesh>
MarchingCubesImageToMeshFilter<TInputImage, TOutputMesh>::MarchingCubesImageToMeshFilter()
{
  this->SetNumberOfRequiredInputs(1);
}

template <typename TInputImage, typename TOutputMesh>
void MarchingCubesImageToMeshFilter<TInputImage, TOutputMesh>::GenerateInputRequestedRegion()
{
  Superclass::GenerateInputRequestedRegion();
  // The surface needs every voxel.
  auto* input = const_cast<InputImageType*>(this->GetInput());
  if (input)
  {
    input->SetRequestedRegionToLargestPossibleRegion();
  }
}

template <typename TInputImage, typename TOutputMesh>
void MarchingCubesImageToMeshFilter<TInputImage, TOutputMesh>::GenerateData()
{
  const InputImageType* input = this->GetInput();
  if (!input)
  {
    itkExceptionMacro(<< "no input image");
  }
  if (std::isnan(m_IsoValue))
  {
    itkExceptionMacro(<< "IsoValue is NaN");
  }
  this->GetOutput()->Initialize();
  this->UpdateProgress(0.0f);

  const auto region = input->GetBufferedRegion();
  std::array<SizeValueType, 3> size;
  std::array<double, 3> start;
  for (unsigned int d = 0; d < 3; ++d)
  {
    size[d] = region.GetSize(d);
    start[d] = static_cast<double>(region.GetIndex(d));
  }
  const InputPixelType* values = input->GetBufferPointer();
  const SizeValueType numberOfVoxels = region.GetNumberOfPixels();

  if (!m_PadBoundary || numberOfVoxels == 0)
  {
    this->Contour(values, size, start);
    this->UpdateProgress(1.0f);
    return;
  }

  // One layer of voxels below IsoValue around the image: the image minimum when it is below IsoValue (the value
  // a constant-pad of the background would use), else the lowest value of the pixel type.
  double padValue = static_cast<double>(*std::min_element(values, values + numberOfVoxels));
  if (!(padValue < m_IsoValue))
  {
    padValue = static_cast<double>(NumericTraits<InputPixelType>::NonpositiveMin());
    if (!(padValue < m_IsoValue))
    {
      itkExceptionMacro(<< "PadBoundary: IsoValue " << m_IsoValue
                        << " is not above the lowest value of the pixel type, so no padding value lies outside");
    }
  }
  const std::array<SizeValueType, 3> padded{{size[0] + 2, size[1] + 2, size[2] + 2}};
  std::vector<InputPixelType> buffer(padded[0] * padded[1] * padded[2], static_cast<InputPixelType>(padValue));
  for (SizeValueType k = 0; k < size[2]; ++k)
  {
    for (SizeValueType j = 0; j < size[1]; ++j)
    {
      std::copy_n(values + size[0] * (j + size[1] * k), size[0],
                  buffer.data() + 1 + padded[0] * ((j + 1) + padded[1] * (k + 1)));
    }
  }
  this->Contour(buffer.data(), padded, {{start[0] - 1.0, start[1] - 1.0, start[2] - 1.0}});
  this->UpdateProgress(1.0f);
}

template <typename TInputImage, typename TOutputMesh>
void MarchingCubesImageToMeshFilter<TInputImage, TOutputMesh>::Contour(const InputPixelType* values,
                                                                       const std::array<SizeValueType, 3>& size,
                                                                       const std::array<double, 3>& start)
{
  using namespace MarchingCubesDetail;
  using PointsContainer = typename OutputMeshType::PointsContainer;
  using CellsContainer = typename OutputMeshType::CellsContainer;
  static_assert(std::is_same<typename PointsContainer::STLContainerType, std::vector<PointType>>::value &&
                  std::is_same<typename CellsContainer::STLContainerType, std::vector<CellType*>>::value,
                "MarchingCubesImageToMeshFilter writes VectorContainer points and cells (default mesh traits)");
  using T = InputPixelType;
  using CompactBlock = CompactTriangleCellBlock<CellType>;

  OutputMeshType* output = this->GetOutput();
  const SizeT nx = size[0];
  const SizeT ny = size[1];
  const SizeT nz = size[2];
  const double iso = m_IsoValue;
  T threshold{};
  if (nx < 2 || ny < 2 || nz < 2 || !ClassificationThreshold<T>(iso, threshold))
  {
    return; // no voxel, or nothing inside: no surface
  }

  const SizeT numberOfRows = ny * nz; // grid row r = j + ny * k: the points (0..nx-1, j, k)
  Rows rows(nx - 1, numberOfRows);
  const SizeT nex = rows.nex;
  // Per row: cut x-, y- and z-edges it owns (edges leaving its points towards +x, +y, +z).
  std::vector<Id> edgeCount(3 * numberOfRows);
  // Per row with j < ny-1 and k < nz-1: triangles of the voxel row whose lower corner row it is.
  std::vector<Id> triangleCount(numberOfRows, 0);

  const auto& cases = MarchingCubesTables::GetCases();
  const std::array<std::uint8_t, 256> trianglesPerCase = TrianglesPerCase(cases);

  MultiThreaderBase* threader = this->GetMultiThreader();
  // Eight slabs of slices per requested work unit (one slab if one work unit is requested): the pool's threads
  // then balance the uneven slices between them and cope with a busy machine. The output does not depend on it.
  const SizeT workUnits = this->GetNumberOfWorkUnits();
  threader->SetNumberOfWorkUnits(
    static_cast<ThreadIdType>(workUnits <= 1 ? 1 : std::min<SizeT>({nz, 8 * workUnits, SizeT{ITK_MAX_THREADS}})));

  // Pass 1: classify the x-edges of every row, count the cut ones and trim.
  threader->ParallelizeArray(
    0, nz,
    [&rows, &edgeCount, values, nx, ny, nex, threshold, iso](SizeT k) {
      for (SizeT r = ny * k; r < ny * (k + 1); ++r)
      {
        edgeCount[3 * r] = ClassifyAndTrimRow<T>(values + nx * r, rows.edgeCase.get() + nex * r, nex, threshold, iso,
                                                 rows.xL[r], rows.xR[r]);
      }
    },
    nullptr);
  this->UpdateProgress(0.3f);

  // Pass 2: count cut y- and z-edges per row and triangles per voxel row.
  threader->ParallelizeArray(
    0, nz,
    [&rows, &edgeCount, &triangleCount, &trianglesPerCase, ny, nz](SizeT k) {
      for (SizeT j = 0; j < ny; ++j)
      {
        CountRow(rows, j, k, ny, nz, trianglesPerCase.data(), edgeCount.data(), triangleCount.data());
      }
    },
    nullptr);
  this->UpdateProgress(0.5f);

  // Fixed id ranges per row, in row order: the same ids whatever the threading.
  std::vector<Id> pointOffset;
  std::vector<Id> triangleOffset;
  RowOffsets(edgeCount, triangleCount, pointOffset, triangleOffset);
  const Id numberOfPoints = pointOffset[numberOfRows];
  const Id numberOfTriangles = triangleOffset[numberOfRows];

  auto points = PointsContainer::New();
  points->Reserve(numberOfPoints);
  auto cells = CellsContainer::New();
  cells->Reserve(numberOfTriangles);
  std::shared_ptr<CompactBlock> block;
  if (m_CompactCells)
  {
    block = std::make_shared<CompactBlock>(numberOfTriangles);
  }

  // The table orients triangles in index space; a mirroring direction matrix flips them in physical space.
  const unsigned int second = IsMirroring(this->GetInput()->GetDirection()) ? 2 : 1;

  // Pass 3: the points of each row, then the triangles of each voxel row.
  // One argument per line would make this initialisation 17 lines.
  // clang-format off
  const SliceWriter<T, PointType, CellType> writer{
    values, nx, ny, nz, iso, rows, edgeCount.data(), pointOffset.data(), triangleOffset.data(), cases,
    this->IndexToPhysicalMap(start), second, 3 - second, points->CastToSTLContainer().data(),
    cells->CastToSTLContainer().data(), block.get()};
  // clang-format on
  if (m_CompactCells)
  {
    threader->ParallelizeArray(
      0, nz, [&writer](SizeT k) { writer.template WriteSlice<true>(k); }, nullptr);
  }
  else
  {
    threader->ParallelizeArray(
      0, nz, [&writer](SizeT k) { writer.template WriteSlice<false>(k); }, nullptr);
  }

  output->SetPoints(points);
  output->SetCells(cells);
  if (m_CompactCells)
  {
    TieCellBlockToContainer<CellsContainer, CellType>(cells.GetPointer(), block);
    output->SetCellsAllocationMethod(OutputMeshType::CellsAllocatedAsStaticArray);
  }
  else
  {
    output->SetCellsAllocationMethod(OutputMeshType::CellsAllocatedDynamicallyCellByCell);
  }
}

template <typename TInputImage, typename TOutputMesh>
MarchingCubesDetail::IndexToPhysical
MarchingCubesImageToMeshFilter<TInputImage, TOutputMesh>::IndexToPhysicalMap(const std::array<double, 3>& start)
{
  const InputImageType* input = this->GetInput();
  MarchingCubesDetail::IndexToPhysical map;
  for (unsigned int a = 0; a < 3; ++a)
  {
    map.origin[a] = input->GetOrigin()[a];
    for (unsigned int b = 0; b < 3; ++b)
    {
      map.matrix[3 * a + b] = input->GetDirection()[a][b] * input->GetSpacing()[b];
    }
  }
  for (unsigned int a = 0; a < 3; ++a)
  {
    map.origin[a] += map.matrix[3 * a] * start[0] + map.matrix[3 * a + 1] * start[1] + map.matrix[3 * a + 2] * start[2];
  }
  return map;
}

template <typename TInputImage, typename TOutputMesh>
void MarchingCubesImageToMeshFilter<TInputImage, TOutputMesh>::PrintSelf(std::ostream& os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "IsoValue: " << m_IsoValue << std::endl;
  os << indent << "PadBoundary: " << (m_PadBoundary ? "On" : "Off") << std::endl;
  os << indent << "CompactCells: " << (m_CompactCells ? "On" : "Off") << std::endl;
}
} // namespace itk

#endif
