// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Small helpers shared by the CLI framework tests.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace mmrep::cli::test
{
inline std::string ReadFile(const std::filesystem::path& path)
{
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

inline std::vector<std::string> Lines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream s(text);
  for (std::string line; std::getline(s, line);)
    lines.push_back(line);
  return lines;
}

// Output of a shell command (used to query xmllint as an independent XML reader).
inline std::string Capture(const std::string& command)
{
  std::string out;
  if (FILE* p = popen(command.c_str(), "r"))
  {
    char buffer[4096];
    for (size_t n; (n = fread(buffer, 1, sizeof(buffer), p)) > 0;)
      out.append(buffer, n);
    pclose(p);
  }
  return out;
}

// A fresh, empty folder for the current test (tests may run in parallel).
inline std::filesystem::path TestFolder()
{
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir =
    std::filesystem::current_path() / (std::string("work-") + info->test_suite_name() + "-" + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}
} // namespace mmrep::cli::test
