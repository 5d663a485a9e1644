// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Checks shared by MMRep's volume readers and writers (internal to MMRepIO): IO factory registration, the header
// probe, the memory budget, finite voxels, complete NIfTI data, and MetaIO's reports on std::cerr.
#pragma once

#include "mmrepImageIO.h"

#include <itkImageIOBase.h>
#include <itkPixelTraits.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

namespace mmrep
{
namespace imageio
{
// Registers the NRRD, MetaImage, NIfTI and GDCM IO factories once (idempotent).
void EnsureImageIOFactories();

// Throws std::runtime_error "'<path>': <what>".
[[noreturn]] void Fail(const std::string& path, const std::string& what);

// Probes the header to give precise errors (format, dimension, components) before reading.
itk::ImageIOBase::Pointer ProbeFile(const std::string& path, unsigned int components);

// Refuses, from the header, a volume that would not fit the memory budget (read buffer in the
// file's type plus the image in ours).
void CheckVoxelBudget(const std::string& path, const itk::ImageIOBase* io, std::size_t bytesPerVoxel);

bool FloatingPointFile(const itk::ImageIOBase* io);

// A NaN or an infinity in a volume would silently cut surfaces and distance maps: refused, with
// the first such voxel, before any work. `lowest`/`highest`: the range of the type we keep.
template <typename TImage>
void RequireFiniteVoxels(const std::string& path, const TImage* image, double lowest, double highest)
{
  const auto* buffer = image->GetBufferPointer();
  const std::size_t n = image->GetBufferedRegion().GetNumberOfPixels();
  constexpr unsigned components = itk::PixelTraits<typename TImage::PixelType>::Dimension;
  for (std::size_t i = 0; i < n; ++i)
    for (unsigned c = 0; c < components; ++c)
    {
      double v;
      if constexpr (components == 1)
        v = static_cast<double>(buffer[i]);
      else
        v = static_cast<double>(buffer[i][c]);
      if (std::isfinite(v) && v >= lowest && v <= highest)
        continue;
      const auto index = image->ComputeIndex(static_cast<typename TImage::OffsetValueType>(i));
      char where[128];
      std::snprintf(where, sizeof where, "voxel (%ld, %ld, %ld) is %s", static_cast<long>(index[0]),
                    static_cast<long>(index[1]), static_cast<long>(index[2]),
                    std::isnan(v)   ? "NaN"
                    : std::isinf(v) ? (v > 0 ? "+Inf" : "-Inf")
                                    : "out of range");
      Fail(path, std::string(where) + "; the volume must hold finite values" +
                   (std::isfinite(v) ? " within [" + std::to_string(static_cast<long long>(lowest)) + ", " +
                                         std::to_string(static_cast<long long>(highest)) + "]"
                                     : std::string()));
    }
}

// NIfTI's reader fills what a truncated file lacks with zeros, silently: the decompressed length
// is checked against the header's data offset and the voxel bytes before reading.
void RequireNiftiData(const std::string& path, const itk::ImageIOBase* io);

// teem and MetaIO read a compressed voxel stream without checking its end or its checksum: a NRRD (gzip) or
// MetaImage (CompressedData) stream is inflated to its end, checksum checked, and its length compared with the
// header's voxel bytes (mmrepCompressedVoxelData.cxx).
void RequireCompleteCompressedVoxels(const std::string& path, const itk::ImageIOBase* io);

// MetaIO reports a short or corrupt data block on std::cerr and returns the image anyway: its
// report is taken as the read's failure.
class CaptureStandardError
{
public:
  CaptureStandardError() : previous_(std::cerr.rdbuf(text_.rdbuf())) {}
  ~CaptureStandardError() { std::cerr.rdbuf(previous_); }
  CaptureStandardError(const CaptureStandardError&) = delete;
  CaptureStandardError& operator=(const CaptureStandardError&) = delete;
  std::string Text() const { return text_.str(); }

private:
  std::ostringstream text_;
  std::streambuf* previous_;
};

// The DICOM series reader (mmrepDicomIO.cxx), used by ReadCTImage for a directory.
CTImage::Pointer ReadDicomDirectory(const std::string& directory);

} // namespace imageio
} // namespace mmrep
