// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#ifndef itkSaitoToriwakiLineEnvelope_h
#define itkSaitoToriwakiLineEnvelope_h

// Line kernels of itk::SaitoToriwakiDistanceMapImageFilter: iteration over the image lines along one axis and
// the lower envelope of parabolas that gives the squared distance along a line. Internal to the filter.

#include "itkImageRegion.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace itk
{
namespace SaitoToriwakiDetail
{
// Calls f(base, index) once per combination of the region's indices on the axes other than skipA and
// skipB; base is the linear offset of that combination (skipped axes at 0). The region is zero-based.
template <unsigned int VDimension, typename TFunction>
void ForEachOuter(const ImageRegion<VDimension>& region, const SizeValueType* stride, unsigned int skipA,
                  unsigned int skipB, TFunction&& f)
{
  IndexValueType index[VDimension];
  for (unsigned int k = 0; k < VDimension; ++k)
  {
    if (region.GetSize(k) == 0)
    {
      return;
    }
    index[k] = region.GetIndex(k);
  }
  for (;;)
  {
    SizeValueType base = 0;
    for (unsigned int k = 0; k < VDimension; ++k)
    {
      if (k != skipA && k != skipB)
      {
        base += static_cast<SizeValueType>(index[k]) * stride[k];
      }
    }
    f(base, static_cast<const IndexValueType*>(index));
    unsigned int k = 0;
    for (; k < VDimension; ++k)
    {
      if (k == skipA || k == skipB)
      {
        continue;
      }
      if (++index[k] < region.GetIndex(k) + static_cast<IndexValueType>(region.GetSize(k)))
      {
        break;
      }
      index[k] = region.GetIndex(k);
    }
    if (k == VDimension)
    {
      return;
    }
  }
}

// Scratch of one line's lower envelope: site index, position, value, value + position^2, start.
struct EnvelopeScratch
{
  explicit EnvelopeScratch(SizeValueType n) : site(n), x(n), f(n), h(n), z(n + 1) {}
  std::vector<std::uint32_t> site;
  std::vector<double> x;
  std::vector<double> f;
  std::vector<double> h;
  std::vector<double> z;
};

// g[i] = min_j f[j] + ((i - j) w)^2 and arg[i] = the minimising j, for the n samples of one line
// (f[j] = +inf where there is no site). Lower envelope of the parabolas rooted at the sites
// (Felzenszwalb & Huttenlocher): sites are pushed left to right, popping those the new parabola hides;
// z[k] is where parabola k starts to be lowest. Linear time. Arithmetic in double: the intersection
// abscissa subtracts terms of size (n w)^2, which float would round to a visible error.
template <bool VTrackArg>
inline void LowerEnvelope(const float* f, SizeValueType n, double w, float* g, std::uint32_t* arg, EnvelopeScratch& e)
{
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::uint32_t* const site = e.site.data();
  double* const sx = e.x.data();
  double* const sf = e.f.data();
  double* const sh = e.h.data();
  double* const z = e.z.data();
  std::ptrdiff_t k = -1;
  for (SizeValueType q = 0; q < n; ++q)
  {
    const double fq = f[q];
    if (!(fq < inf))
    {
      continue;
    }
    const double xq = static_cast<double>(q) * w;
    const double hq = fq + xq * xq;
    // Pop while the new parabola is lower at the start of the top one: s <= z[k] with
    // s = (hq - sh[k]) / (2 (xq - sx[k])), tested without the division (the denominator is > 0).
    while (k >= 0 && (hq - sh[k]) <= z[k] * (2.0 * (xq - sx[k])))
    {
      --k;
    }
    const double s = k >= 0 ? (hq - sh[k]) / (2.0 * (xq - sx[k])) : -inf;
    ++k;
    site[k] = static_cast<std::uint32_t>(q);
    sx[k] = xq;
    sf[k] = fq;
    sh[k] = hq;
    z[k] = k == 0 ? -inf : s;
  }
  if (k < 0)
  {
    std::fill(g, g + n, std::numeric_limits<float>::infinity());
    return;
  }
  z[k + 1] = inf;
  std::ptrdiff_t j = 0;
  for (SizeValueType i = 0; i < n; ++i)
  {
    const double x = static_cast<double>(i) * w;
    while (z[j + 1] < x)
    {
      ++j;
    }
    const double dx = x - sx[j];
    g[i] = static_cast<float>(sf[j] + dx * dx);
    if (VTrackArg)
    {
      arg[i] = site[j];
    }
  }
}
} // namespace SaitoToriwakiDetail
} // namespace itk

#endif
