// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Helpers shared by the MMRepCLI sources (not part of the public API).
#pragma once

#include "mmrepCLI.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace mmrep::cli::detail
{

std::string Trim(std::string_view text);
std::string Lower(std::string text);
// "1, 2,3" -> {"1","2","3"}; Slicer passes vectors, points and regions comma-separated.
std::vector<std::string> SplitComma(const std::string& text);
// Whole-string, locale-independent number parsing ("+3", "-2.5e3"); false on any trailing junk.
bool ParseInt(const std::string& text, long long& value);
bool ParseDouble(const std::string& text, double& value);
bool ParseBool(const std::string& text, bool& value);
// Shortest text that reads back to the same double.
std::string FormatDouble(double value);
// How a parameter is named in messages: "'iterations' (--iterations)".
std::string Describe(const Parameter& p);
// Throws ModuleError naming the parameter when a value does not fit its declaration.
void Validate(const Parameter& p, const std::vector<std::string>& values);

// Abort bookkeeping of one run: polls stop throwing once an output is committed (mmrepProgress.cxx).
void BeginRun();
void OutputCommitted();

// The output transaction of a module run (mmrepOutputSafety.cxx): Begin checks the command line's
// paths (throws ModuleError), Publish renames every scheduled output into place, Discard removes them.
void BeginOutputTransaction(const ModuleDescription& description,
                            const std::map<std::string, std::vector<std::string>>& values,
                            const std::string& returnParameterFile);
void PublishOutputs();
void DiscardOutputs();

// Silences ITK's and VTK's own console output for the rest of the process (see mmrepQuietConsoles.cxx).
void SilenceToolkitConsoles();

} // namespace mmrep::cli::detail
