#ifndef itkSaitoToriwakiDistanceMapImageFilter_hxx
#define itkSaitoToriwakiDistanceMapImageFilter_hxx

#include "itkSaitoToriwakiDistanceMapImageFilter.h"

#include "itkMultiThreaderBase.h"
#include "itkNumericTraits.h"
#include "itkProgressTransformer.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cmath>
#include <limits>

namespace itk
{
namespace SaitoToriwakiDetail
{
// Calls f(base, index) once per combination of the region's indices on the axes other than skipA and
// skipB; base is the linear offset of that combination (skipped axes at 0). The region is zero-based.
template <unsigned int VDimension, typename TFunction>
void
ForEachOuter(const ImageRegion<VDimension> & region,
             const SizeValueType *           stride,
             unsigned int                    skipA,
             unsigned int                    skipB,
             TFunction &&                    f)
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
    f(base, static_cast<const IndexValueType *>(index));
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
  explicit EnvelopeScratch(SizeValueType n)
    : site(n)
    , x(n)
    , f(n)
    , h(n)
    , z(n + 1)
  {}
  std::vector<std::uint32_t> site;
  std::vector<double>        x;
  std::vector<double>        f;
  std::vector<double>        h;
  std::vector<double>        z;
};

// g[i] = min_j f[j] + ((i - j) w)^2 and arg[i] = the minimising j, for the n samples of one line
// (f[j] = +inf where there is no site). Lower envelope of the parabolas rooted at the sites
// (Felzenszwalb & Huttenlocher): sites are pushed left to right, popping those the new parabola hides;
// z[k] is where parabola k starts to be lowest. Linear time. Arithmetic in double: the intersection
// abscissa subtracts terms of size (n w)^2, which float would round to a visible error.
template <bool VTrackArg>
inline void
LowerEnvelope(const float * f, SizeValueType n, double w, float * g, std::uint32_t * arg, EnvelopeScratch & e)
{
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::uint32_t * const site = e.site.data();
  double * const        sx = e.x.data();
  double * const        sf = e.f.data();
  double * const        sh = e.h.data();
  double * const        z = e.z.data();
  std::ptrdiff_t        k = -1;
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

template <typename TInputImage, typename TOutputImage>
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::SaitoToriwakiDistanceMapImageFilter()
{
  m_BackgroundValue = NumericTraits<InputPixelType>::ZeroValue();
  m_ForegroundValue = NumericTraits<InputPixelType>::OneValue();
  this->SetNumberOfRequiredOutputs(2);
  this->SetNthOutput(0, this->MakeOutput(0));
  this->SetNthOutput(1, this->MakeOutput(1));
  this->DynamicMultiThreadingOn();
}

template <typename TInputImage, typename TOutputImage>
void
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::SetForegroundValue(const InputPixelType & value)
{
  if (m_ForegroundValue != value || !m_UseForegroundValue)
  {
    m_ForegroundValue = value;
    m_UseForegroundValue = true;
    this->Modified();
  }
}

template <typename TInputImage, typename TOutputImage>
typename SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::DataObjectPointer
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::MakeOutput(DataObjectPointerArraySizeType idx)
{
  if (idx == 1)
  {
    return NearestVectorImageType::New().GetPointer();
  }
  return Superclass::MakeOutput(idx);
}

template <typename TInputImage, typename TOutputImage>
typename SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::NearestVectorImageType *
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::GetNearestVectorOutput()
{
  return dynamic_cast<NearestVectorImageType *>(this->ProcessObject::GetOutput(1));
}

template <typename TInputImage, typename TOutputImage>
void
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::GenerateInputRequestedRegion()
{
  Superclass::GenerateInputRequestedRegion();
  // Distances depend on the whole image.
  if (auto * input = const_cast<InputImageType *>(this->GetInput()))
  {
    input->SetRequestedRegionToLargestPossibleRegion();
  }
}

template <typename TInputImage, typename TOutputImage>
void
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::EnlargeOutputRequestedRegion(DataObject *)
{
  for (unsigned int i = 0; i < this->GetNumberOfIndexedOutputs(); ++i)
  {
    if (auto * image = dynamic_cast<ImageBase<ImageDimension> *>(this->ProcessObject::GetOutput(i)))
    {
      image->SetRequestedRegionToLargestPossibleRegion();
    }
  }
}

template <typename TInputImage, typename TOutputImage>
void
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::AllocateOutputs()
{
  OutputImageType * output = this->GetOutput();
  output->SetBufferedRegion(output->GetRequestedRegion());
  output->Allocate();
  NearestVectorImageType * vectors = this->GetNearestVectorOutput();
  if (m_ComputeNearestVector)
  {
    vectors->SetBufferedRegion(vectors->GetRequestedRegion());
    vectors->Allocate();
  }
  else
  {
    vectors->Initialize(); // keeps the geometry, drops any buffer
  }
}

template <typename TInputImage, typename TOutputImage>
void
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::GenerateData()
{
  this->AllocateOutputs();
  const InputImageType * input = this->GetInput();
  OutputImageType *      output = this->GetOutput();
  const SizeType         size = output->GetBufferedRegion().GetSize();
  if (input->GetBufferedRegion().GetSize() != size)
  {
    itkExceptionMacro("input buffered region " << input->GetBufferedRegion() << " differs from the output region "
                                               << output->GetBufferedRegion());
  }
  if (output->GetBufferedRegion().GetNumberOfPixels() == 0)
  {
    itkExceptionMacro("input has no foreground voxel (the image is empty): a distance map to nothing is meaningless");
  }

  Context c;
  c.input = input->GetBufferPointer();
  c.output = output->GetBufferPointer();
  SizeValueType stride = 1;
  for (unsigned int k = 0; k < ImageDimension; ++k)
  {
    c.size[k] = size[k];
    c.stride[k] = stride;
    stride *= size[k];
    c.weight[k] = m_UseImageSpacing ? static_cast<double>(output->GetSpacing()[k]) : 1.0;
    for (unsigned int m = 0; m < ImageDimension; ++m)
    {
      c.direction[k][m] = output->GetDirection()[k][m];
    }
  }
  std::vector<SizeValueType> nearest;
  if (m_ComputeNearestVector)
  {
    nearest.assign(stride, 0);
    c.nearest = nearest.data();
    c.vectors = this->GetNearestVectorOutput()->GetBufferPointer();
  }

  // Zero-based lattice: only used to split lines among work units.
  OutputImageRegionType lattice;
  lattice.SetSize(size);

  MultiThreaderBase * threader = this->GetMultiThreader();
  threader->SetNumberOfWorkUnits(this->GetNumberOfWorkUnits());
  const float passShare = 1.0f / static_cast<float>(ImageDimension);

  std::atomic<bool> anyForeground{ false };
  std::atomic<bool> anyFeature{ false };
  {
    ProgressTransformer progress(0.0f, passShare, this);
    threader->template ParallelizeImageRegionRestrictDirection<ImageDimension>(
      0,
      lattice,
      [&](const OutputImageRegionType & region) {
        bool foreground = false;
        bool feature = false;
        if (m_ComputeNearestVector)
        {
          this->template FirstAxisPass<true>(c, region, foreground, feature);
        }
        else
        {
          this->template FirstAxisPass<false>(c, region, foreground, feature);
        }
        if (foreground)
        {
          anyForeground = true;
        }
        if (feature)
        {
          anyFeature = true;
        }
      },
      progress.GetProcessObject());
  }
  if (!anyForeground)
  {
    itkExceptionMacro("input has no foreground voxel: a distance map to nothing is meaningless");
  }
  if (!anyFeature)
  {
    itkExceptionMacro("input has no background voxel, so the object has no boundary: the signed distance is undefined");
  }

  for (unsigned int d = 1; d < ImageDimension; ++d)
  {
    ProgressTransformer progress(passShare * static_cast<float>(d), passShare * static_cast<float>(d + 1), this);
    threader->template ParallelizeImageRegionRestrictDirection<ImageDimension>(
      d,
      lattice,
      [&](const OutputImageRegionType & region) {
        if (m_ComputeNearestVector)
        {
          this->template EnvelopePass<true>(c, d, region);
        }
        else
        {
          this->template EnvelopePass<false>(c, d, region);
        }
      },
      progress.GetProcessObject());
  }
}

template <typename TInputImage, typename TOutputImage>
template <bool VTrackNearest>
void
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::FirstAxisPass(const Context &               c,
                                                                              const OutputImageRegionType & region,
                                                                              bool & anyForeground,
                                                                              bool & anyFeature) const
{
  using Flag = unsigned char;
  const SizeValueType  nx = c.size[0];
  const auto           none = static_cast<std::int64_t>(nx) + 1; // "no feature on this side"
  const bool           useForeground = m_UseForegroundValue;
  const InputPixelType foregroundValue = m_ForegroundValue;
  const InputPixelType backgroundValue = m_BackgroundValue;
  constexpr bool       isFinal = ImageDimension == 1;

  // Squared length of d steps along x; the entry past the longest possible run means "no feature".
  std::vector<OutputPixelType> squaredOfSteps(nx + 2);
  for (SizeValueType d = 0; d <= nx; ++d)
  {
    const double length = static_cast<double>(d) * c.weight[0];
    squaredOfSteps[d] = static_cast<OutputPixelType>(length * length);
  }
  squaredOfSteps[nx + 1] = std::numeric_limits<OutputPixelType>::infinity();

  std::vector<Flag>         foreground(nx);
  std::vector<Flag>         nearBackground(m_SignedDistance ? nx + 2 : 0); // padded by one on both sides
  std::vector<Flag>         boundary(m_SignedDistance ? nx : 0);
  std::vector<std::int64_t> toLeft(nx);
  unsigned int              neighbourLines = 1; // 3^(D-1) lines around (and including) this one
  for (unsigned int k = 1; k < ImageDimension; ++k)
  {
    neighbourLines *= 3;
  }

  SaitoToriwakiDetail::ForEachOuter<ImageDimension>(
    region, c.stride, 0, 0, [&](SizeValueType base, const IndexValueType * index) {
      const InputPixelType * in = c.input + base;
      Flag * const           fg = foreground.data();
      Flag                   lineForeground = 0;
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

      const Flag * feature = fg;
      if (m_SignedDistance)
      {
        // Boundary = foreground with a background pixel among its in-image 3^D-1 neighbours, as in
        // SignedMaurer's fully connected BinaryContourImageFilter; the image border is not background.
        Flag * const bd = boundary.data();
        std::fill(boundary.begin(), boundary.end(), Flag{ 0 });
        if (lineForeground)
        {
          Flag * const nb = nearBackground.data() + 1;
          std::fill(nearBackground.begin(), nearBackground.end(), Flag{ 0 });
          for (unsigned int code = 0; code < neighbourLines; ++code)
          {
            OffsetValueType offset = 0;
            bool            inside = true;
            unsigned int    digits = code;
            for (unsigned int k = 1; k < ImageDimension; ++k)
            {
              const int            o = static_cast<int>(digits % 3) - 1;
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
            const InputPixelType * line = in + offset;
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
        feature = bd;
      }

      // 1-D distance in steps: to the nearest feature on the left (forward scan), then on the right
      // (backward scan); ties go left. Branch-free: step counts are capped at `none`, whose square is +inf.
      OutputPixelType * out = c.output + base;
      std::int64_t      last = -none;
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
            this->template StoreFinal<VTrackNearest>(
              c, base + x, static_cast<double>(squaredOfSteps[steps]), base + static_cast<SizeValueType>(q));
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
void
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::EnvelopePass(const Context &               c,
                                                                             unsigned int                  d,
                                                                             const OutputImageRegionType & region) const
{
  // Neighbouring x-lines are processed together: each row of the block is read and written as a
  // contiguous run of blockWidth values (whole cache lines, prefetcher friendly) and transposed into
  // contiguous per-line buffers. 64 floats per row keeps the buffers of a 256-sample line in L2.
  constexpr SizeValueType blockWidth = 64;
  const SizeValueType     n = c.size[d];
  const SizeValueType     stride = c.stride[d];
  const double            w = c.weight[d];
  const bool              isFinal = d + 1 == ImageDimension;
  const bool              squaredDistance = m_SquaredDistance;
  const bool              signedDistance = m_SignedDistance;
  const bool              insideIsPositive = m_InsideIsPositive;
  const bool              useForeground = m_UseForegroundValue;
  const InputPixelType    foregroundValue = m_ForegroundValue;
  const InputPixelType    backgroundValue = m_BackgroundValue;

  std::vector<float>                    f(blockWidth * n);
  std::vector<float>                    g(blockWidth * n);
  std::vector<std::uint32_t>            arg(VTrackNearest ? blockWidth * n : 0);
  std::vector<SizeValueType>            sourceNearest(VTrackNearest ? blockWidth * n : 0);
  SaitoToriwakiDetail::EnvelopeScratch scratch(n);

  const auto xBegin = static_cast<SizeValueType>(region.GetIndex(0));
  const auto xEnd = xBegin + region.GetSize(0);

  SaitoToriwakiDetail::ForEachOuter<ImageDimension>(
    region, c.stride, 0, d, [&](SizeValueType base, const IndexValueType *) {
      for (SizeValueType xb = xBegin; xb < xEnd; xb += blockWidth)
      {
        const SizeValueType width = std::min(blockWidth, xEnd - xb);
        const SizeValueType first = base + xb;
        for (SizeValueType j = 0; j < n; ++j)
        {
          const OutputPixelType * src = c.output + first + j * stride;
          for (SizeValueType b = 0; b < width; ++b)
          {
            f[b * n + j] = static_cast<float>(src[b]);
          }
          if (VTrackNearest)
          {
            const SizeValueType * srcNearest = c.nearest + first + j * stride;
            for (SizeValueType b = 0; b < width; ++b)
            {
              sourceNearest[b * n + j] = srcNearest[b];
            }
          }
        }
        for (SizeValueType b = 0; b < width; ++b)
        {
          SaitoToriwakiDetail::LowerEnvelope<VTrackNearest>(
            &f[b * n], n, w, &g[b * n], VTrackNearest ? &arg[b * n] : nullptr, scratch);
        }
        for (SizeValueType j = 0; j < n; ++j)
        {
          const SizeValueType p0 = first + j * stride;
          if (!VTrackNearest)
          {
            // Hot paths without the nearest vector, written so the compiler can vectorise them.
            OutputPixelType * dst = c.output + p0;
            const float *     gj = &g[j];
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
              const InputPixelType * in = c.input + p0;
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
template <bool VTrackNearest>
void
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::StoreFinal(const Context & c,
                                                                           SizeValueType   p,
                                                                           double          squared,
                                                                           SizeValueType   nearest) const
{
  double value = m_SquaredDistance ? squared : std::sqrt(squared);
  if (m_SignedDistance && this->IsForeground(c.input[p]) != m_InsideIsPositive)
  {
    value = -value;
  }
  c.output[p] = static_cast<OutputPixelType>(value);
  if (VTrackNearest)
  {
    double        offset[ImageDimension];
    SizeValueType restP = p;
    SizeValueType restQ = nearest;
    for (unsigned int k = ImageDimension; k-- > 0;)
    {
      const SizeValueType ip = restP / c.stride[k];
      const SizeValueType iq = restQ / c.stride[k];
      restP -= ip * c.stride[k];
      restQ -= iq * c.stride[k];
      offset[k] = (static_cast<double>(iq) - static_cast<double>(ip)) * c.weight[k];
    }
    NearestVectorPixelType & v = c.vectors[p];
    for (unsigned int r = 0; r < ImageDimension; ++r)
    {
      double sum = 0.0;
      if (m_UseImageSpacing)
      {
        for (unsigned int k = 0; k < ImageDimension; ++k)
        {
          sum += c.direction[r][k] * offset[k];
        }
      }
      else
      {
        sum = offset[r];
      }
      v[r] = static_cast<float>(sum);
    }
  }
}

template <typename TInputImage, typename TOutputImage>
void
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::PrintSelf(std::ostream & os, Indent indent) const
{
  using PrintType = typename NumericTraits<InputPixelType>::PrintType;
  Superclass::PrintSelf(os, indent);
  os << indent << "BackgroundValue: " << static_cast<PrintType>(m_BackgroundValue) << std::endl;
  os << indent << "ForegroundValue: " << static_cast<PrintType>(m_ForegroundValue) << std::endl;
  os << indent << "UseForegroundValue: " << m_UseForegroundValue << std::endl;
  os << indent << "UseImageSpacing: " << m_UseImageSpacing << std::endl;
  os << indent << "SquaredDistance: " << m_SquaredDistance << std::endl;
  os << indent << "SignedDistance: " << m_SignedDistance << std::endl;
  os << indent << "InsideIsPositive: " << m_InsideIsPositive << std::endl;
  os << indent << "ComputeNearestVector: " << m_ComputeNearestVector << std::endl;
}
} // namespace itk

#endif
