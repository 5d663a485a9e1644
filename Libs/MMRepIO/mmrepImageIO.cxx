// Volume input/output through ITK's ImageIO factories (NRRD, MetaImage, NIfTI, DICOM/GDCM).
#include "mmrepImageIO.h"

#include <itkGDCMImageIO.h>
#include <itkGDCMImageIOFactory.h>
#include <itkGDCMSeriesFileNames.h>
#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkImageIOFactory.h>
#include <itkImageSeriesReader.h>
#include <itkImageSeriesWriter.h>
#include <itkMetaDataObject.h>
#include <itkMetaImageIOFactory.h>
#include <itkNiftiImageIOFactory.h>
#include <itkNrrdImageIOFactory.h>
#include <itkPixelTraits.h>
#include <itksys/SystemTools.hxx>

#include "mmrepResourceBudget.h"
#include "mmrepToolkitMessage.h"

#include <gdcmTrace.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace mmrep
{
namespace
{

// ITK_USE_FILE registers the IO factories from every translation unit that includes
// itkImageFileReader.h; this explicit, idempotent registration also covers builds where that
// static initialisation is dropped (static library linked into a Slicer module library).
template <typename TFactory>
void RegisterIfMissing()
{
  for (itk::ObjectFactoryBase* f : itk::ObjectFactoryBase::GetRegisteredFactories())
  {
    if (dynamic_cast<TFactory*>(f) != nullptr)
    {
      return;
    }
  }
  TFactory::RegisterOneFactory();
}

void EnsureImageIOFactories()
{
  static std::once_flag once;
  std::call_once(once, [] {
    RegisterIfMissing<itk::NrrdImageIOFactory>();
    RegisterIfMissing<itk::MetaImageIOFactory>();
    RegisterIfMissing<itk::NiftiImageIOFactory>();
    RegisterIfMissing<itk::GDCMImageIOFactory>();
  });
}

[[noreturn]] void Fail(const std::string& path, const std::string& what)
{
  throw std::runtime_error("'" + path + "': " + what);
}

// Probes the header to give precise errors (format, dimension, components) before reading.
itk::ImageIOBase::Pointer ProbeFile(const std::string& path, unsigned int components)
{
  if (!itksys::SystemTools::FileExists(path, true))
  {
    Fail(path, "file does not exist");
  }
  itk::ImageIOBase::Pointer io =
    itk::ImageIOFactory::CreateImageIO(path.c_str(), itk::ImageIOFactory::IOFileModeEnum::ReadMode);
  if (!io)
  {
    Fail(path, "unknown or unreadable image format (supported: .nrrd/.nhdr, .mha/.mhd, .nii/.nii.gz, "
               "DICOM directory)");
  }
  io->SetFileName(path);
  try
  {
    io->ReadImageInformation();
  }
  catch (const itk::ExceptionObject& e)
  {
    Fail(path, "cannot read image header: " + ToolkitMessage(e.GetDescription()));
  }
  if (io->GetComponentType() == itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE)
  {
    Fail(path, "unknown voxel type in the header (for example a MetaImage ElementType that is not MET_SHORT, "
               "MET_FLOAT, ...)");
  }
  if (io->GetNumberOfDimensions() != 3)
  {
    Fail(path, "expected a 3D volume, found " + std::to_string(io->GetNumberOfDimensions()) + "D");
  }
  if (io->GetNumberOfComponents() != components)
  {
    Fail(path, (components == 1 ? std::string("expected a scalar volume")
                                : "expected " + std::to_string(components) + " components per voxel") +
                 ", found " + std::to_string(io->GetNumberOfComponents()) + " components per voxel");
  }
  return io;
}

// Refuses, from the header, a volume that would not fit the memory budget (read buffer in the
// file's type plus the image in ours).
void CheckVoxelBudget(const std::string& path, const itk::ImageIOBase* io, std::size_t bytesPerVoxel)
{
  std::vector<double> counts;
  for (unsigned a = 0; a < io->GetNumberOfDimensions(); ++a)
    counts.push_back(static_cast<double>(io->GetDimensions(a)));
  const double fileBytes = static_cast<double>(io->GetComponentSize() * io->GetNumberOfComponents());
  try
  {
    CheckMemoryNeed("the header declares", counts, fileBytes + static_cast<double>(bytesPerVoxel));
  }
  catch (const std::exception& e)
  {
    Fail(path, e.what());
  }
}

bool FloatingPointFile(const itk::ImageIOBase* io)
{
  return io->GetComponentType() == itk::IOComponentEnum::FLOAT ||
         io->GetComponentType() == itk::IOComponentEnum::DOUBLE;
}

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
                    std::isnan(v) ? "NaN" : std::isinf(v) ? (v > 0 ? "+Inf" : "-Inf") : "out of range");
      Fail(path, std::string(where) + "; the volume must hold finite values" +
                   (std::isfinite(v) ? " within [" + std::to_string(static_cast<long long>(lowest)) + ", " +
                                         std::to_string(static_cast<long long>(highest)) + "]"
                                     : std::string()));
    }
}

// NIfTI's reader fills what a truncated file lacks with zeros, silently: the decompressed length
// is checked against the header's data offset and the voxel bytes before reading.
void RequireNiftiData(const std::string& path, const itk::ImageIOBase* io)
{
  const std::string lower = itksys::SystemTools::LowerCase(path);
  auto endsWith = [&](const char* e) {
    const std::size_t n = std::strlen(e);
    return lower.size() >= n && lower.compare(lower.size() - n, n, e) == 0;
  };
  if (!endsWith(".nii") && !endsWith(".nii.gz")) return; // .hdr/.img pairs: the .img is read as it is
  gzFile file = gzopen(path.c_str(), "rb"); // reads uncompressed files as they are
  if (file == nullptr) Fail(path, "cannot open");
  std::vector<unsigned char> header(544, 0);
  const int headerBytes = gzread(file, header.data(), static_cast<unsigned>(header.size()));
  std::uint64_t total = headerBytes > 0 ? static_cast<std::uint64_t>(headerBytes) : 0;
  std::vector<unsigned char> chunk(1 << 20);
  for (int n; (n = gzread(file, chunk.data(), static_cast<unsigned>(chunk.size()))) > 0;)
    total += static_cast<std::uint64_t>(n);
  int error = Z_OK;
  std::string zlibError = gzerror(file, &error);
  gzclose(file);
  if (const auto colon = zlibError.rfind(": "); colon != std::string::npos) zlibError.erase(0, colon + 2); // "path: why"
  if (error != Z_OK && error != Z_STREAM_END)
    Fail(path, "truncated or corrupt compressed data (" + zlibError + ")");
  // sizeof_hdr (348: NIfTI-1, vox_offset a float at 108; 540: NIfTI-2, an int64 at 168), either byte order.
  auto value = [&](std::size_t at, std::size_t n) {
    std::int32_t size;
    std::memcpy(&size, header.data(), 4);
    std::vector<unsigned char> b(header.begin() + static_cast<long>(at), header.begin() + static_cast<long>(at + n));
    if (size != 348 && size != 540) std::reverse(b.begin(), b.end());
    return b;
  };
  std::int32_t size;
  std::memcpy(&size, value(0, 4).data(), 4);
  double offset = 352; // the smallest a single-file NIfTI-1 has
  if (size == 348)
  {
    float f;
    std::memcpy(&f, value(108, 4).data(), 4);
    offset = std::max<double>(offset, f);
  }
  else if (size == 540)
  {
    std::int64_t v;
    std::memcpy(&v, value(168, 8).data(), 8);
    offset = std::max<double>(544, static_cast<double>(v));
  }
  const double need = offset + static_cast<double>(io->GetImageSizeInBytes());
  if (static_cast<double>(total) < need)
  {
    char what[160];
    std::snprintf(what, sizeof what, "truncated file: the header declares %.0f bytes of voxel data, %.0f are present",
                  static_cast<double>(io->GetImageSizeInBytes()), std::max(0.0, static_cast<double>(total) - offset));
    Fail(path, what);
  }
}

// MetaIO reports a short or corrupt data block on std::cerr and returns the image anyway: its
// report is taken as the read's failure.
class CaptureStandardError
{
public:
  CaptureStandardError()
    : previous_(std::cerr.rdbuf(text_.rdbuf()))
  {
  }
  ~CaptureStandardError() { std::cerr.rdbuf(previous_); }
  CaptureStandardError(const CaptureStandardError&) = delete;
  CaptureStandardError& operator=(const CaptureStandardError&) = delete;
  std::string Text() const { return text_.str(); }

private:
  std::ostringstream text_;
  std::streambuf* previous_;
};

template <typename TImage>
typename TImage::Pointer ReadWithIO(const std::string& path, itk::ImageIOBase* io)
{
  auto reader = itk::ImageFileReader<TImage>::New();
  reader->SetFileName(path);
  reader->SetImageIO(io);
  RequireNiftiData(path, io);
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

template <typename TImage>
typename TImage::Pointer ReadFile(const std::string& path)
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

template <typename TImage>
void WriteFile(const TImage* image, const std::string& path)
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
  try
  {
    writer->Update();
  }
  catch (const itk::ExceptionObject& e)
  {
    itksys::SystemTools::RemoveFile(path); // never leave a partial file behind
    Fail(path, "cannot write image: " + ToolkitMessage(e.GetDescription()));
  }
}

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
    std::memcpy(out->GetBufferPointer() + k * sliceVoxels,
                image->GetBufferPointer() + (size[2] - 1 - k) * sliceVoxels, sliceVoxels * sizeof(short));
  }
  return out;
}

} // namespace

CTImage::Pointer ReadCTImage(const std::string& pathOrDicomDirectory)
{
  if (itksys::SystemTools::FileIsDirectory(pathOrDicomDirectory))
  {
    return ReadDicomDirectory(pathOrDicomDirectory);
  }
  return ReadFile<CTImage>(pathOrDicomDirectory);
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
  const std::string orientation =
    FormatDSList({ dir[0][0], dir[1][0], dir[2][0], dir[0][1], dir[1][1], dir[2][1] });

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
    itk::EncapsulateMetaData<std::string>(d, "0020|0032",
                                          FormatDSList({ position[0], position[1], position[2] }));
    itk::EncapsulateMetaData<std::string>(d, "0020|0037", orientation);
    itk::EncapsulateMetaData<std::string>(d, "0020|1041", FormatDS(k * spacing[2]));
    // Pixel Spacing is row spacing (along j) then column spacing (along i).
    itk::EncapsulateMetaData<std::string>(d, "0028|0030", FormatDSList({ spacing[1], spacing[0] }));
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
