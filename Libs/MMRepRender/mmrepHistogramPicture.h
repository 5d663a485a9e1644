// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// PNG of scaled-Jacobian histograms, e.g. before and after a repair (VTK, off-screen; needs X).
#pragma once

#include <string>
#include <vector>

namespace mmrep
{

struct HistogramPanel
{
  std::string title;
  std::vector<double> values; // one scaled Jacobian per solid element; degenerate ones as -infinity
};

// Bins [-1, 1] into `bins` bars per panel (degenerate values in the first bin), bars below the
// threshold red, a line at the threshold, side by side panels sharing one count axis.
// Throws std::runtime_error without an X display or when the PNG cannot be written.
void WriteHistogramPNG(const std::vector<HistogramPanel>& panels, double threshold, const std::string& pngPath,
                       int bins = 40);

// Counts per bin as drawn (exposed for tests).
std::vector<std::size_t> HistogramCounts(const std::vector<double>& values, int bins);

} // namespace mmrep
