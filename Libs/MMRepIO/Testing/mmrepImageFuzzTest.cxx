// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Damaged CT volumes against ReadCTImage, in every compressed format the project reads (NRRD gzip,
// MetaImage zlib, NIfTI .nii.gz) and the raw ones: truncated at many lengths, bytes flipped, sizes
// that no file holds. A compressed volume must read back exactly or be refused: its stream carries
// a checksum, and the readers alone returned wrong voxels without a word. Nothing may crash this
// process or take long.
#include "mmrepImageIO.h"
#include "mmrepTestDir.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>

namespace
{
namespace fs = std::filesystem;

using mmrep::test::ReadBytes;
using mmrep::test::WriteBytes;

mmrep::CTImage::Pointer Volume()
{
  auto ct = mmrep::CTImage::New();
  mmrep::CTImage::RegionType region;
  region.SetSize({{24, 20, 16}});
  ct->SetRegions(region);
  ct->Allocate();
  std::mt19937 random(7);
  std::uniform_int_distribution<int> noise(-30, 30);
  short* v = ct->GetBufferPointer();
  for (std::size_t i = 0; i < region.GetNumberOfPixels(); ++i)
    v[i] = static_cast<short>((i % 24 > 6 && i % 24 < 18 ? 1000 : -1000) + noise(random));
  return ct;
}

enum class Read
{
  Identical, // the same voxels as written
  Different, // read, other voxels (or another size)
  Refused,   // std::runtime_error naming the file
};

Read Outcome(const fs::path& path, const mmrep::CTImage* original)
{
  try
  {
    const auto ct = mmrep::ReadCTImage(path.string());
    const std::size_t n = original->GetBufferedRegion().GetNumberOfPixels();
    if (ct->GetBufferedRegion().GetSize() != original->GetBufferedRegion().GetSize())
      return Read::Different;
    return std::memcmp(ct->GetBufferPointer(), original->GetBufferPointer(), n * sizeof(short)) == 0 ? Read::Identical
                                                                                                     : Read::Different;
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find(path.filename().string()), std::string::npos) << e.what();
    return Read::Refused;
  }
}

// First byte of the voxel data: after the header's empty line (NRRD), ElementDataFile (MetaImage).
std::size_t DataStart(const std::string& bytes, const std::string& name)
{
  if (name.find(".nii") != std::string::npos)
    return name.find(".gz") != std::string::npos ? 0 : 352;
  const std::string mark = name.find(".nrrd") != std::string::npos ? "\n\n" : "ElementDataFile = LOCAL\n";
  return bytes.find(mark) + mark.size();
}

TEST(ImageFuzz, DamagedVolumesReadExactlyOrAreRefused)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const auto start = std::chrono::steady_clock::now();
  const auto ct = Volume();
  for (const std::string name : {"ct.nrrd", "ct.mha", "ct.nii.gz", "ct.nii"})
  {
    const fs::path whole = dir / name;
    mmrep::WriteImage(ct.GetPointer(), whole.string());
    ASSERT_EQ(Outcome(whole, ct), Read::Identical) << name;
    const std::string bytes = ReadBytes(whole);
    const std::size_t data = DataStart(bytes, name);
    const bool compressed = name != "ct.nii";
    // Truncated: 24 lengths from the first byte to one short of the whole; always refused.
    for (int cut = 0; cut < 24; ++cut)
    {
      const std::size_t length = std::min(bytes.size() * static_cast<std::size_t>(cut) / 24 + 1, bytes.size() - 1);
      const fs::path p = dir / ("cut-" + name);
      WriteBytes(p, bytes.substr(0, length));
      EXPECT_EQ(Outcome(p, ct), Read::Refused) << name << " cut to " << length << " of " << bytes.size() << " bytes";
    }
    // Flipped bytes, about 80 per file: in a compressed stream the checksum holds (identical or refused);
    // in a header or raw voxels anything but a crash.
    int refused = 0, flips = 0;
    for (std::size_t at = 0; at < bytes.size(); at += std::max<std::size_t>(1, bytes.size() / 80))
    {
      std::string flipped = bytes;
      flipped[at] = static_cast<char>(flipped[at] ^ 0x5a);
      const fs::path p = dir / ("flip-" + name);
      WriteBytes(p, flipped);
      const Read r = Outcome(p, ct);
      if (compressed && at >= data)
      {
        EXPECT_NE(r, Read::Different) << name << ": byte " << at << " flipped gave other voxels without an error";
        ++flips;
        refused += r == Read::Refused;
      }
    }
    if (compressed)
      EXPECT_GT(refused, flips * 9 / 10) << name; // only gzip header fields (time, OS) are not checked
  }
  // Sizes the file cannot hold: refused from the header.
  const std::string nrrd = ReadBytes(dir / "ct.nrrd");
  WriteBytes(dir / "huge.nrrd", std::regex_replace(nrrd, std::regex("sizes: 24 20 16"), "sizes: 24 20 1600000"));
  EXPECT_EQ(Outcome(dir / "huge.nrrd", ct), Read::Refused);
  const std::string mha = ReadBytes(dir / "ct.mha");
  WriteBytes(dir / "huge.mha", std::regex_replace(mha, std::regex("DimSize = 24 20 16"), "DimSize = 24 20 16000"));
  EXPECT_EQ(Outcome(dir / "huge.mha", ct), Read::Refused);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 120.0);
}

} // namespace
