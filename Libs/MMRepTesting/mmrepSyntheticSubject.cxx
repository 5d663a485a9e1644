// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Synthetic subject images and displacement fields. Every voxel is computed independently, so the
// multi-threaded loops give the same bytes whatever the thread count.
#include "mmrepSyntheticSubject.h"

#include <itkImageRegionIteratorWithIndex.h>
#include <itkLinearInterpolateImageFunction.h>
#include <itkMinimumMaximumImageCalculator.h>
#include <itkMultiThreaderBase.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace mmrep
{
namespace
{

Eigen::Vector3d PhysicalPoint(const itk::ImageBase<3>* image, const itk::Index<3>& index)
{
  itk::Point<double, 3> p;
  image->TransformIndexToPhysicalPoint(index, p);
  return {p[0], p[1], p[2]};
}

// Fills a field on the grid with f(point) - point.
template <typename F> DisplacementField::Pointer FillField(const itk::ImageBase<3>* grid, F&& map)
{
  auto field = DisplacementField::New();
  field->SetOrigin(grid->GetOrigin());
  field->SetSpacing(grid->GetSpacing());
  field->SetDirection(grid->GetDirection());
  field->SetRegions(grid->GetLargestPossibleRegion());
  field->Allocate();
  itk::MultiThreaderBase::New()->ParallelizeImageRegion<3>(
    field->GetBufferedRegion(),
    [&](const DisplacementField::RegionType& region) {
      for (itk::ImageRegionIteratorWithIndex<DisplacementField> it(field, region); !it.IsAtEnd(); ++it)
      {
        const Eigen::Vector3d p = PhysicalPoint(grid, it.GetIndex());
        const Eigen::Vector3d d = map(p) - p;
        DisplacementField::PixelType v;
        for (unsigned i = 0; i < 3; ++i)
          v[i] = static_cast<float>(d(i));
        it.Set(v);
      }
    },
    nullptr);
  return field;
}

} // namespace

void FitWarpToImage(SyntheticWarpParameters& parameters, const itk::ImageBase<3>* image)
{
  const auto region = image->GetLargestPossibleRegion();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  for (int corner = 0; corner < 8; ++corner)
  {
    itk::Index<3> idx;
    for (unsigned d = 0; d < 3; ++d)
      idx[d] = region.GetIndex(d) + (((corner >> d) & 1) ? static_cast<long>(region.GetSize(d)) - 1 : 0);
    const Eigen::Vector3d p = PhysicalPoint(image, idx);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  parameters.centre = 0.5 * (lo + hi);
  parameters.regionMin = parameters.centre - 0.3 * (hi - lo);
  parameters.regionMax = parameters.centre + 0.3 * (hi - lo);
}

CTImage::Pointer ResampleSyntheticSubject(const CTImage* source, const SyntheticWarp& warp,
                                          const std::function<void(double)>& progress)
{
  if (source == nullptr || source->GetLargestPossibleRegion().GetNumberOfPixels() == 0)
    throw std::invalid_argument("synthetic subject: empty source image");
  auto minmax = itk::MinimumMaximumImageCalculator<CTImage>::New();
  minmax->SetImage(source);
  minmax->ComputeMinimum();
  const double air = minmax->GetMinimum();

  auto interpolator = itk::LinearInterpolateImageFunction<CTImage, double>::New();
  interpolator->SetInputImage(source);

  auto subject = CTImage::New();
  subject->CopyInformation(source);
  subject->SetRegions(source->GetLargestPossibleRegion());
  subject->Allocate();
  const std::size_t total = subject->GetBufferedRegion().GetNumberOfPixels();
  std::atomic<std::size_t> done{0};
  std::mutex progressMutex;
  itk::MultiThreaderBase::New()->ParallelizeImageRegion<3>(
    subject->GetBufferedRegion(),
    [&](const CTImage::RegionType& region) {
      for (itk::ImageRegionIteratorWithIndex<CTImage> it(subject, region); !it.IsAtEnd(); ++it)
      {
        const Eigen::Vector3d x = warp.Inverse(PhysicalPoint(subject, it.GetIndex()));
        itk::Point<double, 3> p;
        p[0] = x(0);
        p[1] = x(1);
        p[2] = x(2);
        double v = air;
        if (interpolator->IsInsideBuffer(p))
          v = interpolator->Evaluate(p);
        v = std::clamp(std::round(v), double(std::numeric_limits<short>::min()),
                       double(std::numeric_limits<short>::max()));
        it.Set(static_cast<short>(v));
      }
      const std::size_t n = done += region.GetNumberOfPixels();
      if (progress)
      {
        std::lock_guard<std::mutex> lock(progressMutex);
        progress(static_cast<double>(n) / static_cast<double>(total));
      }
    },
    nullptr);
  return subject;
}

DisplacementField::Pointer ForwardDisplacementField(const itk::ImageBase<3>* grid, const SyntheticWarp& warp)
{
  return FillField(grid, [&](const Eigen::Vector3d& x) { return warp.Forward(x); });
}

DisplacementField::Pointer InverseDisplacementField(const itk::ImageBase<3>* grid, const SyntheticWarp& warp)
{
  return FillField(grid, [&](const Eigen::Vector3d& y) { return warp.Inverse(y); });
}

} // namespace mmrep
