// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The registration report: node-to-surface errors of a stage, JSON and Markdown tables, Q's stage.
#include "mmrepAtlasRegistration.h"

#include <nlohmann/json.hpp>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace mmrep
{
namespace
{
nlohmann::json StatsJson(const SurfaceDistance& s)
{
  return {{"count", s.count}, {"mean", s.mean}, {"max", s.max}, {"sigma", s.sigma}};
}
} // namespace

std::string RegistrationReport::ToJson() const
{
  nlohmann::json j;
  j["stages"] = nlohmann::json::array();
  for (const auto& s : stages)
  {
    j["stages"].push_back({{"name", s.name},
                           {"seconds", s.seconds},
                           {"skin", StatsJson(s.skin)},
                           {"skull", StatsJson(s.skull)},
                           {"lips", StatsJson(s.lips)},
                           {"controlPointMean", s.controlMean},
                           {"controlPointMax", s.controlMax},
                           {"stepsPerLevel", s.stepsPerLevel},
                           {"sweepsPerLevel", s.sweepsPerLevel},
                           {"energyBefore", s.energyBefore},
                           {"energyAfter", s.energyAfter}});
  }
  nlohmann::json cps = nlohmann::json::array();
  for (std::size_t i = 0; i < controlNames.size(); ++i)
    cps.push_back({{"name", controlNames[i]},
                   {"error", i < controlErrors.size() ? controlErrors[i] : 0.0},
                   {"weight", i < controlWeights.size() ? controlWeights[i] : 0.0}});
  j["controlPoints"] = cps;
  return j.dump(2);
}

namespace
{
std::string Cell(double v, bool defined, int precision = 3)
{
  if (!defined)
    return "—";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", precision, v);
  return buf;
}

std::string StatsCells(const SurfaceDistance& s)
{
  const bool d = s.count > 0;
  return Cell(s.mean, d) + " | " + Cell(s.max, d) + " | " + Cell(s.sigma, d);
}
} // namespace

std::string RegistrationReport::ToMarkdown(const std::string& title) const
{
  std::ostringstream md;
  md << "## " << title << "\n\n"
     << "Errors in mm: distance of the registered atlas nodes to the subject's triangle surfaces (skin, skull; "
        "lips = skin nodes of the `lips` set), control points = distance to the subject's points of the same name.\n\n"
     << "| stage | skin mean | skin max | skin σ | skull mean | skull max | skull σ | lips mean | lips max | lips σ "
        "| control mean | control max | steps | time (s) |\n"
     << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& s : stages)
  {
    std::size_t steps = 0;
    for (auto n : s.stepsPerLevel)
      steps += n;
    const bool hasControl = s.controlMeasured;
    md << "| " << s.name << " | " << StatsCells(s.skin) << " | " << StatsCells(s.skull) << " | " << StatsCells(s.lips)
       << " | " << Cell(s.controlMean, hasControl) << " | " << Cell(s.controlMax, hasControl) << " | "
       << (s.stepsPerLevel.empty() ? std::string("—") : std::to_string(steps)) << " | " << Cell(s.seconds, true, 2)
       << " |\n";
  }
  if (!controlNames.empty())
  {
    md << "\n| control point | error (mm) | final weight |\n|---|---:|---:|\n";
    for (std::size_t i = 0; i < controlNames.size(); ++i)
      md << "| " << controlNames[i] << " | "
         << Cell(i < controlErrors.size() ? controlErrors[i] : 0, i < controlErrors.size()) << " | "
         << Cell(i < controlWeights.size() ? controlWeights[i] : 0, i < controlWeights.size(), 1) << " |\n";
  }
  return md.str();
}

RegistrationReport LocalRefinementResult::Report() const
{
  RegistrationReport r;
  RegistrationStage b = before, a = after;
  b.name = "R (before refinement)";
  a.name = "Q∘R";
  b.controlMeasured = a.controlMeasured = false; // RefineLocally has no subject control points
  r.stages = {b, a};
  return r;
}

void AddRefinementStage(RegistrationReport& report, const LocalRefinementResult& refinement,
                        const std::vector<Landmark>& subjectControlPoints)
{
  RegistrationStage s = refinement.after;
  s.name = "refinement (Q∘R)";
  s.controlMean = s.controlMax = 0;
  s.controlMeasured = !subjectControlPoints.empty();
  if (s.controlMeasured)
  {
    std::vector<double> errors;
    for (const auto& name : report.controlNames)
    {
      const auto l = std::find_if(refinement.mesh.landmarks.begin(), refinement.mesh.landmarks.end(),
                                  [&](const Landmark& x) { return x.name == name; });
      const auto t = std::find_if(subjectControlPoints.begin(), subjectControlPoints.end(),
                                  [&](const Landmark& x) { return x.name == name; });
      if (l == refinement.mesh.landmarks.end() || t == subjectControlPoints.end())
        throw std::invalid_argument("refinement report: control point '" + name + "' is missing");
      errors.push_back((l->position - t->position).norm());
      s.controlMean += errors.back() / static_cast<double>(report.controlNames.size());
      s.controlMax = std::max(s.controlMax, errors.back());
    }
    report.controlErrors = errors;
  }
  report.stages.push_back(s);
}

} // namespace mmrep
