// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The activation report (see the header).
#include "mmrepActivationReport.h"

#include <cstdarg>
#include <cstdio>

namespace mmrep::simulation
{
namespace
{
void Append(std::string& s, const char* format, ...)
{
  va_list args;
  va_start(args, format);
  va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string line(static_cast<std::size_t>(n) + 1, '\0');
  std::vsnprintf(line.data(), line.size(), format, args);
  va_end(args);
  line.pop_back();
  s += line;
}
} // namespace

std::string ActivationReport(const ActivationResult& result, int threads, double jawAngle, const MouthMeasures& mouth,
                             double maxDisplacement)
{
  std::string s;
  Append(s,
         "CalculiX: converged in %d increments, %d iterations, %d cutbacks, %.1f s (%d threads); "
         "%zu solids, %zu cables, %zu equations, %zu fixed nodes, %zu sliding nodes, %zu symmetry-plane nodes\n",
         result.run.increments, result.run.iterations, result.run.cutbacks, result.run.seconds, threads,
         result.deck.solids, result.deck.springs, result.deck.equations, result.deck.fixedNodes,
         result.deck.slidingNodes, result.deck.symmetryNodes);
  for (const auto& m : result.muscles)
    Append(s, "muscle %-36s activation %.2f  length %.1f -> %.1f mm (%+.1f %%)  cable force mean %.3f N, max %.3f N\n",
           m.muscle.c_str(), m.level, m.restLength, m.length, 100 * (m.length / m.restLength - 1), m.meanForce,
           m.maxForce);
  Append(s, "%-22s %9s %9s %9s %9s   (mm; +x patient left, -y anterior, +z superior)\n", "landmark", "ux", "uy", "uz",
         "|u|");
  for (const auto& m : result.landmarks)
    Append(s, "%-22s %9.3f %9.3f %9.3f %9.3f   %s\n", m.name.c_str(), m.displacement.x(), m.displacement.y(),
           m.displacement.z(), m.displacement.norm(),
           m.element >= 0 ? ("element " + std::to_string(m.element)).c_str() : "nearest node");
  Append(s, "largest node displacement %.3f mm\n", maxDisplacement);
  if (jawAngle != 0)
    Append(s, "jaw opened %.1f deg (%zu mandible nodes moved)\n", jawAngle, result.deck.jawNodes);
  if (mouth.hasCorners)
    Append(s, "mouth width %.2f -> %.2f mm (%+.2f); right corner %+.3f %+.3f %+.3f mm\n", mouth.restWidth, mouth.width,
           mouth.width - mouth.restWidth, mouth.rightCorner.x(), mouth.rightCorner.y(), mouth.rightCorner.z());
  Append(s, "protrusion (forward): upper lip %+.3f mm, lower lip %+.3f mm\n", mouth.upperProtrusion,
         mouth.lowerProtrusion);
  if (mouth.hasSlit)
    Append(s,
           "lip aperture: height %.2f mm at the centre, width %.2f mm; lip gap min %+.3f mm, mean %+.3f mm "
           "(contact pair: %zu nodes on %zu faces)\n",
           mouth.apertureHeight, mouth.apertureWidth, mouth.minimumLipGap, mouth.meanLipGap, result.deck.contactNodes,
           result.deck.contactFaces);
  return s;
}

} // namespace mmrep::simulation
