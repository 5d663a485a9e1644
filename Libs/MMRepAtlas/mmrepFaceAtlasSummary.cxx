// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFaceAtlasSummary.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace mmrep
{
namespace
{
// Nearest-rank percentile of a non-empty sample.
double Percentile(std::vector<double> v, double p)
{
  std::sort(v.begin(), v.end());
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(std::floor(p * (v.size() - 1) + 0.5)));
  return v[k];
}
} // namespace

FaceAtlasQuality MeasureFaceAtlasQuality(const FEMesh& mesh, double threshold)
{
  quality::QualityOptions qo;
  qo.threads = 1;
  const auto sj = quality::ComputeQuality(mesh, quality::Measure::ScaledJacobian, qo);
  const auto jac = quality::ComputeQuality(mesh, quality::Measure::Jacobian, qo);
  FaceAtlasQuality q;
  q.summary = quality::Summarize(sj, jac, threshold);
  std::vector<double> defined;
  for (double v : sj)
    if (!std::isnan(v))
      defined.push_back(v);
  if (defined.empty())
    throw std::runtime_error("face atlas: no solid element has a defined scaled Jacobian");
  q.percentile1 = Percentile(defined, 0.01);
  q.percentile5 = Percentile(defined, 0.05);
  q.median = Percentile(defined, 0.5);
  std::ostringstream s;
  s << "Scaled Jacobian: min " << q.summary.min << ", 1% " << q.percentile1 << ", 5% " << q.percentile5 << ", median "
    << q.median << ", mean " << q.summary.mean << ", max " << q.summary.max << "; inverted " << q.summary.inverted
    << ", below " << threshold << ": " << q.summary.belowThreshold;
  q.line = s.str();
  return q;
}

void RequireFaceAtlasQuality(const FaceAtlasQuality& quality, double threshold)
{
  const auto& s = quality.summary;
  if (s.inverted > 0 || s.belowThreshold > 0)
    throw std::runtime_error("the atlas does not reach the quality threshold (" + std::to_string(s.belowThreshold) +
                             " elements below " + std::to_string(threshold) + ", " + std::to_string(s.inverted) +
                             " inverted)");
}

std::string FaceAtlasCounts(const FEMesh& mesh)
{
  const std::size_t cables = mesh.elements.size() - mesh.SolidElementCount();
  std::ostringstream s;
  s << "Atlas: " << mesh.nodes.size() << " nodes, " << mesh.SolidElementCount() << " hexahedra, " << cables
    << " cables, " << mesh.muscles.size() << " muscle tracks; lips " << mesh.nodeSets.at("lips").size() << ", skin "
    << mesh.nodeSets.at("skin").size() << ", skull " << mesh.nodeSets.at("skull").size() << ", inner "
    << mesh.nodeSets.at("inner").size() << ", midsagittal " << mesh.nodeSets.at("midsagittal").size() << " nodes";
  return s.str();
}

} // namespace mmrep
