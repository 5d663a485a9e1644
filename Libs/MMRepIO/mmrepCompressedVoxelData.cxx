// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The compressed voxel stream of a NRRD (encoding gzip) or MetaImage (CompressedData) file inflated to its end
// before ITK reads it: teem and MetaIO stop at the bytes they need and never check the stream's checksum, so a
// damaged stream becomes a volume with wrong voxels and no error (.nii.gz: RequireNiftiData). A single
// detached data file (.mhd, .nhdr) must exist.
#include "mmrepImageFileChecks.h"

#include <itksys/SystemTools.hxx>

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace mmrep
{
namespace imageio
{
namespace
{
std::string Trim(std::string s)
{
  const auto first = s.find_first_not_of(" \t\r");
  const auto last = s.find_last_not_of(" \t\r");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

struct CompressedStream
{
  std::string file;         // where the stream is (the header itself or its data file)
  std::uint64_t offset = 0; // first byte of the stream in `file`
  bool present = false;     // false: the voxels are not compressed (`file` still names a single data file)
  std::string wrapper;      // "gzip" or "zlib"
};

// NRRD: "key: value" lines up to the first empty line; data attached after it or in "data file".
CompressedStream NrrdStream(const std::string& path, std::ifstream& in)
{
  CompressedStream s;
  std::string line, encoding, dataFile;
  bool skips = false;
  std::getline(in, line); // NRRD000x
  while (std::getline(in, line) && !Trim(line).empty())
  {
    if (line[0] == '#')
      continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos)
      continue;
    const std::string key = Lower(Trim(line.substr(0, colon)));
    const std::string value = Trim(line.substr(colon + 1 + (colon + 1 < line.size() && line[colon + 1] == '=')));
    if (key == "encoding")
      encoding = Lower(value);
    else if (key == "data file" || key == "datafile")
      dataFile = value;
    else if (key == "line skip" || key == "lineskip" || key == "byte skip" || key == "byteskip")
      skips = skips || value != "0";
  }
  // A list of data files (or a pattern): teem's own reader is left to judge.
  if (dataFile.find(' ') != std::string::npos || dataFile.rfind("LIST", 0) == 0 ||
      dataFile.find('%') != std::string::npos)
    return s;
  if (dataFile.empty())
  {
    s.file = path;
    s.offset = static_cast<std::uint64_t>(in.tellg());
  }
  else
  {
    s.file = itksys::SystemTools::CollapseFullPath(dataFile, itksys::SystemTools::GetFilenamePath(path));
  }
  s.present = (encoding == "gzip" || encoding == "gz") && !skips; // skipped bytes: left to teem too
  s.wrapper = "gzip";
  return s;
}

// MetaImage: "Key = Value" lines up to ElementDataFile, the last header line.
CompressedStream MetaStream(const std::string& path, std::ifstream& in)
{
  CompressedStream s;
  bool compressed = false;
  std::string line;
  while (std::getline(in, line))
  {
    const auto equals = line.find('=');
    if (equals == std::string::npos)
      continue;
    const std::string key = Lower(Trim(line.substr(0, equals)));
    const std::string value = Trim(line.substr(equals + 1));
    if (key == "compresseddata")
      compressed = Lower(value) == "true";
    if (key != "elementdatafile")
      continue;
    if (Lower(value) == "list" || value.find('%') != std::string::npos || value.find(' ') != std::string::npos)
      return s;
    s.present = compressed;
    s.wrapper = "zlib";
    if (Lower(value) == "local")
    {
      s.file = path;
      s.offset = static_cast<std::uint64_t>(in.tellg());
    }
    else
    {
      s.file = itksys::SystemTools::CollapseFullPath(value, itksys::SystemTools::GetFilenamePath(path));
    }
    return s;
  }
  return s;
}
} // namespace

void RequireCompleteCompressedVoxels(const std::string& path, const itk::ImageIOBase* io)
{
  const std::string lower = Lower(path);
  const auto endsWith = [&](const char* e) {
    const std::string ext = e;
    return lower.size() >= ext.size() && lower.compare(lower.size() - ext.size(), ext.size(), ext) == 0;
  };
  std::ifstream header(path, std::ios::binary);
  if (!header)
    Fail(path, "cannot open");
  CompressedStream stream;
  if (endsWith(".nrrd") || endsWith(".nhdr"))
    stream = NrrdStream(path, header);
  else if (endsWith(".mha") || endsWith(".mhd"))
    stream = MetaStream(path, header);
  if (!stream.file.empty() && stream.file != path && !itksys::SystemTools::FileExists(stream.file, true))
    Fail(path, "its voxel data file '" + stream.file + "' does not exist");
  if (!stream.present)
    return;

  std::ifstream in(stream.file, std::ios::binary);
  if (!in)
    Fail(path, "cannot open its data file '" + stream.file + "'");
  in.seekg(static_cast<std::streamoff>(stream.offset));
  z_stream z{};
  // 16: gzip wrapper (CRC-32 and length checked at the end); 32: zlib or gzip, detected (Adler-32 checked).
  if (inflateInit2(&z, 15 + (stream.wrapper == "gzip" ? 16 : 32)) != Z_OK)
    Fail(path, "cannot start zlib");
  std::vector<unsigned char> input(1 << 16), output(1 << 18);
  std::uint64_t inflated = 0;
  int status = Z_OK;
  while (status != Z_STREAM_END)
  {
    if (z.avail_in == 0)
    {
      in.read(reinterpret_cast<char*>(input.data()), static_cast<std::streamsize>(input.size()));
      z.avail_in = static_cast<uInt>(in.gcount());
      z.next_in = input.data();
      if (z.avail_in == 0)
        break; // the file ended before the stream did
    }
    z.next_out = output.data();
    z.avail_out = static_cast<uInt>(output.size());
    status = inflate(&z, Z_NO_FLUSH);
    inflated += output.size() - z.avail_out;
    if (status != Z_OK && status != Z_STREAM_END)
      break;
  }
  const std::string why = z.msg ? z.msg : "";
  inflateEnd(&z);
  if (status == Z_DATA_ERROR || status == Z_NEED_DICT)
    Fail(path, "corrupt compressed voxel data (" + (why.empty() ? std::string("invalid stream") : why) + ")");
  if (status == Z_MEM_ERROR)
    Fail(path, "not enough memory to check the compressed voxel data");
  if (status != Z_STREAM_END)
    Fail(path, "truncated file: the compressed voxel data ends before its stream does");
  const std::uint64_t need = io->GetImageSizeInBytes();
  if (inflated < need)
    Fail(path, "truncated voxel data: the header declares " + std::to_string(need) + " bytes, the stream holds " +
                 std::to_string(inflated));
}

} // namespace imageio
} // namespace mmrep
