// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepSurfaceFileChecks.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace mmrep
{
namespace
{
[[noreturn]] void Fail(const std::string& path, const std::string& what)
{
  throw std::runtime_error("'" + path + "': " + what);
}

constexpr long long kMaxListLength = 1000; // a polygon of more corners is not a face of a mesh

struct PLYProperty
{
  std::string name;
  bool list = false;
  int countBytes = 0, itemBytes = 0; // item (or scalar) size in bytes
  bool itemSigned = true, itemFloat = false;
};

struct PLYElement
{
  std::string name;
  long long count = 0;
  std::vector<PLYProperty> properties;
};

// Size in bytes of a PLY scalar type, 0 when unknown.
int TypeBytes(const std::string& t, bool& isSigned, bool& isFloat)
{
  static const std::map<std::string, std::pair<int, int>> types = {
    {"char", {1, 1}},  {"int8", {1, 1}},    {"uchar", {1, 0}},  {"uint8", {1, 0}},
    {"short", {2, 1}}, {"int16", {2, 1}},   {"ushort", {2, 0}}, {"uint16", {2, 0}},
    {"int", {4, 1}},   {"int32", {4, 1}},   {"uint", {4, 0}},   {"uint32", {4, 0}},
    {"float", {4, 2}}, {"float32", {4, 2}}, {"double", {8, 2}}, {"float64", {8, 2}}};
  const auto it = types.find(t);
  if (it == types.end())
    return 0;
  isSigned = it->second.second != 0;
  isFloat = it->second.second == 2;
  return it->second.first;
}

// An integer of `bytes` bytes at `p`, in the file's byte order.
long long ReadInteger(const unsigned char* p, int bytes, bool isSigned, bool bigEndian)
{
  std::uint64_t u = 0;
  for (int b = 0; b < bytes; ++b)
    u |= static_cast<std::uint64_t>(p[bigEndian ? b : bytes - 1 - b]) << (8 * (bytes - 1 - b));
  if (isSigned && bytes < 8 && (u >> (8 * bytes - 1)) & 1u)
    return static_cast<long long>(u) - (1LL << (8 * bytes));
  return static_cast<long long>(u);
}

struct PLYHeader
{
  std::string format;
  std::vector<PLYElement> elements;
  std::size_t dataStart = 0;
};

PLYHeader ReadPLYHeader(const std::string& path, const std::string& bytes)
{
  PLYHeader h;
  std::istringstream in(bytes);
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0)
    Fail(path, "not a PLY file (no 'ply' magic)");
  for (int n = 0; std::getline(in, line) && n < 10000; ++n)
  {
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "format")
      words >> h.format;
    else if (word == "element")
    {
      PLYElement e;
      if (!(words >> e.name >> e.count) || e.count < 0)
        Fail(path, "PLY header: malformed element line '" + line + "'");
      h.elements.push_back(e);
    }
    else if (word == "property")
    {
      if (h.elements.empty())
        Fail(path, "PLY header: a property before any element");
      PLYProperty p;
      std::string type;
      words >> type;
      bool s = true, f = false;
      if (type == "list")
      {
        std::string countType, itemType;
        words >> countType >> itemType >> p.name;
        bool cs = true, cf = false;
        p.list = true;
        p.countBytes = TypeBytes(countType, cs, cf);
        p.itemBytes = TypeBytes(itemType, s, f);
        if (p.countBytes == 0 || p.itemBytes == 0 || cf)
          Fail(path, "PLY header: unknown list type in '" + line + "'");
      }
      else
      {
        words >> p.name;
        p.itemBytes = TypeBytes(type, s, f);
        if (p.itemBytes == 0)
          Fail(path, "PLY header: unknown property type '" + type + "'");
      }
      p.itemSigned = s;
      p.itemFloat = f;
      h.elements.back().properties.push_back(p);
    }
    else if (word == "end_header")
    {
      h.dataStart = static_cast<std::size_t>(in.tellg());
      return h;
    }
  }
  Fail(path, "PLY header without end_header");
}

void CheckVertexCoordinates(const std::string& path, const PLYHeader& h)
{
  bool x = false, y = false, z = false;
  for (const auto& e : h.elements)
    if (e.name == "vertex")
      for (const auto& p : e.properties)
      {
        x = x || p.name == "x";
        y = y || p.name == "y";
        z = z || p.name == "z";
      }
  if (!(x && y && z))
    Fail(path, "the PLY header declares no vertex x, y and z properties");
  // vtkPLYReader dereferences the face list it expects without checking that it is there.
  for (const auto& e : h.elements)
    if (e.name == "face")
    {
      bool indices = false;
      for (const auto& p : e.properties)
        indices = indices || (p.list && (p.name == "vertex_indices" || p.name == "vertex_index"));
      if (!indices)
        Fail(path, "the PLY header declares faces without a vertex_indices list");
    }
}

// Walks the binary body; `vertices` bounds the face indices.
void WalkBinary(const std::string& path, const PLYHeader& h, const std::string& bytes, bool bigEndian,
                long long vertices)
{
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  std::size_t at = h.dataStart;
  auto need = [&](std::size_t n, const PLYElement& e, long long i) {
    if (bytes.size() - at < n)
      Fail(path,
           "truncated PLY: the file ends in " + e.name + " " + std::to_string(i) + " of " + std::to_string(e.count));
  };
  for (const auto& e : h.elements)
    for (long long i = 0; i < e.count; ++i)
      for (const auto& p : e.properties)
      {
        long long items = 1;
        if (p.list)
        {
          need(static_cast<std::size_t>(p.countBytes), e, i);
          items = ReadInteger(data + at, p.countBytes, true, bigEndian);
          at += static_cast<std::size_t>(p.countBytes);
          if (items < 0 || items > kMaxListLength)
            Fail(path, "PLY " + e.name + " " + std::to_string(i) + ": a list of " + std::to_string(items) + " items");
        }
        need(static_cast<std::size_t>(items * p.itemBytes), e, i);
        if (p.list && e.name == "face" && !p.itemFloat)
          for (long long k = 0; k < items; ++k)
          {
            const long long v = ReadInteger(data + at + k * p.itemBytes, p.itemBytes, p.itemSigned, bigEndian);
            if (v < 0 || v >= vertices)
              Fail(path, "PLY face " + std::to_string(i) + " refers to vertex " + std::to_string(v) +
                           " (the file has " + std::to_string(vertices) + ")");
          }
        at += static_cast<std::size_t>(items * p.itemBytes);
      }
}

void WalkAscii(const std::string& path, const PLYHeader& h, const std::string& bytes, long long vertices)
{
  std::istringstream in(bytes.substr(h.dataStart));
  for (const auto& e : h.elements)
    for (long long i = 0; i < e.count; ++i)
      for (const auto& p : e.properties)
      {
        double value = 0;
        long long items = 1;
        if (p.list)
        {
          if (!(in >> value))
            Fail(path, "truncated PLY: the file ends in " + e.name + " " + std::to_string(i) + " of " +
                         std::to_string(e.count));
          items = static_cast<long long>(value);
          if (value != static_cast<double>(items) || items < 0 || items > kMaxListLength)
            Fail(path, "PLY " + e.name + " " + std::to_string(i) + ": a list of " + std::to_string(value) + " items");
        }
        for (long long k = 0; k < items; ++k)
        {
          if (!(in >> value))
            Fail(path, "truncated PLY: the file ends in " + e.name + " " + std::to_string(i) + " of " +
                         std::to_string(e.count));
          if (p.list && e.name == "face" && (value < 0 || value >= static_cast<double>(vertices)))
            Fail(path, "PLY face " + std::to_string(i) + " refers to vertex " + std::to_string(value) +
                         " (the file has " + std::to_string(vertices) + ")");
        }
      }
}
} // namespace

void CheckPLYFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const PLYHeader h = ReadPLYHeader(path, bytes);
  CheckVertexCoordinates(path, h);
  const bool ascii = h.format == "ascii";
  if (!ascii && h.format != "binary_little_endian" && h.format != "binary_big_endian")
    Fail(path, "PLY header: unknown format '" + h.format + "'");
  // Before walking: every declared item takes at least one byte (binary: its size; ascii: a digit
  // and a separator), so a count the file cannot hold is refused at once.
  long double least = 0, vertices = 0;
  for (const auto& e : h.elements)
  {
    long double perItem = 0;
    for (const auto& p : e.properties)
      perItem += ascii ? 2 : (p.list ? p.countBytes : p.itemBytes);
    least += perItem * static_cast<long double>(e.count);
    if (e.name == "vertex")
      vertices = static_cast<long double>(e.count);
  }
  if (least > static_cast<long double>(bytes.size() - h.dataStart))
    Fail(path, "truncated PLY: the header declares more data than the file's " + std::to_string(bytes.size()) +
                 " bytes hold");
  if (ascii)
    WalkAscii(path, h, bytes, static_cast<long long>(vertices));
  else
    WalkBinary(path, h, bytes, h.format == "binary_big_endian", static_cast<long long>(vertices));
}

void CheckSTLFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (bytes.size() >= 84)
  {
    std::uint32_t n = 0;
    for (int b = 3; b >= 0; --b)
      n = (n << 8) | static_cast<unsigned char>(bytes[80 + static_cast<std::size_t>(b)]);
    if (bytes.size() == 84 + 50ULL * n)
      return; // binary, whole
  }
  if (bytes.rfind("solid", 0) == 0)
  {
    const std::size_t last = bytes.find_last_not_of(" \t\r\n");
    const std::size_t lineStart = last == std::string::npos ? 0 : bytes.find_last_of('\n', last) + 1;
    if (bytes.compare(lineStart, 8, "endsolid") == 0)
      return; // ASCII, closed by its last line
    Fail(path, "truncated STL: an ASCII STL that does not end with 'endsolid'");
  }
  Fail(path, "truncated or damaged STL: a binary STL must hold 84 + 50 bytes a triangle (" +
               std::to_string(bytes.size()) + " bytes)");
}

} // namespace mmrep
