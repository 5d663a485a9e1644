// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Header probe, memory budget, NIfTI data length and IO factory registration for the volume readers.
#include "mmrepImageFileChecks.h"

#include <itkGDCMImageIOFactory.h>
#include <itkImageIOFactory.h>
#include <itkMetaImageIOFactory.h>
#include <itkNiftiImageIOFactory.h>
#include <itkNrrdImageIOFactory.h>
#include <itksys/SystemTools.hxx>

#include "mmrepResourceBudget.h"
#include "mmrepToolkitMessage.h"

#include <zlib.h>

#include <cstring>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace mmrep
{
namespace imageio
{
namespace
{

// ITK_USE_FILE registers the IO factories from every translation unit that includes
// itkImageFileReader.h; this explicit, idempotent registration also covers builds where that
// static initialisation is dropped (static library linked into a Slicer module library).
template <typename TFactory> void RegisterIfMissing()
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

} // namespace

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

// NIfTI's reader fills what a truncated file lacks with zeros, silently: the decompressed length
// is checked against the header's data offset and the voxel bytes before reading.
void RequireNiftiData(const std::string& path, const itk::ImageIOBase* io)
{
  const std::string lower = itksys::SystemTools::LowerCase(path);
  auto endsWith = [&](const char* e) {
    const std::size_t n = std::strlen(e);
    return lower.size() >= n && lower.compare(lower.size() - n, n, e) == 0;
  };
  if (!endsWith(".nii") && !endsWith(".nii.gz"))
    return;                                 // .hdr/.img pairs: the .img is read as it is
  gzFile file = gzopen(path.c_str(), "rb"); // reads uncompressed files as they are
  if (file == nullptr)
    Fail(path, "cannot open");
  std::vector<unsigned char> header(544, 0);
  const int headerBytes = gzread(file, header.data(), static_cast<unsigned>(header.size()));
  std::uint64_t total = headerBytes > 0 ? static_cast<std::uint64_t>(headerBytes) : 0;
  std::vector<unsigned char> chunk(1 << 20);
  for (int n; (n = gzread(file, chunk.data(), static_cast<unsigned>(chunk.size()))) > 0;)
    total += static_cast<std::uint64_t>(n);
  int error = Z_OK;
  std::string zlibError = gzerror(file, &error);
  gzclose(file);
  if (const auto colon = zlibError.rfind(": "); colon != std::string::npos)
    zlibError.erase(0, colon + 2); // "path: why"
  if (error != Z_OK && error != Z_STREAM_END)
    Fail(path, "truncated or corrupt compressed data (" + zlibError + ")");
  // sizeof_hdr (348: NIfTI-1, vox_offset a float at 108; 540: NIfTI-2, an int64 at 168), either byte order.
  auto value = [&](std::size_t at, std::size_t n) {
    std::int32_t size;
    std::memcpy(&size, header.data(), 4);
    std::vector<unsigned char> b(header.begin() + static_cast<long>(at), header.begin() + static_cast<long>(at + n));
    if (size != 348 && size != 540)
      std::reverse(b.begin(), b.end());
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

} // namespace imageio
} // namespace mmrep
