// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepToolkitMessage.h"

#include <regex>
#include <sstream>
#include <vector>

namespace mmrep
{
namespace
{
std::string Trim(const std::string& s)
{
  const auto b = s.find_first_not_of(" \t\r\n");
  const auto e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}
} // namespace

std::string ToolkitMessage(const std::string& text)
{
  // Source locations: ITK's what() "file.cxx:123:", VTK's "ERROR: In file, line 123".
  static const std::regex location(
    R"(^\S+\.(cxx|hxx|txx|cpp|cc|h):\d+:?$|^(ERROR|Warning|Generic Warning): In .*, line \d+$)");
  // "ITK ERROR: NrrdImageIO(0x55…): ", "itk::ERROR: …", "vtkXMLPolyDataReader (0x55…): ".
  static const std::regex origin(R"((itk::ERROR|ITK ERROR|itk::WARNING|ITK WARNING): |\b\w+ ?\(0x[0-9a-fA-F]+\): )");
  static const std::regex address(R"(\s*\(?0x[0-9a-fA-F]+\)?)");
  static const std::regex enumName(R"(\b(itk::)?\w+Enums::\w+::)");
  static const std::regex method(R"(^[A-Z][A-Za-z]*: (?=\S))"); // "Read: ", the throwing method's name
  static const std::regex teem(R"(^\[\w+\] \w+:\s*)");          // "[nrrd] _nrrdRead: "
  static const std::regex metaIO(R"(^Meta\w*: M?_?\w+: )");     // "MetaImage: M_ReadElementsData: "
  std::vector<std::string> lines;
  std::string innermost; // of a Teem stack
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
  {
    line = Trim(line);
    if (line.empty() || std::regex_search(line, location))
      continue;
    if (std::regex_search(line, teem))
    {
      if (const std::string reason = Trim(std::regex_replace(line, teem, "")); !reason.empty())
        innermost = reason;
      continue;
    }
    line = std::regex_replace(line, metaIO, "");
    const bool prefixed = std::regex_search(line, origin);
    line = std::regex_replace(line, origin, "");
    if (prefixed)
      line = std::regex_replace(line, method, "");
    line = Trim(std::regex_replace(std::regex_replace(line, address, ""), enumName, ""));
    if (!line.empty())
      lines.push_back(line);
  }
  std::string out;
  for (const std::string& line : lines)
    out += (out.empty() ? "" : out.back() == ':' ? " " : "; ") + line;
  if (!innermost.empty())
    out += (out.empty() ? "" : out.back() == ':' ? " " : ": ") + innermost;
  return out.empty() ? "unknown toolkit error" : out;
}

} // namespace mmrep
