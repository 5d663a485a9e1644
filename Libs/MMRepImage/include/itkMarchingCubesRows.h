// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#ifndef itkMarchingCubesRows_h
#define itkMarchingCubesRows_h

// Row scans of itk::MarchingCubesImageToMeshFilter (passes 1 and 2 of Flying Edges): x-edge classification,
// trimming, and the counts of cut edges and triangles per row. Internal to the filter.

#include "itkIntTypes.h"

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
namespace MarchingCubesDetail
{
// The hot loops are free functions on raw pointers: inside lambdas that capture by reference, every byte store
// may alias the captured sizes, which then get reloaded and keep the loops from vectorising.
using Id = IdentifierType;
using SizeT = SizeValueType;

// x-edge code: bit 0 = class of the lower point, bit 1 = class of the upper point; the edge is cut when they differ.
inline unsigned int Crossed(unsigned int code)
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

inline std::uint64_t Load8(const std::uint8_t* p)
{
  std::uint64_t w;
  std::memcpy(&w, p, sizeof(w));
  return w;
}

// Bit 8q set when byte q of w is the code of a cut edge.
inline std::uint64_t CrossedMask(std::uint64_t w)
{
  return (w ^ (w >> 1)) & LowBits;
}

// Calls f(i) for every cut x-edge i in [first, last), in increasing i.
template <typename F> void ForEachCrossedEdge(const std::uint8_t* __restrict ec, SizeT first, SizeT last, F&& f)
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
void ClassifyRow(const T* __restrict s, std::uint8_t* __restrict ec, SizeT nex, T threshold, double iso)
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
      ec[i] =
        static_cast<std::uint8_t>((static_cast<double>(s[i]) >= iso) | ((static_cast<double>(s[i + 1]) >= iso) << 1));
    }
  }
}

// Per-row data shared by the passes.
struct Rows
{
  Rows(SizeT numberOfXEdges, SizeT numberOfRows)
      : nex(numberOfXEdges), edgeCase(new std::uint8_t[numberOfXEdges * numberOfRows]), xL(numberOfRows),
        xR(numberOfRows)
  {
  }

  SizeT nex = 0;                            // x-edges per row (nx - 1)
  std::unique_ptr<std::uint8_t[]> edgeCase; // x-edge codes, row after row (not zeroed: pass 1 writes all)
  std::vector<SizeT> xL; // intersected x-edges of a row lie in [xL, xR); outside, its points share a class
  std::vector<SizeT> xR;

  const std::uint8_t* Codes(SizeT r) const { return edgeCase.get() + nex * r; }
  unsigned int FirstClass(SizeT r) const { return Codes(r)[0] & 1U; }
  unsigned int LastClass(SizeT r) const { return Codes(r)[nex - 1] >> 1; }
  // Points [lo, hi] where rows a and b may differ in class (the cut y- or z-edges between them); false if none.
  bool PairRange(SizeT a, SizeT b, SizeT& lo, SizeT& hi) const
  {
    lo = FirstClass(a) != FirstClass(b) ? 0 : std::min(xL[a], xL[b]);
    hi = LastClass(a) != LastClass(b) ? nex : std::max(xR[a], xR[b]);
    return lo <= hi;
  }
  // Voxels [L, R) of the voxel row with corner row r (rows r, r+1, r+ny, r+ny+1) whose case may be non-trivial.
  void VoxelRange(SizeT r, SizeT ny, SizeT& L, SizeT& R) const
  {
    const SizeT rows[4] = {r, r + 1, r + ny, r + ny + 1};
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

inline Id CountCrossedPairs(const std::uint8_t* __restrict a, const std::uint8_t* __restrict b, SizeT lo, SizeT hi,
                            SizeT nex)
{
  std::uint32_t count = 0;
  const SizeT end = std::min(hi + 1, nex);
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
void ForEachCrossedPair(const std::uint8_t* __restrict a, const std::uint8_t* __restrict b, SizeT lo, SizeT hi,
                        SizeT nex, F&& f)
{
  const SizeT end = std::min(hi + 1, nex);
  SizeT i = lo;
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

inline Id CountTriangles(const std::uint8_t* __restrict e0, const std::uint8_t* __restrict e1,
                         const std::uint8_t* __restrict e2, const std::uint8_t* __restrict e3, SizeT L, SizeT R,
                         const std::uint8_t* __restrict trianglesPerCase)
{
  std::uint32_t count = 0;
  for (SizeT i = L; i < R; ++i)
  {
    count += trianglesPerCase[e0[i] | (e1[i] << 2) | (e2[i] << 4) | (e3[i] << 6)];
  }
  return count;
}

// Classification is value >= iso. For integer pixels the rows compare against ceil(iso) in the pixel type (same
// result, and the comparison vectorises); false when no value of T reaches iso.
template <typename T> bool ClassificationThreshold(double iso, T& threshold)
{
  if constexpr (std::is_integral<T>::value)
  {
    const double c = std::ceil(iso);
    if (c > static_cast<double>(std::numeric_limits<T>::max()))
    {
      return false;
    }
    threshold =
      c <= static_cast<double>(std::numeric_limits<T>::lowest()) ? std::numeric_limits<T>::lowest() : static_cast<T>(c);
  }
  return true;
}

// Pass 1 on one row: classify its x-edges into ec, trim the uniform stretches at both ends ([xL, xR) holds
// every cut edge; xL = nex, xR = 0 when none) and return the number of cut x-edges.
template <typename T>
Id ClassifyAndTrimRow(const T* s, std::uint8_t* ec, SizeT nex, T threshold, double iso, SizeT& xL, SizeT& xR)
{
  ClassifyRow<T>(s, ec, nex, threshold, iso);
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
  xL = first < last ? first : nex;
  xR = first < last ? last : 0;
  return count;
}

// Pass 2 on row r = j + ny k: its cut y- and z-edges (edgeCount[3r+1], [3r+2]) and the triangles of the voxel row
// whose lower corner row it is (triangleCount[r], only for j < ny-1 and k < nz-1).
inline void CountRow(const Rows& rows, SizeT j, SizeT k, SizeT ny, SizeT nz, const std::uint8_t* trianglesPerCase,
                     Id* edgeCount, Id* triangleCount)
{
  const SizeT nex = rows.nex;
  const SizeT r = j + ny * k;
  SizeT lo, hi;
  edgeCount[3 * r + 1] = (j + 1 < ny && rows.PairRange(r, r + 1, lo, hi))
                           ? CountCrossedPairs(rows.Codes(r), rows.Codes(r + 1), lo, hi, nex)
                           : 0;
  edgeCount[3 * r + 2] = (k + 1 < nz && rows.PairRange(r, r + ny, lo, hi))
                           ? CountCrossedPairs(rows.Codes(r), rows.Codes(r + ny), lo, hi, nex)
                           : 0;
  if (j + 1 < ny && k + 1 < nz)
  {
    SizeT L, R;
    rows.VoxelRange(r, ny, L, R);
    triangleCount[r] = CountTriangles(rows.Codes(r), rows.Codes(r + 1), rows.Codes(r + ny), rows.Codes(r + ny + 1), L,
                                      R, trianglesPerCase);
  }
}
// Prefix sums over rows: row r owns points [pointOffset[r], pointOffset[r+1]) and triangles
// [triangleOffset[r], triangleOffset[r+1]).
inline void RowOffsets(const std::vector<Id>& edgeCount, const std::vector<Id>& triangleCount,
                       std::vector<Id>& pointOffset, std::vector<Id>& triangleOffset)
{
  const SizeT numberOfRows = triangleCount.size();
  pointOffset.assign(numberOfRows + 1, 0);
  triangleOffset.assign(numberOfRows + 1, 0);
  for (SizeT r = 0; r < numberOfRows; ++r)
  {
    pointOffset[r + 1] = pointOffset[r] + edgeCount[3 * r] + edgeCount[3 * r + 1] + edgeCount[3 * r + 2];
    triangleOffset[r + 1] = triangleOffset[r] + triangleCount[r];
  }
}
} // namespace MarchingCubesDetail
} // namespace itk

#endif
