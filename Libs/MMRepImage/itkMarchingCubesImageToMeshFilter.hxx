#ifndef itkMarchingCubesImageToMeshFilter_hxx
#define itkMarchingCubesImageToMeshFilter_hxx

#include "itkMarchingCubesImageToMeshFilter.h"

#include "itkCompactTriangleCell.h"
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
void
MarchingCubesImageToMeshFilter<TInputImage, TOutputMesh>::GenerateInputRequestedRegion()
{
  Superclass::GenerateInputRequestedRegion();
  // The surface needs every voxel.
  auto * input = const_cast<InputImageType *>(this->GetInput());
  if (input)
  {
    input->SetRequestedRegionToLargestPossibleRegion();
  }
}

template <typename TInputImage, typename TOutputMesh>
void
MarchingCubesImageToMeshFilter<TInputImage, TOutputMesh>::GenerateData()
{
  const InputImageType * input = this->GetInput();
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

  const auto                   region = input->GetBufferedRegion();
  std::array<SizeValueType, 3> size;
  std::array<double, 3>        start;
  for (unsigned int d = 0; d < 3; ++d)
  {
    size[d] = region.GetSize(d);
    start[d] = static_cast<double>(region.GetIndex(d));
  }
  const InputPixelType * values = input->GetBufferPointer();
  const SizeValueType    numberOfVoxels = region.GetNumberOfPixels();

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
  const std::array<SizeValueType, 3> padded{ { size[0] + 2, size[1] + 2, size[2] + 2 } };
  std::vector<InputPixelType> buffer(padded[0] * padded[1] * padded[2], static_cast<InputPixelType>(padValue));
  for (SizeValueType k = 0; k < size[2]; ++k)
  {
    for (SizeValueType j = 0; j < size[1]; ++j)
    {
      std::copy_n(values + size[0] * (j + size[1] * k),
                  size[0],
                  buffer.data() + 1 + padded[0] * ((j + 1) + padded[1] * (k + 1)));
    }
  }
  this->Contour(buffer.data(), padded, { { start[0] - 1.0, start[1] - 1.0, start[2] - 1.0 } });
  this->UpdateProgress(1.0f);
}

namespace MarchingCubesDetail
{
// The hot loops are free functions on raw pointers: inside lambdas that capture by reference, every byte store
// may alias the captured sizes, which then get reloaded and keep the loops from vectorising.
using Id = IdentifierType;
using SizeT = SizeValueType;

// x-edge code: bit 0 = class of the lower point, bit 1 = class of the upper point; the edge is cut when they differ.
inline unsigned int
Crossed(unsigned int code)
{
  return (code ^ (code >> 1)) & 1U;
}

// Byte-parallel scans: 8 edge codes per 64-bit word skip the long uniform stretches of a row quickly.
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
constexpr bool WordScan = true;
#else
constexpr bool WordScan = true;
#endif
constexpr std::uint64_t LowBits = 0x0101010101010101ULL;

inline std::uint64_t
Load8(const std::uint8_t * p)
{
  std::uint64_t w;
  std::memcpy(&w, p, sizeof(w));
  return w;
}

// Bit 8q set when byte q of w is the code of a cut edge.
inline std::uint64_t
CrossedMask(std::uint64_t w)
{
  return (w ^ (w >> 1)) & LowBits;
}

// Calls f(i) for every cut x-edge i in [first, last), in increasing i.
template <typename F>
void
ForEachCrossedEdge(const std::uint8_t * __restrict ec, SizeT first, SizeT last, F && f)
{
  SizeT i = first;
  if constexpr (WordScan)
  {
    for (; i + 8 <= last; i += 8)
    {
      for (std::uint64_t m = CrossedMask(Load8(ec + i)); m != 0; m &= m - 1)
      {
        f(i + static_cast<SizeT>(__builtin_ctzll(m) >> 3));
      }
    }
  }
  for (; i < last; ++i)
  {
    if (Crossed(ec[i]))
    {
      f(i);
    }
  }
}

template <typename T>
void
ClassifyRow(const T * __restrict s, std::uint8_t * __restrict ec, SizeT nex, T threshold, double iso)
{
  if constexpr (std::is_integral<T>::value)
  {
    (void)iso;
    for (SizeT i = 0; i < nex; ++i)
    {
      ec[i] = static_cast<std::uint8_t>((s[i] >= threshold) | ((s[i + 1] >= threshold) << 1));
    }
  }
  else
  {
    (void)threshold;
    for (SizeT i = 0; i < nex; ++i)
    {
      ec[i] = static_cast<std::uint8_t>((static_cast<double>(s[i]) >= iso) |
                                        ((static_cast<double>(s[i + 1]) >= iso) << 1));
    }
  }
}

// Per-row data shared by the passes.
struct Rows
{
  SizeT                      nex = 0; // x-edges per row (nx - 1)
  std::unique_ptr<std::uint8_t[]> edgeCase; // x-edge codes, row after row (not zeroed: pass 1 writes all)
  std::vector<SizeT>         xL; // intersected x-edges of a row lie in [xL, xR); outside, its points share a class
  std::vector<SizeT>         xR;

  const std::uint8_t *
  Codes(SizeT r) const
  {
    return edgeCase.get() + nex * r;
  }
  unsigned int
  FirstClass(SizeT r) const
  {
    return Codes(r)[0] & 1U;
  }
  unsigned int
  LastClass(SizeT r) const
  {
    return Codes(r)[nex - 1] >> 1;
  }
  // Points [lo, hi] where rows a and b may differ in class (the cut y- or z-edges between them); false if none.
  bool
  PairRange(SizeT a, SizeT b, SizeT & lo, SizeT & hi) const
  {
    lo = FirstClass(a) != FirstClass(b) ? 0 : std::min(xL[a], xL[b]);
    hi = LastClass(a) != LastClass(b) ? nex : std::max(xR[a], xR[b]);
    return lo <= hi;
  }
  // Voxels [L, R) of the voxel row with corner row r (rows r, r+1, r+ny, r+ny+1) whose case may be non-trivial.
  void
  VoxelRange(SizeT r, SizeT ny, SizeT & L, SizeT & R) const
  {
    const SizeT   rows[4] = { r, r + 1, r + ny, r + ny + 1 };
    unsigned int first = 0;
    unsigned int last = 0;
    L = nex;
    R = 0;
    for (unsigned int q = 0; q < 4; ++q)
    {
      L = std::min(L, xL[rows[q]]);
      R = std::max(R, xR[rows[q]]);
      first |= (FirstClass(rows[q]) * 3U) << (2 * q);
      last |= (LastClass(rows[q]) * 3U) << (2 * q);
    }
    if (first != 0 && first != 255)
    {
      L = 0;
    }
    if (last != 0 && last != 255)
    {
      R = nex;
    }
  }
};

inline Id
CountCrossedPairs(const std::uint8_t * __restrict a, const std::uint8_t * __restrict b, SizeT lo, SizeT hi, SizeT nex)
{
  std::uint32_t count = 0;
  const SizeT    end = std::min(hi + 1, nex);
  for (SizeT i = lo; i < end; ++i)
  {
    count += (a[i] ^ b[i]) & 1U;
  }
  if (hi == nex)
  {
    count += ((a[nex - 1] ^ b[nex - 1]) >> 1) & 1U;
  }
  return count;
}

// Calls f(i) for every point i in [lo, hi] where rows a and b differ, in increasing i.
template <typename F>
void
ForEachCrossedPair(const std::uint8_t * __restrict a, const std::uint8_t * __restrict b, SizeT lo, SizeT hi, SizeT nex, F && f)
{
  const SizeT end = std::min(hi + 1, nex);
  SizeT       i = lo;
  if constexpr (WordScan)
  {
    for (; i + 8 <= end; i += 8)
    {
      for (std::uint64_t m = (Load8(a + i) ^ Load8(b + i)) & LowBits; m != 0; m &= m - 1)
      {
        f(i + static_cast<SizeT>(__builtin_ctzll(m) >> 3));
      }
    }
  }
  for (; i < end; ++i)
  {
    if ((a[i] ^ b[i]) & 1U)
    {
      f(i);
    }
  }
  if (hi == nex && (((a[nex - 1] ^ b[nex - 1]) >> 1) & 1U))
  {
    f(nex);
  }
}

inline Id
CountTriangles(const std::uint8_t * __restrict e0,
               const std::uint8_t * __restrict e1,
               const std::uint8_t * __restrict e2,
               const std::uint8_t * __restrict e3,
               SizeT                            L,
               SizeT                            R,
               const std::uint8_t * __restrict trianglesPerCase)
{
  std::uint32_t count = 0;
  for (SizeT i = L; i < R; ++i)
  {
    count += trianglesPerCase[e0[i] | (e1[i] << 2) | (e2[i] << 4) | (e3[i] << 6)];
  }
  return count;
}
} // namespace MarchingCubesDetail

template <typename TInputImage, typename TOutputMesh>
void
MarchingCubesImageToMeshFilter<TInputImage, TOutputMesh>::Contour(const InputPixelType *               values,
                                                                  const std::array<SizeValueType, 3> & size,
                                                                  const std::array<double, 3> &        start)
{
  using namespace MarchingCubesDetail;
  using PointsContainer = typename OutputMeshType::PointsContainer;
  using CellsContainer = typename OutputMeshType::CellsContainer;
  static_assert(std::is_same<typename PointsContainer::STLContainerType, std::vector<PointType>>::value &&
                  std::is_same<typename CellsContainer::STLContainerType, std::vector<CellType *>>::value,
                "MarchingCubesImageToMeshFilter writes VectorContainer points and cells (default mesh traits)");
  using CoordRep = typename PointType::ValueType;
  using T = InputPixelType;
  using CompactBlock = CompactTriangleCellBlock<CellType>;

  OutputMeshType * output = this->GetOutput();
  const SizeT       nx = size[0];
  const SizeT       ny = size[1];
  const SizeT       nz = size[2];
  if (nx < 2 || ny < 2 || nz < 2)
  {
    return; // no voxel, no surface
  }
  const double iso = m_IsoValue;

  // Classification: value >= iso. For integer pixels compare against ceil(iso) in the pixel type (same result,
  // and the comparison vectorises).
  T threshold{};
  if constexpr (std::is_integral<T>::value)
  {
    const double c = std::ceil(iso);
    if (c > static_cast<double>(std::numeric_limits<T>::max()))
    {
      return; // nothing inside
    }
    threshold = c <= static_cast<double>(std::numeric_limits<T>::lowest()) ? std::numeric_limits<T>::lowest()
                                                                            : static_cast<T>(c);
  }

  const SizeT numberOfRows = ny * nz; // grid row r = j + ny * k: the points (0..nx-1, j, k)
  Rows       rows;
  rows.nex = nx - 1;
  rows.edgeCase.reset(new std::uint8_t[rows.nex * numberOfRows]);
  rows.xL.resize(numberOfRows);
  rows.xR.resize(numberOfRows);
  const SizeT nex = rows.nex;
  // Per row: cut x-, y- and z-edges it owns (edges leaving its points towards +x, +y, +z).
  std::vector<Id> edgeCount(3 * numberOfRows);
  // Per row with j < ny-1 and k < nz-1: triangles of the voxel row whose lower corner row it is.
  std::vector<Id> triangleCount(numberOfRows, 0);

  const auto &                  cases = MarchingCubesTables::GetCases();
  std::array<std::uint8_t, 256> trianglesPerCase;
  for (unsigned int c = 0; c < 256; ++c)
  {
    trianglesPerCase[c] = cases[c].NumberOfTriangles;
  }

  MultiThreaderBase * threader = this->GetMultiThreader();
  // Eight slabs of slices per requested work unit (one slab if one work unit is requested): the pool's threads
  // then balance the uneven slices between them and cope with a busy machine. The output does not depend on it.
  const SizeT workUnits = this->GetNumberOfWorkUnits();
  threader->SetNumberOfWorkUnits(static_cast<ThreadIdType>(
    workUnits <= 1 ? 1 : std::min<SizeT>({ nz, 8 * workUnits, SizeT{ ITK_MAX_THREADS } })));

  // Pass 1: classify the x-edges of every row, count the cut ones and trim.
  threader->ParallelizeArray(
    0,
    nz,
    [&rows, &edgeCount, values, nx, ny, nex, threshold, iso](SizeT k) {
      for (SizeT r = ny * k; r < ny * (k + 1); ++r)
      {
        std::uint8_t * ec = rows.edgeCase.get() + nex * r;
        ClassifyRow<T>(values + nx * r, ec, nex, threshold, iso);
        SizeT first = 0;
        if constexpr (WordScan)
        {
          while (first + 8 <= nex && CrossedMask(Load8(ec + first)) == 0)
          {
            first += 8;
          }
        }
        while (first < nex && !Crossed(ec[first]))
        {
          ++first;
        }
        SizeT last = nex;
        if constexpr (WordScan)
        {
          while (last >= first + 8 && CrossedMask(Load8(ec + last - 8)) == 0)
          {
            last -= 8;
          }
        }
        while (last > first && !Crossed(ec[last - 1]))
        {
          --last;
        }
        std::uint32_t count = 0;
        for (SizeT i = first; i < last; ++i)
        {
          count += Crossed(ec[i]);
        }
        rows.xL[r] = first < last ? first : nex;
        rows.xR[r] = first < last ? last : 0;
        edgeCount[3 * r] = count;
      }
    },
    nullptr);
  this->UpdateProgress(0.3f);

  // Pass 2: count cut y- and z-edges per row and triangles per voxel row.
  threader->ParallelizeArray(
    0,
    nz,
    [&rows, &edgeCount, &triangleCount, &trianglesPerCase, ny, nz, nex](SizeT k) {
      for (SizeT j = 0; j < ny; ++j)
      {
        const SizeT r = j + ny * k;
        SizeT       lo, hi;
        edgeCount[3 * r + 1] =
          (j + 1 < ny && rows.PairRange(r, r + 1, lo, hi)) ? CountCrossedPairs(rows.Codes(r), rows.Codes(r + 1), lo, hi, nex) : 0;
        edgeCount[3 * r + 2] =
          (k + 1 < nz && rows.PairRange(r, r + ny, lo, hi)) ? CountCrossedPairs(rows.Codes(r), rows.Codes(r + ny), lo, hi, nex) : 0;
        if (j + 1 < ny && k + 1 < nz)
        {
          SizeT L, R;
          rows.VoxelRange(r, ny, L, R);
          triangleCount[r] = CountTriangles(rows.Codes(r),
                                            rows.Codes(r + 1),
                                            rows.Codes(r + ny),
                                            rows.Codes(r + ny + 1),
                                            L,
                                            R,
                                            trianglesPerCase.data());
        }
      }
    },
    nullptr);
  this->UpdateProgress(0.5f);

  // Fixed id ranges per row, in row order: the same ids whatever the threading.
  std::vector<Id> pointOffset(numberOfRows + 1);
  std::vector<Id> triangleOffset(numberOfRows + 1);
  pointOffset[0] = 0;
  triangleOffset[0] = 0;
  for (SizeT r = 0; r < numberOfRows; ++r)
  {
    pointOffset[r + 1] = pointOffset[r] + edgeCount[3 * r] + edgeCount[3 * r + 1] + edgeCount[3 * r + 2];
    triangleOffset[r + 1] = triangleOffset[r] + triangleCount[r];
  }
  const Id numberOfPoints = pointOffset[numberOfRows];
  const Id numberOfTriangles = triangleOffset[numberOfRows];

  auto points = PointsContainer::New();
  points->Reserve(numberOfPoints);
  PointType * pointArray = points->CastToSTLContainer().data();
  auto        cells = CellsContainer::New();
  cells->Reserve(numberOfTriangles);
  CellType ** cellArray = cells->CastToSTLContainer().data();
  std::shared_ptr<CompactBlock> block;
  if (m_CompactCells)
  {
    block = std::make_shared<CompactBlock>(numberOfTriangles);
  }

  // Continuous index (relative to `start`) -> physical point: origin + Direction * Spacing * index.
  const InputImageType * input = this->GetInput();
  std::array<double, 9>  matrix;
  std::array<double, 3>  origin;
  for (unsigned int a = 0; a < 3; ++a)
  {
    origin[a] = input->GetOrigin()[a];
    for (unsigned int b = 0; b < 3; ++b)
    {
      matrix[3 * a + b] = input->GetDirection()[a][b] * input->GetSpacing()[b];
    }
  }
  for (unsigned int a = 0; a < 3; ++a)
  {
    origin[a] += matrix[3 * a] * start[0] + matrix[3 * a + 1] * start[1] + matrix[3 * a + 2] * start[2];
  }
  // The table orients triangles in index space; a mirroring direction matrix flips them in physical space.
  const auto & D = input->GetDirection();
  const double det = D[0][0] * (D[1][1] * D[2][2] - D[1][2] * D[2][1]) -
                     D[0][1] * (D[1][0] * D[2][2] - D[1][2] * D[2][0]) +
                     D[0][2] * (D[1][0] * D[2][1] - D[1][1] * D[2][0]);
  const unsigned int second = det < 0.0 ? 2 : 1;
  const unsigned int third = 3 - second;

  // Pass 3: the points of each row (its cut x-edges, then y-edges, then z-edges, each by increasing i), then the
  // triangles of each voxel row.
  const auto generate = [&, values, nx, ny, nz, nex, iso, pointArray, cellArray](SizeT k, auto compact) {
    const SizeT   nxy = nx * ny;
    const auto   setPoint = [&matrix, &origin, pointArray](Id id, double x, double y, double z) {
      PointType & p = pointArray[id];
      for (unsigned int a = 0; a < 3; ++a)
      {
        p[a] = static_cast<CoordRep>(origin[a] + matrix[3 * a] * x + matrix[3 * a + 1] * y + matrix[3 * a + 2] * z);
      }
    };
    CompactBlock * cellBlock = block.get();
    for (SizeT j = 0; j < ny; ++j)
    {
      const SizeT           r = j + ny * k;
      const T *            s = values + nx * r;
      const double         dj = static_cast<double>(j);
      const double         dk = static_cast<double>(k);
      const std::uint8_t * ec = rows.Codes(r);
      Id                   id = pointOffset[r];
      ForEachCrossedEdge(ec, rows.xL[r], rows.xR[r], [&](SizeT i) {
        const double s0 = static_cast<double>(s[i]);
        const double t = (iso - s0) / (static_cast<double>(s[i + 1]) - s0);
        setPoint(id++, static_cast<double>(i) + t, dj, dk);
      });
      SizeT lo, hi;
      if (j + 1 < ny && rows.PairRange(r, r + 1, lo, hi))
      {
        ForEachCrossedPair(ec, rows.Codes(r + 1), lo, hi, nex, [&](SizeT i) {
          const double s0 = static_cast<double>(s[i]);
          const double t = (iso - s0) / (static_cast<double>(s[i + nx]) - s0);
          setPoint(id++, static_cast<double>(i), dj + t, dk);
        });
      }
      if (k + 1 < nz && rows.PairRange(r, r + ny, lo, hi))
      {
        ForEachCrossedPair(ec, rows.Codes(r + ny), lo, hi, nex, [&](SizeT i) {
          const double s0 = static_cast<double>(s[i]);
          const double t = (iso - s0) / (static_cast<double>(s[i + nxy]) - s0);
          setPoint(id++, static_cast<double>(i), dj, dk + t);
        });
      }
      if (j + 1 == ny || k + 1 == nz)
      {
        continue;
      }

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
      const std::uint8_t * e0 = ec;
      const std::uint8_t * e1 = rows.Codes(r + 1);
      const std::uint8_t * e2 = rows.Codes(r + ny);
      const std::uint8_t * e3 = rows.Codes(r + ny + 1);
      SizeT                 L, R;
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
        const MarchingCubesTables::Case & c = cases[code];
        const unsigned int                m = c.IntersectedEdges;
        const Id ids[12] = { cx0, cx1, cx2, cx3, cy0, cy0 + ((m >> 4) & 1U), cy1, cy1 + ((m >> 6) & 1U),
                             cz0, cz0 + ((m >> 8) & 1U), cz1, cz1 + ((m >> 10) & 1U) };
        for (unsigned int t = 0; t < c.NumberOfTriangles; ++t, ++tri)
        {
          const std::uint8_t * edges = c.Edges.data() + 3 * t;
          if constexpr (decltype(compact)::value)
          {
            cellArray[tri] = cellBlock->Construct(tri, ids[edges[0]], ids[edges[second]], ids[edges[third]]);
          }
          else
          {
            auto *                cell = new TriangleCell<CellType>;
            const PointIdentifier triangle[3] = { ids[edges[0]], ids[edges[second]], ids[edges[third]] };
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
  if (m_CompactCells)
  {
    threader->ParallelizeArray(0, nz, [&generate](SizeT k) { generate(k, std::true_type{}); }, nullptr);
  }
  else
  {
    threader->ParallelizeArray(0, nz, [&generate](SizeT k) { generate(k, std::false_type{}); }, nullptr);
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
void
MarchingCubesImageToMeshFilter<TInputImage, TOutputMesh>::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "IsoValue: " << m_IsoValue << std::endl;
  os << indent << "PadBoundary: " << (m_PadBoundary ? "On" : "Off") << std::endl;
  os << indent << "CompactCells: " << (m_CompactCells ? "On" : "Off") << std::endl;
}
} // namespace itk

#endif
