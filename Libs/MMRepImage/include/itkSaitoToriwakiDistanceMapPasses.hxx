// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#ifndef itkSaitoToriwakiDistanceMapPasses_hxx
#define itkSaitoToriwakiDistanceMapPasses_hxx

// The passes of itk::SaitoToriwakiDistanceMapImageFilter: the 1-D distance along x (with the boundary of the
// signed distance), then one lower-envelope pass per further axis. Included by the filter's .hxx.

#include "itkSaitoToriwakiLineEnvelope.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace itk
{
template <typename TInputImage, typename TOutputImage>
template <bool VTrackNearest>
void SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::FirstAxisPass(const Context& c,
                                                                                   const OutputImageRegionType& region,
                                                                                   bool& anyForeground,
                                                                                   bool& anyFeature) const
{
  using Flag = unsigned char;
  const SizeValueType nx = c.size[0];
  const auto none = static_cast<std::int64_t>(nx) + 1; // "no feature on this side"
  const bool useForeground = m_UseForegroundValue;
  const InputPixelType foregroundValue = m_ForegroundValue;
  const InputPixelType backgroundValue = m_BackgroundValue;
  constexpr bool isFinal = ImageDimension == 1;

  // Squared length of d steps along x; the entry past the longest possible run means "no feature".
  std::vector<OutputPixelType> squaredOfSteps(nx + 2);
  for (SizeValueType d = 0; d <= nx; ++d)
  {
    const double length = static_cast<double>(d) * c.weight[0];
    squaredOfSteps[d] = static_cast<OutputPixelType>(length * length);
  }
  squaredOfSteps[nx + 1] = std::numeric_limits<OutputPixelType>::infinity();

  std::vector<Flag> foreground(nx);
  std::vector<Flag> nearBackground(m_SignedDistance ? nx + 2 : 0); // padded by one on both sides
  std::vector<Flag> boundary(m_SignedDistance ? nx : 0);
  std::vector<std::int64_t> toLeft(nx);

  SaitoToriwakiDetail::ForEachOuter<ImageDimension>(
    region, c.stride, 0, 0, [&](SizeValueType base, const IndexValueType* index) {
      const InputPixelType* in = c.input + base;
      Flag* const fg = foreground.data();
      Flag lineForeground = 0;
      if (useForeground)
      {
        for (SizeValueType x = 0; x < nx; ++x)
        {
          fg[x] = static_cast<Flag>(in[x] == foregroundValue);
          lineForeground |= fg[x];
        }
      }
      else
      {
        for (SizeValueType x = 0; x < nx; ++x)
        {
          fg[x] = static_cast<Flag>(in[x] != backgroundValue);
          lineForeground |= fg[x];
        }
      }
      anyForeground = anyForeground || lineForeground != 0;

      const Flag* feature = fg;
      if (m_SignedDistance)
      {
        std::fill(boundary.begin(), boundary.end(), Flag{0});
        if (lineForeground)
        {
          this->FlagBoundary(c, in, index, fg, nearBackground.data(), boundary.data());
        }
        feature = boundary.data();
      }

      // 1-D distance in steps: to the nearest feature on the left (forward scan), then on the right
      // (backward scan); ties go left. Branch-free: step counts are capped at `none`, whose square is +inf.
      OutputPixelType* out = c.output + base;
      std::int64_t last = -none;
      for (SizeValueType x = 0; x < nx; ++x)
      {
        const auto xi = static_cast<std::int64_t>(x);
        last = feature[x] ? xi : last;
        toLeft[x] = std::min(xi - last, none);
      }
      if (last < 0)
      {
        std::fill(out, out + nx, std::numeric_limits<OutputPixelType>::infinity());
        return;
      }
      anyFeature = true;
      std::int64_t next = static_cast<std::int64_t>(nx) + none;
      for (SizeValueType x = nx; x-- > 0;)
      {
        const auto xi = static_cast<std::int64_t>(x);
        next = feature[x] ? xi : next;
        const std::int64_t right = std::min(next - xi, none);
        const std::int64_t steps = std::min(toLeft[x], right);
        if (isFinal || VTrackNearest)
        {
          const std::int64_t q = toLeft[x] <= right ? xi - toLeft[x] : next;
          if (isFinal)
          {
            this->template StoreFinal<VTrackNearest>(c, base + x, static_cast<double>(squaredOfSteps[steps]),
                                                     base + static_cast<SizeValueType>(q));
            continue;
          }
          c.nearest[base + x] = base + static_cast<SizeValueType>(q);
        }
        out[x] = squaredOfSteps[steps];
      }
    });
}

template <typename TInputImage, typename TOutputImage>
template <bool VTrackNearest>
void SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::EnvelopePass(
  const Context& c, unsigned int d, const OutputImageRegionType& region) const
{
  // Neighbouring x-lines are processed together: each row of the block is read and written as a
  // contiguous run of blockWidth values (whole cache lines, prefetcher friendly) and transposed into
  // contiguous per-line buffers. 64 floats per row keeps the buffers of a 256-sample line in L2.
  constexpr SizeValueType blockWidth = 64;
  const SizeValueType n = c.size[d];
  const SizeValueType stride = c.stride[d];
  const double w = c.weight[d];
  const bool isFinal = d + 1 == ImageDimension;
  const bool squaredDistance = m_SquaredDistance;
  const bool signedDistance = m_SignedDistance;
  const bool insideIsPositive = m_InsideIsPositive;
  const bool useForeground = m_UseForegroundValue;
  const InputPixelType foregroundValue = m_ForegroundValue;
  const InputPixelType backgroundValue = m_BackgroundValue;

  std::vector<float> f(blockWidth * n);
  std::vector<float> g(blockWidth * n);
  std::vector<std::uint32_t> arg(VTrackNearest ? blockWidth * n : 0);
  std::vector<SizeValueType> sourceNearest(VTrackNearest ? blockWidth * n : 0);
  SaitoToriwakiDetail::EnvelopeScratch scratch(n);

  const auto xBegin = static_cast<SizeValueType>(region.GetIndex(0));
  const auto xEnd = xBegin + region.GetSize(0);

  SaitoToriwakiDetail::ForEachOuter<ImageDimension>(
    region, c.stride, 0, d, [&](SizeValueType base, const IndexValueType*) {
      for (SizeValueType xb = xBegin; xb < xEnd; xb += blockWidth)
      {
        const SizeValueType width = std::min(blockWidth, xEnd - xb);
        const SizeValueType first = base + xb;
        for (SizeValueType j = 0; j < n; ++j)
        {
          const OutputPixelType* src = c.output + first + j * stride;
          for (SizeValueType b = 0; b < width; ++b)
          {
            f[b * n + j] = static_cast<float>(src[b]);
          }
          if (VTrackNearest)
          {
            const SizeValueType* srcNearest = c.nearest + first + j * stride;
            for (SizeValueType b = 0; b < width; ++b)
            {
              sourceNearest[b * n + j] = srcNearest[b];
            }
          }
        }
        for (SizeValueType b = 0; b < width; ++b)
        {
          SaitoToriwakiDetail::LowerEnvelope<VTrackNearest>(&f[b * n], n, w, &g[b * n],
                                                            VTrackNearest ? &arg[b * n] : nullptr, scratch);
        }
        for (SizeValueType j = 0; j < n; ++j)
        {
          const SizeValueType p0 = first + j * stride;
          if (!VTrackNearest)
          {
            // Hot paths without the nearest vector, written so the compiler can vectorise them.
            OutputPixelType* dst = c.output + p0;
            const float* gj = &g[j];
            if (!isFinal || squaredDistance)
            {
              for (SizeValueType b = 0; b < width; ++b)
              {
                dst[b] = static_cast<OutputPixelType>(gj[b * n]);
              }
            }
            else
            {
              for (SizeValueType b = 0; b < width; ++b)
              {
                dst[b] = static_cast<OutputPixelType>(std::sqrt(gj[b * n]));
              }
            }
            if (isFinal && signedDistance)
            {
              const InputPixelType* in = c.input + p0;
              for (SizeValueType b = 0; b < width; ++b)
              {
                const bool inside = useForeground ? in[b] == foregroundValue : in[b] != backgroundValue;
                dst[b] = inside != insideIsPositive ? -dst[b] : dst[b];
              }
            }
            continue;
          }
          for (SizeValueType b = 0; b < width; ++b)
          {
            const SizeValueType near = VTrackNearest ? sourceNearest[b * n + arg[b * n + j]] : 0;
            if (isFinal)
            {
              this->template StoreFinal<VTrackNearest>(c, p0 + b, static_cast<double>(g[b * n + j]), near);
            }
            else
            {
              c.output[p0 + b] = static_cast<OutputPixelType>(g[b * n + j]);
              c.nearest[p0 + b] = near;
            }
          }
        }
      }
    });
}

template <typename TInputImage, typename TOutputImage>
void SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::FlagBoundary(
  const Context& c, const InputPixelType* in, const IndexValueType* index, const unsigned char* fg,
  unsigned char* nearBackground, unsigned char* boundary) const
{
  using Flag = unsigned char;
  const SizeValueType nx = c.size[0];
  const bool useForeground = m_UseForegroundValue;
  const InputPixelType foregroundValue = m_ForegroundValue;
  const InputPixelType backgroundValue = m_BackgroundValue;
  unsigned int neighbourLines = 1; // 3^(D-1) lines around (and including) this one
  for (unsigned int k = 1; k < ImageDimension; ++k)
  {
    neighbourLines *= 3;
  }
  Flag* const bd = boundary;
  Flag* const nb = nearBackground + 1;
  std::fill(nearBackground, nearBackground + nx + 2, Flag{0});
  // Boundary = foreground with a background pixel among its in-image 3^D-1 neighbours, as in
  // SignedMaurer's fully connected BinaryContourImageFilter; the image border is not background.
  for (unsigned int code = 0; code < neighbourLines; ++code)
  {
    OffsetValueType offset = 0;
    bool inside = true;
    unsigned int digits = code;
    for (unsigned int k = 1; k < ImageDimension; ++k)
    {
      const int o = static_cast<int>(digits % 3) - 1;
      const IndexValueType j = index[k] + o;
      digits /= 3;
      if (j < 0 || j >= static_cast<IndexValueType>(c.size[k]))
      {
        inside = false;
        break;
      }
      offset += o * static_cast<OffsetValueType>(c.stride[k]);
    }
    if (!inside)
    {
      continue;
    }
    const InputPixelType* line = in + offset;
    if (useForeground)
    {
      for (SizeValueType x = 0; x < nx; ++x)
      {
        nb[x] |= static_cast<Flag>(line[x] != foregroundValue);
      }
    }
    else
    {
      for (SizeValueType x = 0; x < nx; ++x)
      {
        nb[x] |= static_cast<Flag>(line[x] == backgroundValue);
      }
    }
  }
  for (SizeValueType x = 0; x < nx; ++x)
  {
    bd[x] = static_cast<Flag>(fg[x] & (nb[x - 1] | nb[x] | nb[x + 1]));
  }
}
} // namespace itk

#endif
