// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepRepairSummary.h"

#include "mmrepMeshQuality.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

namespace mmrep
{
namespace
{
using nlohmann::json;

json Number(double v) // JSON has no NaN / infinity
{
  return std::isfinite(v) ? json(v) : json(nullptr);
}

json ToJSON(const SurfaceDistance& d)
{
  return {{"nodes", d.count}, {"meanDistance", d.mean}, {"maxDistance", d.max}};
}
} // namespace

std::vector<double> ScaledJacobianValues(const FEMesh& mesh)
{
  std::vector<double> values;
  const auto all = quality::ComputeQuality(mesh, quality::Measure::ScaledJacobian, {1, {}});
  for (const double v : all)
    if (!std::isnan(v))
      values.push_back(quality::IsVerdictFlag(v) ? -std::numeric_limits<double>::infinity() : v);
  return values;
}

std::vector<SurfaceAccuracy> SurfaceAccuracySets(vtkPolyData* skin, vtkPolyData* skull)
{
  std::vector<SurfaceAccuracy> accuracy;
  if (skin)
  {
    accuracy.push_back({"skin", "skinSurface", skin, {}, {}});
    accuracy.push_back({"lips", "skinSurface", skin, {}, {}});
  }
  if (skull)
    accuracy.push_back({"skull", "skullSurface", skull, {}, {}});
  return accuracy;
}

void MeasureSurfaceAccuracy(const FEMesh& mesh, std::vector<SurfaceAccuracy>& accuracy, bool after)
{
  for (auto& a : accuracy)
    (after ? a.after : a.before) = MeasureSurfaceDistance(mesh, a.set, a.surface);
}

std::string RepairReportJson(const RepairReport& report, const FEMesh& repaired,
                             const std::vector<SurfaceAccuracy>& accuracy, const std::string& input,
                             const std::string& output, double threshold)
{
  json j;
  j["input"] = input;
  j["output"] = report.success ? json(output) : json(nullptr);
  j["threshold"] = threshold;
  j["success"] = report.success;
  j["quality"] = {{"before",
                   {{"minScaledJacobian", Number(report.minScaledJacobianBefore)},
                    {"meanScaledJacobian", Number(report.meanScaledJacobianBefore)},
                    {"belowThreshold", report.belowThresholdBefore},
                    {"inverted", report.invertedBefore},
                    {"notCertifiedInside", report.notCertifiedBefore},
                    {"certifiedMinimumJacobianRatio", Number(report.certifiedMinimumBefore)}}},
                  {"after",
                   {{"minScaledJacobian", Number(report.minScaledJacobianAfter)},
                    {"meanScaledJacobian", Number(report.meanScaledJacobianAfter)},
                    {"belowThreshold", report.belowThresholdAfter},
                    {"inverted", report.invertedAfter},
                    {"notCertifiedInside", report.notCertifiedAfter},
                    {"certifiedMinimumJacobianRatio", Number(report.certifiedMinimumAfter)}}}};
  json surfaces = json::object();
  for (const auto& a : accuracy)
    surfaces[a.set] = {{"surface", a.surfaceName}, {"before", ToJSON(a.before)}, {"after", ToJSON(a.after)}};
  j["surfaceAccuracy"] = surfaces;
  j["solidElements"] = repaired.SolidElementCount();
  j["untanglingSteps"] = report.untanglingSteps;
  j["movedNodes"] = report.movedNodes;
  j["movedSurfaceNodes"] = report.movedSurfaceNodes;
  j["symmetricPairs"] = report.symmetricPairs;
  j["seconds"] = report.seconds;
  j["untanglingSeconds"] = report.untanglingSeconds;
  json failed = json::array();
  for (std::size_t k = 0; k < report.failedElements.size(); ++k)
  {
    const std::size_t e = report.failedElements[k];
    failed.push_back({{"element", e},
                      {"layer", TissueLayerName(repaired.elements[e].layer)},
                      {"scaledJacobian", Number(report.failedValues[k])},
                      {"degenerate", std::isinf(report.failedValues[k])}});
  }
  j["failedElements"] = failed;
  json folded = json::array();
  for (std::size_t k = 0; k < report.foldedInside.size(); ++k)
    folded.push_back({{"element", report.foldedInside[k]},
                      {"layer", TissueLayerName(repaired.elements[report.foldedInside[k]].layer)},
                      {"certifiedMinimumJacobianRatio", Number(report.foldedInsideValues[k])}});
  j["foldedInsideElements"] = folded;
  return j.dump(2);
}

std::string RepairFailureMessage(const RepairReport& report, double threshold)
{
  if (report.failedElements.empty() && !report.foldedInside.empty())
  {
    char text[160];
    std::snprintf(text, sizeof text,
                  "%zu elements are folded inside although their corners are good (worst: element %zu, det J down "
                  "to %.3g of its mean)",
                  report.foldedInside.size(), report.foldedInside[0], report.foldedInsideValues[0]);
    return text;
  }
  char worst[64];
  const double w = report.failedValues.empty() ? std::numeric_limits<double>::quiet_NaN() : report.failedValues[0];
  if (std::isinf(w))
    std::snprintf(worst, sizeof worst, "degenerate");
  else
    std::snprintf(worst, sizeof worst, "%.4g", w);
  char limit[32];
  std::snprintf(limit, sizeof limit, "%g", threshold);
  return std::to_string(report.failedElements.size()) + " elements stay below the scaled Jacobian threshold " + limit +
         " (worst: element " +
         (report.failedElements.empty() ? std::string("?") : std::to_string(report.failedElements[0])) + ", " + worst +
         ")";
}

} // namespace mmrep
