// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Volume reading/writing: sample CTs against an independent zlib decoding of the NRRD files,
// format round trips, DICOM series geometry, and clear errors for bad input.
#include "mmrepImageIO.h"
#include "mmrepTestDir.h"

#include <itkImageFileWriter.h>
#include <itkImageRegionConstIteratorWithIndex.h>

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace fs = std::filesystem;
using mmrep::CTImage;

namespace
{

const std::string kCtHead = std::string(MMREP_SAMPLE_DATA) + "/cthead.nrrd";
const std::string kHeadSq = std::string(MMREP_SAMPLE_DATA) + "/headsq.nrrd";

std::string ReadBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Decodes an attached-header gzip little-endian NRRD of shorts with zlib alone.
std::vector<short> DecodeNrrdWithZlib(const std::string& path)
{
  const std::string bytes = ReadBytes(path);
  const std::size_t start = bytes.find("\n\n");
  EXPECT_NE(start, std::string::npos);
  z_stream zs{};
  EXPECT_EQ(inflateInit2(&zs, 16 + MAX_WBITS), Z_OK); // gzip wrapper
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data() + start + 2));
  zs.avail_in = static_cast<uInt>(bytes.size() - start - 2);
  std::string raw;
  char chunk[1 << 16];
  int rc = Z_OK;
  while (rc == Z_OK)
  {
    zs.next_out = reinterpret_cast<Bytef*>(chunk);
    zs.avail_out = sizeof(chunk);
    rc = inflate(&zs, Z_NO_FLUSH);
    raw.append(chunk, sizeof(chunk) - zs.avail_out);
  }
  inflateEnd(&zs);
  EXPECT_EQ(rc, Z_STREAM_END);
  std::vector<short> values(raw.size() / 2);
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    const auto lo = static_cast<unsigned char>(raw[2 * i]);
    const auto hi = static_cast<unsigned char>(raw[2 * i + 1]);
    values[i] = static_cast<short>(static_cast<unsigned short>(lo | (hi << 8)));
  }
  return values;
}

void ExpectSameGeometry(const CTImage* a, const CTImage* b, double spacingTol, double originTol, double dirTol)
{
  ASSERT_EQ(a->GetLargestPossibleRegion().GetSize(), b->GetLargestPossibleRegion().GetSize());
  for (unsigned i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(a->GetSpacing()[i], b->GetSpacing()[i], spacingTol) << "axis " << i;
    EXPECT_NEAR(a->GetOrigin()[i], b->GetOrigin()[i], originTol) << "axis " << i;
    for (unsigned j = 0; j < 3; ++j)
    {
      EXPECT_NEAR(a->GetDirection()[i][j], b->GetDirection()[i][j], dirTol) << i << "," << j;
    }
  }
}

void ExpectSamePixels(const CTImage* a, const CTImage* b)
{
  const std::size_t n = a->GetLargestPossibleRegion().GetNumberOfPixels();
  ASSERT_EQ(n, b->GetLargestPossibleRegion().GetNumberOfPixels());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    differing += a->GetBufferPointer()[i] != b->GetBufferPointer()[i];
  }
  EXPECT_EQ(differing, 0u);
}

// Rotation R = Rz(az) * Rx(ax), a proper (right-handed) direction matrix.
CTImage::DirectionType Rotation(double az, double ax)
{
  CTImage::DirectionType rz, rx;
  rz.SetIdentity();
  rx.SetIdentity();
  rz[0][0] = std::cos(az);
  rz[0][1] = -std::sin(az);
  rz[1][0] = std::sin(az);
  rz[1][1] = std::cos(az);
  rx[1][1] = std::cos(ax);
  rx[1][2] = -std::sin(ax);
  rx[2][1] = std::sin(ax);
  rx[2][2] = std::cos(ax);
  return rz * rx;
}

void ExpectThrowsNaming(const std::function<void()>& f, const std::string& path, const std::string& what = {})
{
  try
  {
    f();
    ADD_FAILURE() << "no exception for " << path;
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    if (!what.empty())
    {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  }
}

} // namespace

TEST(ImageIO, ReadsCtHeadLikeTheNrrdHeader)
{
  CTImage::Pointer image = mmrep::ReadCTImage(kCtHead);
  const CTImage::SizeType size = image->GetLargestPossibleRegion().GetSize();
  EXPECT_EQ(size[0], 256u);
  EXPECT_EQ(size[1], 256u);
  EXPECT_EQ(size[2], 113u);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[0], 1.0);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[1], 1.0);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[2], 2.0);
  for (unsigned i = 0; i < 3; ++i)
  {
    EXPECT_DOUBLE_EQ(image->GetOrigin()[i], 0.0);
    for (unsigned j = 0; j < 3; ++j)
    {
      EXPECT_DOUBLE_EQ(image->GetDirection()[i][j], i == j ? 1.0 : 0.0);
    }
  }
  const std::vector<short> reference = DecodeNrrdWithZlib(kCtHead);
  ASSERT_EQ(reference.size(), 256u * 256u * 113u);
  EXPECT_EQ(0, std::memcmp(reference.data(), image->GetBufferPointer(), reference.size() * sizeof(short)));
}

TEST(ImageIO, ReadsHeadSqLikeTheNrrdHeader)
{
  CTImage::Pointer image = mmrep::ReadCTImage(kHeadSq);
  const CTImage::SizeType size = image->GetLargestPossibleRegion().GetSize();
  EXPECT_EQ(size[0], 64u);
  EXPECT_EQ(size[1], 64u);
  EXPECT_EQ(size[2], 93u);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[0], 3.2);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[1], 3.2);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[2], 1.5);
  // Our copy declares +k inferior (see Resources/SampleData/README.md): origin at the top slice.
  EXPECT_DOUBLE_EQ(image->GetOrigin()[2], 138.0);
  EXPECT_DOUBLE_EQ(image->GetDirection()[2][2], -1.0);
  EXPECT_DOUBLE_EQ(image->GetDirection()[0][0], 1.0);
  EXPECT_DOUBLE_EQ(image->GetDirection()[1][1], 1.0);
  const std::vector<short> reference = DecodeNrrdWithZlib(kHeadSq);
  ASSERT_EQ(reference.size(), 64u * 64u * 93u);
  EXPECT_EQ(0, std::memcmp(reference.data(), image->GetBufferPointer(), reference.size() * sizeof(short)));
}

TEST(ImageIO, NrrdToMhaToNiftiKeepsPixelsAndGeometry)
{
  const fs::path dir = mmrep::test::ScratchDir();
  CTImage::Pointer original = mmrep::ReadCTImage(kHeadSq);
  // A rotated, shifted geometry exercises every header field of each format.
  CTImage::PointType origin;
  origin[0] = -101.5;
  origin[1] = 37.25;
  origin[2] = -12.125;
  original->SetOrigin(origin);
  original->SetDirection(Rotation(0.3, -0.2));

  CTImage::Pointer current = original;
  for (const char* name : {"a.mha", "b.nii.gz", "c.nii", "d.nrrd", "e.mhd"})
  {
    const std::string path = (dir / name).string();
    mmrep::WriteImage(current.GetPointer(), path);
    CTImage::Pointer back = mmrep::ReadCTImage(path);
    SCOPED_TRACE(name);
    // NIfTI stores the geometry in single precision.
    ExpectSameGeometry(original, back, 1e-5, 1e-4, 1e-5);
    ExpectSamePixels(original, back);
    current = back;
  }
}

TEST(ImageIO, FloatAndLabelImagesRoundTrip)
{
  const fs::path dir = mmrep::test::ScratchDir();
  auto f = mmrep::FloatImage::New();
  mmrep::FloatImage::SizeType size = {{7, 5, 3}};
  f->SetRegions(size);
  f->Allocate();
  auto label = itk::Image<unsigned char, 3>::New();
  label->SetRegions(size);
  label->Allocate();
  for (std::size_t i = 0; i < 7 * 5 * 3; ++i)
  {
    f->GetBufferPointer()[i] = static_cast<float>(std::sin(0.37 * i) * 123.456);
    label->GetBufferPointer()[i] = static_cast<unsigned char>((i * 37) % 256);
  }
  mmrep::WriteImage(f.GetPointer(), (dir / "f.nrrd").string());
  mmrep::FloatImage::Pointer fb = mmrep::ReadFloatImage((dir / "f.nrrd").string());
  for (std::size_t i = 0; i < 7 * 5 * 3; ++i)
  {
    ASSERT_EQ(fb->GetBufferPointer()[i], f->GetBufferPointer()[i]) << i;
  }
  mmrep::WriteImage(label.GetPointer(), (dir / "l.nii.gz").string());
  CTImage::Pointer lb = mmrep::ReadCTImage((dir / "l.nii.gz").string());
  for (std::size_t i = 0; i < 7 * 5 * 3; ++i)
  {
    ASSERT_EQ(lb->GetBufferPointer()[i], static_cast<short>(label->GetBufferPointer()[i])) << i;
  }
  mmrep::MaskImage::Pointer mb = mmrep::ReadMaskImage((dir / "l.nii.gz").string());
  EXPECT_EQ(0, std::memcmp(mb->GetBufferPointer(), label->GetBufferPointer(), 7 * 5 * 3));
}

TEST(ImageIO, DicomSeriesFromCtHeadReadsBackIdentical)
{
  // cthead is right-handed (identity direction) as DICOM slices are; headsq, whose slices run
  // inferior, is covered by DicomSeriesOfLeftHandedVolumeKeepsPhysicalVoxels.
  const fs::path dir = mmrep::test::ScratchDir();
  CTImage::Pointer original = mmrep::ReadCTImage(kCtHead);
  mmrep::WriteDicomSeries(original, dir.string());
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir))
  {
    files += entry.path().extension() == ".dcm";
  }
  EXPECT_EQ(files, 113u);
  CTImage::Pointer back = mmrep::ReadCTImage(dir.string());
  ExpectSameGeometry(original, back, 1e-4, 1e-3, 1e-6);
  ExpectSamePixels(original, back);
}

TEST(ImageIO, DicomSeriesKeepsRotatedDirection)
{
  const fs::path dir = mmrep::test::ScratchDir();
  CTImage::Pointer original = mmrep::ReadCTImage(kHeadSq);
  CTImage::PointType origin;
  origin[0] = -87.3;
  origin[1] = 120.45;
  origin[2] = -33.1;
  original->SetOrigin(origin);
  original->SetDirection(Rotation(0.4, 0.25));
  mmrep::WriteDicomSeries(original, dir.string());
  CTImage::Pointer back = mmrep::ReadCTImage(dir.string());
  ExpectSameGeometry(original, back, 1e-4, 1e-3, 1e-6);
  ExpectSamePixels(original, back);
}

TEST(ImageIO, DicomSeriesOfLeftHandedVolumeKeepsPhysicalVoxels)
{
  const fs::path dir = mmrep::test::ScratchDir();
  CTImage::Pointer original = mmrep::ReadCTImage(kHeadSq);
  CTImage::DirectionType flip;
  flip.SetIdentity();
  flip[2][2] = -1; // slices go inferior: not expressible as DICOM row x column
  original->SetDirection(flip);
  mmrep::WriteDicomSeries(original, dir.string());
  CTImage::Pointer back = mmrep::ReadCTImage(dir.string());
  ASSERT_EQ(back->GetLargestPossibleRegion().GetSize(), original->GetLargestPossibleRegion().GetSize());
  EXPECT_NEAR(back->GetDirection()[2][2], 1.0, 1e-6);
  // Every voxel of the result sits at the physical point of the same-valued input voxel.
  std::size_t mismatches = 0;
  for (itk::ImageRegionConstIteratorWithIndex<CTImage> it(back, back->GetLargestPossibleRegion()); !it.IsAtEnd(); ++it)
  {
    CTImage::PointType p;
    back->TransformIndexToPhysicalPoint(it.GetIndex(), p);
    CTImage::IndexType inOriginal;
    ASSERT_TRUE(original->TransformPhysicalPointToIndex(p, inOriginal));
    mismatches += original->GetPixel(inOriginal) != it.Get();
  }
  EXPECT_EQ(mismatches, 0u);
}

TEST(ImageIO, TruncatedNrrdThrowsNamingThePath)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const std::string bytes = ReadBytes(kCtHead);
  const std::string path = (dir / "half.nrrd").string();
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  ExpectThrowsNaming([&] { mmrep::ReadCTImage(path); }, path);
}

TEST(ImageIO, TwoDimensionalImageThrows)
{
  const fs::path dir = mmrep::test::ScratchDir();
  using Image2 = itk::Image<short, 2>;
  auto slice = Image2::New();
  Image2::SizeType size = {{8, 8}};
  slice->SetRegions(size);
  slice->Allocate();
  slice->FillBuffer(7);
  const std::string path = (dir / "slice.nrrd").string();
  auto writer = itk::ImageFileWriter<Image2>::New();
  writer->SetInput(slice);
  writer->SetFileName(path);
  writer->Update();
  ExpectThrowsNaming([&] { mmrep::ReadCTImage(path); }, path, "3D");
}

TEST(ImageIO, MissingUnknownAndEmptyInputsThrow)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const std::string missing = (dir / "missing.nrrd").string();
  ExpectThrowsNaming([&] { mmrep::ReadCTImage(missing); }, missing, "does not exist");
  const std::string unknown = (dir / "volume.xyz").string();
  std::ofstream(unknown) << "not an image\n";
  ExpectThrowsNaming([&] { mmrep::ReadCTImage(unknown); }, unknown, "format");
  const fs::path emptyDir = dir / "empty";
  fs::create_directories(emptyDir);
  std::ofstream((emptyDir / "notes.txt").string()) << "no DICOM here\n";
  ExpectThrowsNaming([&] { mmrep::ReadCTImage(emptyDir.string()); }, emptyDir.string(), "DICOM");
  CTImage::Pointer image = mmrep::ReadCTImage(kHeadSq);
  const std::string badOut = (dir / "out.xyz").string();
  ExpectThrowsNaming([&] { mmrep::WriteImage(image.GetPointer(), badOut); }, badOut, "extension");
  EXPECT_FALSE(fs::exists(badOut));
  const std::string noDir = (dir / "no-such-dir").string();
  ExpectThrowsNaming([&] { mmrep::WriteDicomSeries(image, noDir); }, noDir);
}
