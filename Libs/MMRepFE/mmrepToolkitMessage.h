// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// ITK's and VTK's error texts are written for their developers: "ITK ERROR: NrrdImageIO(0x55…):",
// "ERROR: In /build/…/vtkXMLReader.cxx, line 123", "[nrrd] _nrrdRead:" stacks over several lines.
// A module reports a problem as one line in words, so every toolkit text that reaches the user
// goes through ToolkitMessage first.
#pragma once

#include <string>

namespace mmrep
{

// One line from a toolkit's error text: without object addresses, class and function prefixes,
// source locations and qualified enum names; of a Teem (NRRD) stack, the innermost reason.
std::string ToolkitMessage(const std::string& text);

} // namespace mmrep
