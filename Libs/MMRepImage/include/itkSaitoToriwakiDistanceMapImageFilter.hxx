// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#ifndef itkSaitoToriwakiDistanceMapImageFilter_hxx
#define itkSaitoToriwakiDistanceMapImageFilter_hxx

#include "itkSaitoToriwakiDistanceMapImageFilter.h"

#include "itkMultiThreaderBase.h"
#include "itkNumericTraits.h"
#include "itkProgressTransformer.h"
#include "itkSaitoToriwakiDistanceMapPasses.hxx"
#include "itkSaitoToriwakiLineEnvelope.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cmath>
#include <limits>

namespace itk
{
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
void SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::SetForegroundValue(const InputPixelType& value)
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
typename SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::NearestVectorImageType*
SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::GetNearestVectorOutput()
{
  return dynamic_cast<NearestVectorImageType*>(this->ProcessObject::GetOutput(1));
}

template <typename TInputImage, typename TOutputImage>
void SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::GenerateInputRequestedRegion()
{
  Superclass::GenerateInputRequestedRegion();
  // Distances depend on the whole image.
  if (auto* input = const_cast<InputImageType*>(this->GetInput()))
  {
    input->SetRequestedRegionToLargestPossibleRegion();
  }
}

template <typename TInputImage, typename TOutputImage>
void SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::EnlargeOutputRequestedRegion(DataObject*)
{
  for (unsigned int i = 0; i < this->GetNumberOfIndexedOutputs(); ++i)
  {
    if (auto* image = dynamic_cast<ImageBase<ImageDimension>*>(this->ProcessObject::GetOutput(i)))
    {
      image->SetRequestedRegionToLargestPossibleRegion();
    }
  }
}

template <typename TInputImage, typename TOutputImage>
void SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::AllocateOutputs()
{
  OutputImageType* output = this->GetOutput();
  output->SetBufferedRegion(output->GetRequestedRegion());
  output->Allocate();
  NearestVectorImageType* vectors = this->GetNearestVectorOutput();
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
void SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::GenerateData()
{
  this->AllocateOutputs();
  const InputImageType* input = this->GetInput();
  OutputImageType* output = this->GetOutput();
  const SizeType size = output->GetBufferedRegion().GetSize();
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

  MultiThreaderBase* threader = this->GetMultiThreader();
  threader->SetNumberOfWorkUnits(this->GetNumberOfWorkUnits());
  const float passShare = 1.0f / static_cast<float>(ImageDimension);

  std::atomic<bool> anyForeground{false};
  std::atomic<bool> anyFeature{false};
  {
    ProgressTransformer progress(0.0f, passShare, this);
    threader->template ParallelizeImageRegionRestrictDirection<ImageDimension>(
      0, lattice,
      [&](const OutputImageRegionType& region) {
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
      d, lattice,
      [&](const OutputImageRegionType& region) {
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
void SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::StoreFinal(const Context& c, SizeValueType p,
                                                                                double squared,
                                                                                SizeValueType nearest) const
{
  double value = m_SquaredDistance ? squared : std::sqrt(squared);
  if (m_SignedDistance && this->IsForeground(c.input[p]) != m_InsideIsPositive)
  {
    value = -value;
  }
  c.output[p] = static_cast<OutputPixelType>(value);
  if (VTrackNearest)
  {
    double offset[ImageDimension];
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
    NearestVectorPixelType& v = c.vectors[p];
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
void SaitoToriwakiDistanceMapImageFilter<TInputImage, TOutputImage>::PrintSelf(std::ostream& os, Indent indent) const
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
