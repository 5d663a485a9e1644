// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepNotImaged.h"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <limits>

namespace mmrep
{
namespace
{
constexpr double kMinPaddingShare = 0.02; // of the volume: a reconstruction circle, not stray voxels
constexpr double kMaxCutShare = 0.5;      // of the face's skin voxels: more is air clamped to the minimum
constexpr std::size_t kMinCutVoxels = 20; // a cut is a patch of skin; fewer voxels are strays of the noise

struct Grid
{
  std::int64_t n[3];
  std::int64_t Index(std::int64_t i, std::int64_t j, std::int64_t k) const { return i + n[0] * (j + n[1] * k); }
};

// Voxels of `value` reached from the volume's border through voxels of `value` (6-connected).
std::vector<std::uint8_t> FloodFromBorder(const short* v, const Grid& g, short value, std::size_t& count)
{
  const std::int64_t total = g.n[0] * g.n[1] * g.n[2];
  std::vector<std::uint8_t> flood(static_cast<std::size_t>(total), 0);
  std::deque<std::int64_t> queue;
  auto seed = [&](std::int64_t at) {
    if (v[at] == value && !flood[static_cast<std::size_t>(at)])
    {
      flood[static_cast<std::size_t>(at)] = 1;
      queue.push_back(at);
    }
  };
  for (std::int64_t k = 0; k < g.n[2]; ++k)
    for (std::int64_t j = 0; j < g.n[1]; ++j)
      for (std::int64_t i = 0; i < g.n[0]; ++i)
        if (i == 0 || j == 0 || k == 0 || i == g.n[0] - 1 || j == g.n[1] - 1 || k == g.n[2] - 1)
          seed(g.Index(i, j, k));
  const std::int64_t step[3] = {1, g.n[0], g.n[0] * g.n[1]};
  count = 0;
  while (!queue.empty())
  {
    const std::int64_t at = queue.front();
    queue.pop_front();
    ++count;
    std::int64_t c[3] = {at % g.n[0], (at / g.n[0]) % g.n[1], at / (g.n[0] * g.n[1])};
    for (int a = 0; a < 3; ++a)
    {
      if (c[a] > 0)
        seed(at - step[a]);
      if (c[a] < g.n[a] - 1)
        seed(at + step[a]);
    }
  }
  return flood;
}
} // namespace

NotImagedTissue FindNotImagedTissue(const CTImage* ct, double skinThreshold, const std::array<double, 6>* box)
{
  NotImagedTissue result;
  const auto region = ct->GetBufferedRegion();
  const Grid g{{static_cast<std::int64_t>(region.GetSize(0)), static_cast<std::int64_t>(region.GetSize(1)),
                static_cast<std::int64_t>(region.GetSize(2))}};
  const std::int64_t total = g.n[0] * g.n[1] * g.n[2];
  const short* v = ct->GetBufferPointer();
  if (total == 0 || v == nullptr)
    return result;
  result.paddingValue = *std::min_element(v, v + total);
  if (!(result.paddingValue < skinThreshold))
    return result;
  const auto flood = FloodFromBorder(v, g, result.paddingValue, result.paddingVoxels);
  if (static_cast<double>(result.paddingVoxels) < kMinPaddingShare * static_cast<double>(total))
    return result;

  // Skin voxels of the face: tissue with a neighbour below the threshold; cut: a neighbour in the padding.
  const std::int64_t step[3] = {1, g.n[0], g.n[0] * g.n[1]};
  std::size_t skinVoxels = 0;
  for (std::int64_t k = 0; k < g.n[2]; ++k)
    for (std::int64_t j = 0; j < g.n[1]; ++j)
      for (std::int64_t i = 0; i < g.n[0]; ++i)
      {
        const std::int64_t at = g.Index(i, j, k);
        if (!(v[at] >= skinThreshold))
          continue;
        bool air = false, measuredAir = false, padding = false;
        const std::int64_t c[3] = {i, j, k};
        for (int a = 0; a < 3; ++a)
          for (int side = -1; side <= 1; side += 2)
          {
            const std::int64_t n = c[a] + side;
            if (n < 0 || n >= g.n[a])
              continue;
            const std::int64_t next = at + side * step[a];
            const bool isPadding = flood[static_cast<std::size_t>(next)] != 0;
            air = air || v[next] < skinThreshold;
            measuredAir = measuredAir || (v[next] < skinThreshold && !isPadding);
            padding = padding || isPadding;
          }
        if (!air)
          continue;
        CTImage::IndexType index;
        index[0] = region.GetIndex(0) + i;
        index[1] = region.GetIndex(1) + j;
        index[2] = region.GetIndex(2) + k;
        CTImage::PointType p;
        ct->TransformIndexToPhysicalPoint(index, p);
        if (box != nullptr && (p[0] < (*box)[0] || p[0] > (*box)[1] || p[1] < (*box)[2] || p[1] > (*box)[3] ||
                               p[2] < (*box)[4] || p[2] > (*box)[5]))
          continue;
        ++skinVoxels;
        // A flat cut faces the padding alone; skin that also faces measured air met a thread of stray
        // minimum-valued voxels running through noisy air to the padding.
        if (padding && !measuredAir)
          result.cut.emplace_back(p[0], p[1], p[2]);
      }
  if (static_cast<double>(result.cut.size()) > kMaxCutShare * static_cast<double>(skinVoxels))
  {
    result.cut.clear(); // the minimum is the air itself, clamped: nothing tells imaged from not imaged
    return result;
  }
  result.padded = true;
  if (result.cut.size() < kMinCutVoxels)
    result.cut.clear();
  std::sort(result.cut.begin(), result.cut.end(), [](const Point3& a, const Point3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return result;
}

} // namespace mmrep
