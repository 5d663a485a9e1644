// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepHeadSegmentation.h"

#include "itkSaitoToriwakiDistanceMapImageFilter.h"

#include <itkBinaryThresholdImageFilter.h>
#include <itkConnectedComponentImageFilter.h>
#include <itkRelabelComponentImageFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace mmrep
{

unsigned int AxialAxis(const itk::ImageBase<3>* image)
{
  const auto& d = image->GetDirection();
  unsigned int best = 2;
  double bestValue = -1;
  for (unsigned int a = 0; a < 3; ++a)
    if (std::abs(d[2][a]) > bestValue)
    {
      bestValue = std::abs(d[2][a]);
      best = a;
    }
  return best;
}

namespace
{
MaskImage::Pointer Threshold(const CTImage* ct, double lower)
{
  using Filter = itk::BinaryThresholdImageFilter<CTImage, MaskImage>;
  auto f = Filter::New();
  f->SetInput(ct);
  f->SetLowerThreshold(static_cast<short>(std::max(-32768.0, std::min(32767.0, std::ceil(lower)))));
  f->SetInsideValue(1);
  f->SetOutsideValue(0);
  f->Update();
  return f->GetOutput();
}

double VoxelVolume(const MaskImage* m)
{
  const auto s = m->GetSpacing();
  return s[0] * s[1] * s[2];
}

std::size_t CountForeground(const MaskImage* m)
{
  const auto* p = m->GetBufferPointer();
  const std::size_t n = m->GetBufferedRegion().GetNumberOfPixels();
  std::size_t c = 0;
  for (std::size_t i = 0; i < n; ++i)
    c += p[i] != 0;
  return c;
}

// Breadth-first marking of background reachable from the seeds, over a (sub)grid given by
// strides. `mark` must be zero-initialised for the visited range.
void MarkReachableBackground(const unsigned char* mask, unsigned char* mark, const std::vector<std::size_t>& seeds,
                             const std::array<std::size_t, 3>& size, const std::array<std::size_t, 3>& stride,
                             std::size_t base, int dims)
{
  std::vector<std::size_t> queue;
  queue.reserve(1 << 16);
  for (auto s : seeds)
    if (!mask[s] && !mark[s])
    {
      mark[s] = 1;
      queue.push_back(s);
    }
  for (std::size_t head = 0; head < queue.size(); ++head)
  {
    const std::size_t v = queue[head];
    std::size_t rel = v - base, coord[3];
    // Recover coordinates along the (up to 3) axes of this grid.
    for (int a = dims - 1; a >= 0; --a)
    {
      coord[a] = rel / stride[a];
      rel -= coord[a] * stride[a];
    }
    for (int a = 0; a < dims; ++a)
    {
      if (coord[a] > 0)
      {
        const std::size_t u = v - stride[a];
        if (!mask[u] && !mark[u])
        {
          mark[u] = 1;
          queue.push_back(u);
        }
      }
      if (coord[a] + 1 < size[a])
      {
        const std::size_t u = v + stride[a];
        if (!mask[u] && !mark[u])
        {
          mark[u] = 1;
          queue.push_back(u);
        }
      }
    }
  }
}
} // namespace

void FillEnclosedBackground(MaskImage* mask, bool axialSlices, unsigned int axis)
{
  const auto sz = mask->GetBufferedRegion().GetSize();
  const std::array<std::size_t, 3> size{sz[0], sz[1], sz[2]};
  const std::array<std::size_t, 3> stride{1, size[0], size[0] * size[1]};
  unsigned char* m = mask->GetBufferPointer();
  const std::size_t n = size[0] * size[1] * size[2];
  std::vector<unsigned char> outside(n, 0);

  // 3-D: seeds on all six faces, sorted order of the buffer so the result is deterministic.
  std::vector<std::size_t> seeds;
  for (std::size_t k = 0; k < size[2]; ++k)
    for (std::size_t j = 0; j < size[1]; ++j)
      for (std::size_t i = 0; i < size[0]; ++i)
        if (i == 0 || j == 0 || k == 0 || i + 1 == size[0] || j + 1 == size[1] || k + 1 == size[2])
          seeds.push_back(i + j * stride[1] + k * stride[2]);
  MarkReachableBackground(m, outside.data(), seeds, size, stride, 0, 3);
  for (std::size_t v = 0; v < n; ++v)
    if (!m[v] && !outside[v])
      m[v] = 1;
  if (!axialSlices)
    return;

  // 2-D, slice by slice along `axis`: in-plane axes a0, a1.
  const unsigned int a0 = axis == 0 ? 1 : 0, a1 = axis == 2 ? 1 : 2;
  std::fill(outside.begin(), outside.end(), 0);
  for (std::size_t s = 0; s < size[axis]; ++s)
  {
    const std::size_t base = s * stride[axis];
    seeds.clear();
    for (std::size_t y = 0; y < size[a1]; ++y)
      for (std::size_t x = 0; x < size[a0]; ++x)
        if (x == 0 || y == 0 || x + 1 == size[a0] || y + 1 == size[a1])
          seeds.push_back(base + x * stride[a0] + y * stride[a1]);
    // A 2-D grid embedded in the volume: coordinates recovered with the in-plane strides, which
    // only works when a0's stride is smaller than a1's (true by construction, a0 < a1).
    MarkReachableBackground(m, outside.data(), seeds, {size[a0], size[a1], 1}, {stride[a0], stride[a1], 0}, base, 2);
    for (std::size_t y = 0; y < size[a1]; ++y)
      for (std::size_t x = 0; x < size[a0]; ++x)
      {
        const std::size_t v = base + x * stride[a0] + y * stride[a1];
        if (!m[v] && !outside[v])
          m[v] = 1;
      }
  }
}

namespace
{
// Voxel distance (index units) from every voxel to the nearest voxel equal to `value`.
FloatImage::Pointer IndexDistanceTo(const MaskImage* mask, unsigned char value)
{
  using EDT = itk::SaitoToriwakiDistanceMapImageFilter<MaskImage, FloatImage>;
  auto edt = EDT::New();
  edt->SetInput(mask);
  edt->SetUseImageSpacing(false);
  edt->SetSquaredDistance(true);
  edt->SetForegroundValue(value);
  edt->Update();
  return edt->GetOutput();
}
} // namespace

void OpenWithBall(MaskImage* mask, unsigned int radius)
{
  const std::size_t n = mask->GetBufferedRegion().GetNumberOfPixels();
  unsigned char* m = mask->GetBufferPointer();
  std::size_t background = 0;
  for (std::size_t i = 0; i < n; ++i)
    background += m[i] == 0;
  if (background == 0 || background == n)
    return; // nothing to erode from, or nothing to open
  const float r2 = static_cast<float>(radius) * static_cast<float>(radius);
  // Erosion: keep voxels farther than r from the background.
  {
    auto toBackground = IndexDistanceTo(mask, 0);
    const float* d = toBackground->GetBufferPointer();
    for (std::size_t i = 0; i < n; ++i)
      m[i] = d[i] > r2;
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i)
    kept += m[i];
  if (kept == 0)
    return; // everything thinner than the ball: the opening is empty
  // Dilation: voxels within r of the eroded set.
  auto toEroded = IndexDistanceTo(mask, 1);
  const float* d = toEroded->GetBufferPointer();
  for (std::size_t i = 0; i < n; ++i)
    m[i] = d[i] <= r2;
}

std::size_t KeepLargestComponent(MaskImage::Pointer& mask)
{
  using LabelImage = itk::Image<unsigned int, 3>;
  auto cc = itk::ConnectedComponentImageFilter<MaskImage, LabelImage>::New();
  cc->SetInput(mask);
  cc->SetFullyConnected(false);
  auto relabel = itk::RelabelComponentImageFilter<LabelImage, LabelImage>::New();
  relabel->SetInput(cc->GetOutput());
  relabel->Update();
  if (relabel->GetNumberOfObjects() == 0)
    return 0;
  const auto* l = relabel->GetOutput()->GetBufferPointer();
  unsigned char* m = mask->GetBufferPointer();
  const std::size_t n = mask->GetBufferedRegion().GetNumberOfPixels();
  for (std::size_t i = 0; i < n; ++i)
    m[i] = l[i] == 1;
  return relabel->GetSizeOfObjectsInPixels()[0];
}

HeadSegmentation SegmentHead(const CTImage* ct, const HeadSegmentationOptions& o,
                             const std::function<void(double)>& progress)
{
  auto report = [&](double f) {
    if (progress)
      progress(f);
  };
  HeadSegmentation result;
  const unsigned int axial = AxialAxis(ct);

  // Skin.
  auto skin = Threshold(ct, o.skinThreshold);
  if (CountForeground(skin) == 0)
  {
    std::ostringstream s;
    s << "empty segmentation: no voxel at or above the skin threshold " << o.skinThreshold;
    throw std::runtime_error(s.str());
  }
  report(0.1);
  if (o.openingRadius > 0)
    OpenWithBall(skin, o.openingRadius);
  report(0.35);
  const std::size_t skinVoxels = KeepLargestComponent(skin);
  result.skinVolume = skinVoxels * VoxelVolume(skin);
  const double imagedVolume = static_cast<double>(skin->GetBufferedRegion().GetNumberOfPixels()) * VoxelVolume(skin);
  const double minimumHeadVolume =
    o.minimumHeadVolume > 0 ? o.minimumHeadVolume : std::max(1.5e5, std::min(5.0e5, 0.05 * imagedVolume));
  if (result.skinVolume < minimumHeadVolume)
  {
    std::ostringstream s;
    s << "no head found: the largest object above the skin threshold " << o.skinThreshold << " is "
      << result.skinVolume / 1000.0 << " ml (a head in this " << imagedVolume / 1.0e6 << " l volume is at least "
      << minimumHeadVolume / 1000.0 << " ml)";
    throw std::runtime_error(s.str());
  }
  report(0.55);
  if (o.fillInteriorAir)
    FillEnclosedBackground(skin, true, axial);
  result.skinVolume = CountForeground(skin) * VoxelVolume(skin);
  report(0.65);

  // Bone, inside the head only (drops the table even when it is as dense as bone).
  auto bone = Threshold(ct, o.boneThreshold);
  {
    unsigned char* b = bone->GetBufferPointer();
    const unsigned char* s = skin->GetBufferPointer();
    const std::size_t n = bone->GetBufferedRegion().GetNumberOfPixels();
    for (std::size_t i = 0; i < n; ++i)
      b[i] = b[i] && s[i];
  }
  report(0.75);
  const std::size_t boneVoxels = KeepLargestComponent(bone);
  result.boneVolume = boneVoxels * VoxelVolume(bone);
  if (result.boneVolume < o.minimumBoneVolume)
  {
    std::ostringstream s;
    s << "no skull found: the largest object above the bone threshold " << o.boneThreshold << " is "
      << result.boneVolume / 1000.0 << " ml";
    throw std::runtime_error(s.str());
  }
  FillEnclosedBackground(bone, false, axial);
  result.boneVolume = CountForeground(bone) * VoxelVolume(bone);
  report(1.0);
  result.skin = skin;
  result.bone = bone;
  return result;
}

CTImage::Pointer MaskedIntensities(const CTImage* ct, const MaskImage* mask, double threshold)
{
  auto out = CTImage::New();
  out->CopyInformation(ct);
  out->SetRegions(ct->GetBufferedRegion());
  out->Allocate();
  const short inside = static_cast<short>(std::min(32767.0, std::floor(threshold) + 1.0));
  const short outsideV = static_cast<short>(std::max(-32768.0, std::ceil(threshold) - 1.0));
  const short* c = ct->GetBufferPointer();
  const unsigned char* m = mask->GetBufferPointer();
  short* o = out->GetBufferPointer();
  const std::size_t n = ct->GetBufferedRegion().GetNumberOfPixels();
  for (std::size_t i = 0; i < n; ++i)
    o[i] = m[i] ? std::max(c[i], inside) : std::min(c[i], outsideV);
  return out;
}

std::size_t CloseAxialSlits(MaskImage* mask, int maxRun)
{
  const unsigned axis = AxialAxis(mask);
  const auto size = mask->GetLargestPossibleRegion().GetSize();
  std::array<std::size_t, 3> stride{1, size[0], size[0] * size[1]};
  unsigned char* data = mask->GetBufferPointer();
  const unsigned a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  std::size_t filled = 0;
  for (std::size_t p = 0; p < size[a1]; ++p)
    for (std::size_t q = 0; q < size[a2]; ++q)
    {
      const std::size_t base = p * stride[a1] + q * stride[a2];
      std::size_t lastTissue = std::numeric_limits<std::size_t>::max();
      for (std::size_t k = 0; k < size[axis]; ++k)
      {
        if (!data[base + k * stride[axis]])
          continue;
        if (lastTissue != std::numeric_limits<std::size_t>::max() && k - lastTissue > 1 &&
            k - lastTissue - 1 <= static_cast<std::size_t>(maxRun))
          for (std::size_t g = lastTissue + 1; g < k; ++g, ++filled)
            data[base + g * stride[axis]] = 1;
        lastTissue = k;
      }
    }
  mask->Modified();
  return filled;
}

} // namespace mmrep
