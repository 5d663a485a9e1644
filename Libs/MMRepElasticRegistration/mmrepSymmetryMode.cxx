// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The three symmetry modes of the registration by name (mmrepAtlasRegistration.h).
#include "mmrepAtlasRegistration.h"

#include <stdexcept>

namespace mmrep
{

void SetSymmetryMode(AtlasRegistrationOptions& options, const std::string& mode)
{
  if (mode == "half-face" || mode == "averaged" || mode == "full")
  {
    options.symmetric = mode != "full";
    options.halfFace = mode == "half-face";
    return;
  }
  throw std::invalid_argument("symmetry: '" + mode + "' is not a mode (half-face, averaged or full)");
}

std::string SymmetryModeName(const AtlasRegistrationOptions& options)
{
  return !options.symmetric ? "full" : options.halfFace ? "half-face" : "averaged";
}

} // namespace mmrep
