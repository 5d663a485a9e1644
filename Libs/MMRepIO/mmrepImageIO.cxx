// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Volume files through ITK's ImageIO factories (NRRD, MetaImage, NIfTI): checked reads, cast to our pixel types,
// and writes that leave no partial file. DICOM series: mmrepDicomIO.cxx.
#include "mmrepImageIO.h"

#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkImageIOFactory.h>
#include <itkPixelTraits.h>
#include <itksys/SystemTools.hxx>

#include "mmrepDiskSpace.h"
#include "mmrepImageFileChecks.h"
#include "mmrepSilencedCStandardError.h"
#include "mmrepToolkitMessage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace mmrep
{
namespace
{
using imageio::EnsureImageIOFactories;
using imageio::Fail;
using namespace imageio;

template <typename TImage> typename TImage::Pointer ReadWithIO(const std::string& path, itk::ImageIOBase* io)
{
  auto reader = itk::ImageFileReader<TImage>::New();
  reader->SetFileName(path);
  reader->SetImageIO(io);
  RequireNiftiData(path, io);
  RequireCompleteCompressedVoxels(path, io);
  CaptureStandardError library;
  try
  {
    reader->Update();
  }
  catch (const itk::ExceptionObject& e)
  {
    Fail(path, "cannot read voxel data (truncated or corrupt file?): " + ToolkitMessage(e.GetDescription()));
  }
  catch (const std::bad_alloc&)
  {
    Fail(path, "not enough memory to read the voxel data");
  }
  catch (const std::exception& e)
  {
    Fail(path, std::string("cannot read voxel data: ") + e.what());
  }
  if (const std::string text = library.Text(); !text.empty())
    Fail(path, "cannot read voxel data (truncated or corrupt file?): " + ToolkitMessage(text));
  typename TImage::Pointer image = reader->GetOutput();
  image->DisconnectPipeline();
  return image;
}

template <typename TImage> typename TImage::Pointer ReadFile(const std::string& path)
{
  using Pixel = typename TImage::PixelType;
  using Value = typename itk::PixelTraits<Pixel>::ValueType;
  EnsureImageIOFactories();
  itk::ImageIOBase::Pointer io = ProbeFile(path, itk::PixelTraits<Pixel>::Dimension);
  const bool floating = FloatingPointFile(io);
  CheckVoxelBudget(path, io, sizeof(Pixel) + (floating && std::is_integral_v<Value> ? sizeof(double) : 0));
  if constexpr (std::is_integral_v<Value>)
  {
    if (floating) // check the values before they are cast to our integer type
    {
      using DoubleImage = itk::Image<double, TImage::ImageDimension>;
      const auto values = ReadWithIO<DoubleImage>(path, io);
      RequireFiniteVoxels(path, values.GetPointer(), static_cast<double>(std::numeric_limits<Value>::lowest()),
                          static_cast<double>(std::numeric_limits<Value>::max()));
      auto image = TImage::New();
      image->CopyInformation(values);
      image->SetRegions(values->GetLargestPossibleRegion());
      image->Allocate();
      std::transform(values->GetBufferPointer(),
                     values->GetBufferPointer() + values->GetBufferedRegion().GetNumberOfPixels(),
                     image->GetBufferPointer(), [](double v) { return static_cast<Value>(std::lround(v)); });
      return image;
    }
    return ReadWithIO<TImage>(path, io);
  }
  else
  {
    auto image = ReadWithIO<TImage>(path, io);
    RequireFiniteVoxels(path, image.GetPointer(), -std::numeric_limits<double>::max(),
                        std::numeric_limits<double>::max());
    return image;
  }
}

// ITK's warnings (a metadata item a format cannot store) are blocks "WARNING: In file, line n\n…\n\n";
// what is left is what MetaIO prints when a write fails.
std::string WithoutToolkitWarnings(const std::string& text)
{
  std::string kept;
  for (std::size_t at = 0; at < text.size();)
  {
    std::size_t end = text.find("\n\n", at);
    end = end == std::string::npos ? text.size() : end + 2;
    if (text.compare(at, 12, "WARNING: In ") != 0)
      kept += text.substr(at, end - at);
    at = end;
  }
  return kept.find_first_not_of(" \n") == std::string::npos ? std::string() : kept;
}

template <typename TImage> void WriteFile(const TImage* image, const std::string& path)
{
  EnsureImageIOFactories();
  if (image == nullptr)
  {
    throw std::invalid_argument("WriteImage: null image for '" + path + "'");
  }
  if (!itk::ImageIOFactory::CreateImageIO(path.c_str(), itk::ImageIOFactory::IOFileModeEnum::WriteMode))
  {
    Fail(path, "unsupported image file extension (use .nrrd, .nhdr, .mha, .mhd, .nii or .nii.gz)");
  }
  auto writer = itk::ImageFileWriter<TImage>::New();
  writer->SetInput(image);
  writer->SetFileName(path);
  writer->SetUseCompression(true);
  std::string failure;
  {
    CaptureStandardError library;    // MetaIO reports a failed write there and returns
    SilencedCStandardError niftilib; // its short-write line: the file is checked below
    try
    {
      writer->Update();
    }
    catch (const itk::ExceptionObject& e)
    {
      failure = ToolkitMessage(e.GetDescription());
    }
    if (const std::string text = WithoutToolkitWarnings(library.Text()); failure.empty() && !text.empty())
      failure = ToolkitMessage(text);
  }
  // NIfTI's writer reports a short write on stderr only: the file is read back as a reader would check it.
  if (failure.empty())
  {
    try
    {
      const itk::ImageIOBase::Pointer io = ProbeFile(path, itk::PixelTraits<typename TImage::PixelType>::Dimension);
      RequireNiftiData(path, io);
      RequireCompleteCompressedVoxels(path, io);
    }
    catch (const std::exception& e)
    {
      const std::string what = e.what();
      const auto colon = what.find("': ");
      failure = "the written file is incomplete (is the disk full?): " +
                (colon == std::string::npos ? what : what.substr(colon + 3));
    }
  }
  if (!failure.empty() && DiskFull(path))
    failure = "no space left on the device";
  if (!failure.empty())
  {
    itksys::SystemTools::RemoveFile(path); // never leave a partial file behind
    Fail(path, "cannot write image: " + failure);
  }
}

} // namespace

CTImage::Pointer ReadCTImage(const std::string& pathOrDicomDirectory)
{
  const CTImage::Pointer ct = itksys::SystemTools::FileIsDirectory(pathOrDicomDirectory)
                                ? imageio::ReadDicomDirectory(pathOrDicomDirectory)
                                : ReadFile<CTImage>(pathOrDicomDirectory);
  // A slice or two (a scout view, one DICOM file of a series) holds no head to segment.
  constexpr itk::SizeValueType kMinimumVoxelsPerAxis = 3;
  const auto size = ct->GetLargestPossibleRegion().GetSize();
  if (size[0] < kMinimumVoxelsPerAxis || size[1] < kMinimumVoxelsPerAxis || size[2] < kMinimumVoxelsPerAxis)
    Fail(pathOrDicomDirectory, "a CT of " + std::to_string(size[0]) + " x " + std::to_string(size[1]) + " x " +
                                 std::to_string(size[2]) + " voxels is not a volume of the head (at least " +
                                 std::to_string(kMinimumVoxelsPerAxis) +
                                 " voxels along each axis; one slice of a "
                                 "series? give the series' folder)");
  return ct;
}

FloatImage::Pointer ReadFloatImage(const std::string& path)
{
  return ReadFile<FloatImage>(path);
}

MaskImage::Pointer ReadMaskImage(const std::string& path)
{
  return ReadFile<MaskImage>(path);
}

void WriteImage(const CTImage* image, const std::string& path)
{
  WriteFile(image, path);
}

void WriteImage(const FloatImage* image, const std::string& path)
{
  WriteFile(image, path);
}

void WriteImage(const MaskImage* image, const std::string& path)
{
  WriteFile(image, path);
}

DisplacementField::Pointer ReadDisplacementField(const std::string& path)
{
  return ReadFile<DisplacementField>(path);
}

void WriteDisplacementField(const DisplacementField* field, const std::string& path)
{
  WriteFile(field, path);
}

} // namespace mmrep
