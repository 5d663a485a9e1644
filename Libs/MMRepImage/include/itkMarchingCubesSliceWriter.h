// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#ifndef itkMarchingCubesSliceWriter_h
#define itkMarchingCubesSliceWriter_h

// Pass 3 of itk::MarchingCubesImageToMeshFilter: the points and triangles of one z-slice of rows, written at the
// id ranges fixed by the prefix sums of pass 2 (so any split into slices gives the same mesh). Internal.

#include "itkCompactTriangleCell.h"
#include "itkMarchingCubesRows.h"
#include "itkMarchingCubesTables.h"
#include "itkTriangleCell.h"

#include <array>

namespace itk
{
namespace MarchingCubesDetail
{
// Continuous index (relative to the contoured block) -> physical point: origin + Direction * Spacing * index.
struct IndexToPhysical
{
  std::array<double, 9> matrix;
  std::array<double, 3> origin;

  template <typename TPoint> void operator()(TPoint& p, double x, double y, double z) const
  {
    using CoordRep = typename TPoint::ValueType;
    for (unsigned int a = 0; a < 3; ++a)
    {
      p[a] = static_cast<CoordRep>(origin[a] + matrix[3 * a] * x + matrix[3 * a + 1] * y + matrix[3 * a + 2] * z);
    }
  }
};

// True when the direction matrix mirrors (negative determinant): triangles then take the other corner order.
template <typename TMatrix> bool IsMirroring(const TMatrix& D)
{
  const double det = D[0][0] * (D[1][1] * D[2][2] - D[1][2] * D[2][1]) -
                     D[0][1] * (D[1][0] * D[2][2] - D[1][2] * D[2][0]) +
                     D[0][2] * (D[1][0] * D[2][1] - D[1][1] * D[2][0]);
  return det < 0.0;
}

// Number of triangles of each of the 256 cases (pass 2 sums them per voxel row).
inline std::array<std::uint8_t, 256> TrianglesPerCase(const std::array<MarchingCubesTables::Case, 256>& cases)
{
  std::array<std::uint8_t, 256> count;
  for (unsigned int c = 0; c < 256; ++c)
  {
    count[c] = cases[c].NumberOfTriangles;
  }
  return count;
}

template <typename T, typename TPoint, typename TCell> struct SliceWriter
{
  using CompactBlock = CompactTriangleCellBlock<TCell>;
  using PointIdentifier = typename TCell::PointIdentifier;

  const T* values;
  SizeT nx, ny, nz;
  double iso;
  const Rows& rows;
  const Id* edgeCount;
  const Id* pointOffset;
  const Id* triangleOffset;
  const std::array<MarchingCubesTables::Case, 256>& cases;
  IndexToPhysical toPhysical;
  unsigned int second; // triangle corner order: 1, 2 (or 2, 1 when mirrored)
  unsigned int third;
  TPoint* pointArray;
  TCell** cellArray;
  CompactBlock* block;

  template <bool VCompact> void WriteSlice(SizeT k) const
  {
    for (SizeT j = 0; j < ny; ++j)
    {
      this->WritePoints(j, k);
      if (j + 1 < ny && k + 1 < nz)
      {
        this->template WriteTriangles<VCompact>(j, k);
      }
    }
  }

  // The points of row (j, k): its cut x-edges, then y-edges, then z-edges, each by increasing i.
  void WritePoints(SizeT j, SizeT k) const
  {
    const SizeT nex = rows.nex;
    const SizeT nxy = nx * ny;
    const SizeT r = j + ny * k;
    const T* s = values + nx * r;
    const double dj = static_cast<double>(j);
    const double dk = static_cast<double>(k);
    const std::uint8_t* ec = rows.Codes(r);
    Id id = pointOffset[r];
    ForEachCrossedEdge(ec, rows.xL[r], rows.xR[r], [&](SizeT i) {
      const double s0 = static_cast<double>(s[i]);
      const double t = (iso - s0) / (static_cast<double>(s[i + 1]) - s0);
      toPhysical(pointArray[id++], static_cast<double>(i) + t, dj, dk);
    });
    SizeT lo, hi;
    if (j + 1 < ny && rows.PairRange(r, r + 1, lo, hi))
    {
      ForEachCrossedPair(ec, rows.Codes(r + 1), lo, hi, nex, [&](SizeT i) {
        const double s0 = static_cast<double>(s[i]);
        const double t = (iso - s0) / (static_cast<double>(s[i + nx]) - s0);
        toPhysical(pointArray[id++], static_cast<double>(i), dj + t, dk);
      });
    }
    if (k + 1 < nz && rows.PairRange(r, r + ny, lo, hi))
    {
      ForEachCrossedPair(ec, rows.Codes(r + ny), lo, hi, nex, [&](SizeT i) {
        const double s0 = static_cast<double>(s[i]);
        const double t = (iso - s0) / (static_cast<double>(s[i + nxy]) - s0);
        toPhysical(pointArray[id++], static_cast<double>(i), dj, dk + t);
      });
    }
  }

  // The triangles of the voxel row whose lower corner row is (j, k), j < ny-1, k < nz-1.
  template <bool VCompact> void WriteTriangles(SizeT j, SizeT k) const
  {
    const SizeT r = j + ny * k;
    // Running ids of the next cut edge of each row the voxel row touches: x-edges of its four rows, y-edges of
    // rows (j,k) and (j,k+1), z-edges of rows (j,k) and (j+1,k). No edge before L is cut.
    Id cx0 = pointOffset[r];
    Id cx1 = pointOffset[r + 1];
    Id cx2 = pointOffset[r + ny];
    Id cx3 = pointOffset[r + ny + 1];
    Id cy0 = cx0 + edgeCount[3 * r];
    Id cy1 = cx2 + edgeCount[3 * (r + ny)];
    Id cz0 = cy0 + edgeCount[3 * r + 1];
    Id cz1 = cx1 + edgeCount[3 * (r + 1)] + edgeCount[3 * (r + 1) + 1];
    Id tri = triangleOffset[r];
    const std::uint8_t* e0 = rows.Codes(r);
    const std::uint8_t* e1 = rows.Codes(r + 1);
    const std::uint8_t* e2 = rows.Codes(r + ny);
    const std::uint8_t* e3 = rows.Codes(r + ny + 1);
    SizeT L, R;
    rows.VoxelRange(r, ny, L, R);
    for (SizeT i = L; i < R; ++i)
    {
      if constexpr (WordScan)
      {
        // Skip 8 voxels at once when their 8 corners all have one class (four equal rows of 0s or 3s).
        while (i + 8 <= R)
        {
          const std::uint64_t w = Load8(e0 + i);
          if (CrossedMask(w) != 0 || w != Load8(e1 + i) || w != Load8(e2 + i) || w != Load8(e3 + i))
          {
            break;
          }
          i += 8;
        }
        if (i >= R)
        {
          break;
        }
      }
      const unsigned int code = e0[i] | (e1[i] << 2) | (e2[i] << 4) | (e3[i] << 6);
      if (code == 0 || code == 255)
      {
        continue;
      }
      const MarchingCubesTables::Case& c = cases[code];
      const unsigned int m = c.IntersectedEdges;
      const Id ids[12] = {cx0, cx1,
                          cx2, cx3,
                          cy0, cy0 + ((m >> 4) & 1U),
                          cy1, cy1 + ((m >> 6) & 1U),
                          cz0, cz0 + ((m >> 8) & 1U),
                          cz1, cz1 + ((m >> 10) & 1U)};
      for (unsigned int t = 0; t < c.NumberOfTriangles; ++t, ++tri)
      {
        const std::uint8_t* edges = c.Edges.data() + 3 * t;
        if constexpr (VCompact)
        {
          cellArray[tri] = block->Construct(tri, ids[edges[0]], ids[edges[second]], ids[edges[third]]);
        }
        else
        {
          auto* cell = new TriangleCell<TCell>;
          const PointIdentifier triangle[3] = {ids[edges[0]], ids[edges[second]], ids[edges[third]]};
          cell->SetPointIds(triangle);
          cellArray[tri] = cell;
        }
      }
      cx0 += m & 1U;
      cx1 += (m >> 1) & 1U;
      cx2 += (m >> 2) & 1U;
      cx3 += (m >> 3) & 1U;
      cy0 += (m >> 4) & 1U;
      cy1 += (m >> 6) & 1U;
      cz0 += (m >> 8) & 1U;
      cz1 += (m >> 10) & 1U;
    }
  }
};
} // namespace MarchingCubesDetail
} // namespace itk

#endif
