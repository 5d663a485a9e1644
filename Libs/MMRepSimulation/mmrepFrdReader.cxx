// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// .frd nodal result reader: parses the "100C" result blocks (fixed-width ASCII records).
#include "mmrepFrdReader.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mmrep::simulation
{
namespace
{
double ParseNumber(const std::string& text, const std::string& where)
{
  std::size_t used = 0;
  double v = 0;
  try
  {
    v = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    throw std::runtime_error(where + ": '" + text + "' is not a number");
  }
  return v;
}

std::string Trim(const std::string& s)
{
  const auto b = s.find_first_not_of(' ');
  const auto e = s.find_last_not_of(" \r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}
} // namespace

std::vector<FrdBlock> ReadFrd(std::istream& in, const std::string& source)
{
  std::vector<FrdBlock> blocks;
  std::string line;
  long lineNo = 0;
  const auto where = [&]() { return source + " line " + std::to_string(lineNo); };
  FrdBlock current;
  double pendingTime = 0;
  int pendingStep = 0;
  bool inBlock = false;
  while (std::getline(in, line))
  {
    ++lineNo;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    if (line.compare(0, 7, "  100CL") == 0)
    {
      // "  100CL  101 1.000000000          10   0    6           1": time at columns 12..24.
      if (line.size() < 24)
        throw std::runtime_error(where() + ": short 100CL record");
      pendingTime = ParseNumber(line.substr(12, 12), where());
      std::istringstream rest(line.substr(24));
      int n = 0, mode = 0, step = 0;
      rest >> n >> mode >> step;
      pendingStep = step;
      const auto last = line.find_last_not_of(' ');
      if (last != std::string::npos && line[last] == '2')
        throw std::runtime_error(where() + ": binary .frd results are not supported (use the ASCII format)");
      continue;
    }
    if (line.compare(0, 3, " -4") == 0)
    {
      current = FrdBlock();
      std::istringstream s(line.substr(3));
      s >> current.name >> current.components;
      current.time = pendingTime;
      current.step = pendingStep;
      inBlock = true;
      continue;
    }
    if (!inBlock)
      continue;
    if (line.compare(0, 3, " -5") == 0)
      continue;
    if (line.compare(0, 3, " -1") == 0)
    {
      // " -1" + node (5 or 10 columns) + values of 12 columns each.
      const std::size_t body = line.size() - 3;
      const std::size_t width = body % 12;
      if (width != 5 && width != 10)
        throw std::runtime_error(where() + ": unexpected record length " + std::to_string(line.size()));
      const int node = static_cast<int>(ParseNumber(line.substr(3, width), where()));
      std::vector<double> v;
      for (std::size_t p = 3 + width; p + 12 <= line.size(); p += 12)
        v.push_back(ParseNumber(line.substr(p, 12), where()));
      if (v.empty())
        throw std::runtime_error(where() + ": result record without values");
      current.values[node] = std::move(v);
      continue;
    }
    if (line.compare(0, 3, " -2") == 0)
      continue; // continuation records (more than 6 components): not used here
    if (line.compare(0, 3, " -3") == 0)
    {
      blocks.push_back(std::move(current));
      current = FrdBlock();
      inBlock = false;
      continue;
    }
  }
  if (inBlock)
    throw std::runtime_error(source + ": result block '" + current.name + "' is not terminated (truncated file?)");
  return blocks;
}

std::vector<FrdBlock> ReadFrdFile(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("cannot open CalculiX result file '" + path + "'");
  return ReadFrd(in, path);
}

const FrdBlock* LastBlock(const std::vector<FrdBlock>& blocks, const std::string& name)
{
  for (auto it = blocks.rbegin(); it != blocks.rend(); ++it)
    if (it->name == name)
      return &*it;
  return nullptr;
}

} // namespace mmrep::simulation
