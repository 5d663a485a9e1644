// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// DICOM series input/output (ITK's GDCM series reader and writer): the first series of a directory, sorted by
// position; a CT written one file per slice, right-handed, with the geometry in the DICOM tags.
#include "mmrepImageIO.h"

#include <itkGDCMImageIO.h>
#include <itkGDCMSeriesFileNames.h>
#include <itkImageSeriesReader.h>
#include <itkImageSeriesWriter.h>
#include <itkMetaDataObject.h>
#include <itksys/SystemTools.hxx>

#include "mmrepImageFileChecks.h"
#include "mmrepResourceBudget.h"
#include "mmrepToolkitMessage.h"

#include <gdcmTrace.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace mmrep
{
namespace
{
using imageio::EnsureImageIOFactories;
using imageio::Fail;

std::string FormatDS(double v)
{
  // DICOM decimal strings hold at most 16 characters; %.10g always fits.
  if (std::abs(v) < 1e-12)
  {
    v = 0.0;
  }
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.10g", v);
  return buffer;
}

std::string FormatDSList(const std::vector<double>& values)
{
  std::string s;
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    s += (i ? "\\" : "") + FormatDS(values[i]);
  }
  return s;
}

// DICOM readers derive the slice axis as row x column; a left-handed direction matrix is
// therefore re-expressed with the slice order reversed (same voxels in physical space).
CTImage::Pointer RightHanded(const CTImage* image)
{
  const CTImage::DirectionType d = image->GetDirection();
  if (vnl_determinant(d.GetVnlMatrix()) > 0)
  {
    CTImage::Pointer copy = CTImage::New();
    copy->Graft(image);
    return copy;
  }
  const CTImage::RegionType region = image->GetLargestPossibleRegion();
  const CTImage::SizeType size = region.GetSize();
  CTImage::IndexType last = region.GetIndex();
  last[2] += static_cast<CTImage::IndexValueType>(size[2]) - 1;
  CTImage::PointType origin;
  image->TransformIndexToPhysicalPoint(last, origin);
  CTImage::DirectionType flipped = d;
  for (unsigned r = 0; r < 3; ++r)
  {
    flipped[r][2] = -d[r][2];
  }
  CTImage::Pointer out = CTImage::New();
  out->SetRegions(size);
  out->SetSpacing(image->GetSpacing());
  out->SetOrigin(origin);
  out->SetDirection(flipped);
  out->Allocate();
  const std::size_t sliceVoxels = size[0] * size[1];
  for (std::size_t k = 0; k < size[2]; ++k)
  {
    std::memcpy(out->GetBufferPointer() + k * sliceVoxels, image->GetBufferPointer() + (size[2] - 1 - k) * sliceVoxels,
                sliceVoxels * sizeof(short));
  }
  return out;
}

} // namespace

namespace imageio
{
CTImage::Pointer ReadDicomDirectory(const std::string& directory)
{
  EnsureImageIOFactories();
  // GDCM prints its own multi-line dumps for junk files on std::cerr; our line says it instead.
  gdcm::Trace::SetError(false);
  gdcm::Trace::SetWarning(false);
  gdcm::Trace::SetDebug(false);
  auto names = itk::GDCMSeriesFileNames::New();
  names->SetUseSeriesDetails(true);
  std::vector<std::string> seriesUIDs;
  try
  {
    names->SetDirectory(directory);
    seriesUIDs = names->GetSeriesUIDs();
  }
  catch (const itk::ExceptionObject& e)
  {
    Fail(directory, "cannot scan DICOM directory: " + ToolkitMessage(e.GetDescription()));
  }
  if (seriesUIDs.empty())
  {
    Fail(directory, "directory contains no DICOM image series");
  }
  // GDCMSeriesFileNames returns the files of a series sorted along the slice normal.
  const std::vector<std::string> files = names->GetFileNames(seriesUIDs.front());
  if (files.empty())
  {
    Fail(directory, "DICOM series " + seriesUIDs.front() + " has no readable files");
  }

  // The series' size from its first slice's header, before the reader allocates it.
  {
    auto probe = itk::GDCMImageIO::New();
    probe->SetFileName(files.front());
    try
    {
      probe->ReadImageInformation();
    }
    catch (const itk::ExceptionObject& e)
    {
      Fail(files.front(), "cannot read DICOM header: " + ToolkitMessage(e.GetDescription()));
    }
    try
    {
      CheckMemoryNeed("the series declares",
                      {static_cast<double>(probe->GetDimensions(0)), static_cast<double>(probe->GetDimensions(1)),
                       static_cast<double>(files.size())},
                      static_cast<double>(2 * sizeof(short)));
    }
    catch (const std::exception& e)
    {
      Fail(directory, e.what());
    }
  }
  auto reader = itk::ImageSeriesReader<CTImage>::New();
  reader->SetImageIO(itk::GDCMImageIO::New());
  reader->SetFileNames(files);
  try
  {
    reader->Update();
  }
  catch (const itk::ExceptionObject& e)
  {
    Fail(directory, "cannot read DICOM series: " + ToolkitMessage(e.GetDescription()));
  }
  CTImage::Pointer image = reader->GetOutput();
  image->DisconnectPipeline();
  return image;
}
} // namespace imageio

void WriteDicomSeries(const CTImage* input, const std::string& directory)
{
  EnsureImageIOFactories();
  if (input == nullptr)
  {
    throw std::invalid_argument("WriteDicomSeries: null image for '" + directory + "'");
  }
  if (!itksys::SystemTools::FileIsDirectory(directory))
  {
    Fail(directory, "DICOM output directory does not exist");
  }
  CTImage::Pointer image = RightHanded(input);
  const CTImage::SizeType size = image->GetLargestPossibleRegion().GetSize();
  const CTImage::SpacingType spacing = image->GetSpacing();
  const CTImage::DirectionType dir = image->GetDirection();

  // Row direction cosines (along i) then column direction cosines (along j).
  const std::string orientation = FormatDSList({dir[0][0], dir[1][0], dir[2][0], dir[0][1], dir[1][1], dir[2][1]});

  using Dictionary = itk::MetaDataDictionary;
  std::vector<Dictionary> dictionaries(size[2]);
  itk::ImageSeriesWriter<CTImage, itk::Image<short, 2>>::DictionaryArrayType dictionaryPointers;
  std::vector<std::string> files;
  for (unsigned k = 0; k < size[2]; ++k)
  {
    Dictionary& d = dictionaries[k];
    CTImage::IndexType index = image->GetLargestPossibleRegion().GetIndex();
    index[2] += k;
    CTImage::PointType position;
    image->TransformIndexToPhysicalPoint(index, position);

    itk::EncapsulateMetaData<std::string>(d, "0008|0060", "CT");
    itk::EncapsulateMetaData<std::string>(d, "0008|0016", "1.2.840.10008.5.1.4.1.1.2"); // CT Image Storage
    itk::EncapsulateMetaData<std::string>(d, "0008|103e", "MMRep volume");
    itk::EncapsulateMetaData<std::string>(d, "0010|0010", "Anonymous");
    itk::EncapsulateMetaData<std::string>(d, "0010|0020", "MMRep");
    itk::EncapsulateMetaData<std::string>(d, "0020|0011", "1");
    itk::EncapsulateMetaData<std::string>(d, "0020|0013", std::to_string(k + 1));
    itk::EncapsulateMetaData<std::string>(d, "0020|0032", FormatDSList({position[0], position[1], position[2]}));
    itk::EncapsulateMetaData<std::string>(d, "0020|0037", orientation);
    itk::EncapsulateMetaData<std::string>(d, "0020|1041", FormatDS(k * spacing[2]));
    // Pixel Spacing is row spacing (along j) then column spacing (along i).
    itk::EncapsulateMetaData<std::string>(d, "0028|0030", FormatDSList({spacing[1], spacing[0]}));
    itk::EncapsulateMetaData<std::string>(d, "0018|0050", FormatDS(spacing[2]));
    itk::EncapsulateMetaData<std::string>(d, "0018|0088", FormatDS(spacing[2]));
    // Identity rescale: stored values are the scanner values.
    itk::EncapsulateMetaData<std::string>(d, "0028|1052", "0");
    itk::EncapsulateMetaData<std::string>(d, "0028|1053", "1");
    dictionaryPointers.push_back(&d);

    char name[32];
    std::snprintf(name, sizeof(name), "IM%05u.dcm", k + 1);
    files.push_back(directory + "/" + name);
  }

  auto io = itk::GDCMImageIO::New();
  // With KeepOriginalUID off, one IO instance generates a single Study/Series/Frame of Reference
  // UID for all slices and a new SOP Instance UID per file.
  io->KeepOriginalUIDOff();
  auto writer = itk::ImageSeriesWriter<CTImage, itk::Image<short, 2>>::New();
  writer->SetInput(image);
  writer->SetImageIO(io);
  writer->SetFileNames(files);
  writer->SetMetaDataDictionaryArray(&dictionaryPointers);
  try
  {
    writer->Update();
  }
  catch (const itk::ExceptionObject& e)
  {
    for (const std::string& f : files)
    {
      itksys::SystemTools::RemoveFile(f);
    }
    Fail(directory, "cannot write DICOM series: " + ToolkitMessage(e.GetDescription()));
  }
}

} // namespace mmrep
