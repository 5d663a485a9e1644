// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFaceModelReport.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace mmrep
{
namespace
{
using nlohmann::json;

json Number(double v) // JSON has no NaN or infinity
{
  return std::isfinite(v) ? json(v) : json(nullptr);
}

json Stats(const SurfaceDistance& s)
{
  return {{"nodes", s.count}, {"mean", Number(s.mean)}, {"max", Number(s.max)}, {"sigma", Number(s.sigma)}};
}

std::string F(double v, int digits = 3)
{
  if (!std::isfinite(v))
    return "–";
  char s[32];
  std::snprintf(s, sizeof s, "%.*f", digits, v);
  return s;
}

double Mean(const std::vector<double>& v)
{
  double s = 0;
  for (double x : v)
    s += x;
  return v.empty() ? 0 : s / static_cast<double>(v.size());
}

double Max(const std::vector<double>& v)
{
  double m = 0;
  for (double x : v)
    m = std::max(m, x);
  return m;
}

json Point(const Point3& p)
{
  return json::array({p.x(), p.y(), p.z()});
}
} // namespace

std::string FaceModelReportJson(const FaceModelResult& r, const FaceModelReportInputs& in)
{
  json j;
  j["inputs"] = {{"ct", in.ct}, {"controlPoints", in.controlPoints}, {"atlas", in.atlas}};
  j["fieldOfView"] = {{"complete", r.fieldOfViewMissing.empty() && r.notImaged.empty()},
                      {"missing", r.fieldOfViewMissing},
                      {"notImaged", r.notImaged},
                      {"notImagedNodes", r.notImagedNodes}};
  j["fit"] = {{"poor", !r.poorFit.empty()}, {"why", r.poorFit}};
  if (r.reorientation.applied)
  {
    nlohmann::json rows = nlohmann::json::array();
    for (int i = 0; i < 3; ++i)
      rows.push_back({r.reorientation.rotation(i, 0), r.reorientation.rotation(i, 1), r.reorientation.rotation(i, 2)});
    j["reorientation"] = {{"storedFace", r.reorientation.before}, {"rotation", rows}};
  }
  j["thresholds"] = {{"skin", r.thresholds.skin}, {"bone", r.thresholds.bone}, {"source", r.thresholds.source}};
  j["surfaces"] = {{"skinVertices", r.skin->GetNumberOfPoints()},
                   {"skinTriangles", r.skin->GetNumberOfPolys()},
                   {"skullVertices", r.skull->GetNumberOfPoints()},
                   {"skullTriangles", r.skull->GetNumberOfPolys()}};
  j["symmetryPlane"] = {
    {"point", Point(r.plane.point)}, {"normal", Point(r.plane.normal)}, {"rmsResidual", r.planeResidual}};
  json accuracy = json::array();
  for (const auto& a : r.accuracy)
  {
    json cp = json::object();
    for (std::size_t i = 0; i < r.controlNames.size() && i < a.controlErrors.size(); ++i)
      cp[r.controlNames[i]] = Number(a.controlErrors[i]);
    accuracy.push_back(
      {{"state", a.state},
       {"skin", Stats(a.skin)},
       {"skull", Stats(a.skull)},
       {"lips", Stats(a.lips)},
       {"fittedHalf", {{"skin", Stats(a.skinHalf)}, {"skull", Stats(a.skullHalf)}, {"lips", Stats(a.lipsHalf)}}},
       {"controlPoints", {{"mean", Mean(a.controlErrors)}, {"max", Max(a.controlErrors)}, {"each", cp}}}});
  }
  j["accuracy"] = accuracy;
  j["fitted"] = r.fitted;
  j["accuracyUnits"] = "mm, node to the subject's triangle surface (control points: point to point)";
  j["quality"] = {{"threshold", in.repairThreshold},
                  {"elements", r.model.SolidElementCount()},
                  {"beforeRepair",
                   {{"minScaledJacobian", Number(r.repair.minScaledJacobianBefore)},
                    {"meanScaledJacobian", Number(r.repair.meanScaledJacobianBefore)},
                    {"inverted", r.repair.invertedBefore},
                    {"belowThreshold", r.repair.belowThresholdBefore},
                    {"notCertifiedInside", r.repair.notCertifiedBefore}}},
                  {"afterRepair",
                   {{"minScaledJacobian", Number(r.repair.minScaledJacobianAfter)},
                    {"meanScaledJacobian", Number(r.repair.meanScaledJacobianAfter)},
                    {"inverted", r.repair.invertedAfter},
                    {"belowThreshold", r.repair.belowThresholdAfter},
                    {"notCertifiedInside", r.repair.notCertifiedAfter}}},
                  {"repairSeconds", r.repair.seconds},
                  {"repairSucceeded", r.repair.success},
                  {"movedNodes", r.repair.movedNodes},
                  {"movedSurfaceNodes", r.repair.movedSurfaceNodes}};
  json insertions = json::object();
  for (const auto& ins : r.muscles.insertions)
    insertions[ins.muscle] = {{"atlas", Point(ins.atlas)}, {"subject", Point(ins.subject)}};
  j["muscles"] = {{"tracks", r.muscles.muscles},
                  {"points", r.muscles.points},
                  {"pointsOutsideElements", r.muscles.outside},
                  {"maxOutsideDistance", r.muscles.maxOutsideDistance},
                  {"insertions", insertions}};
  json times = json::object();
  for (const auto& t : r.times)
    times[t.name] = t.seconds;
  j["seconds"] = times;
  j["totalSeconds"] = r.totalSeconds;
  j["mesh"] = {{"nodes", r.model.nodes.size()},
               {"elements", r.model.elements.size()},
               {"solidElements", r.model.SolidElementCount()}};
  json files = json::object();
  for (const auto& [f, what] : in.files)
    files[f] = what;
  j["files"] = files;
  return j.dump(2) + "\n";
}

std::string FaceModelReportMarkdown(const FaceModelResult& r, const FaceModelReportInputs& in)
{
  std::ostringstream md;
  md << "# MMRep speaker face model\n\n"
     << "CT `" << in.ct << "`, control points `" << in.controlPoints << "`, atlas `" << in.atlas << "`.\n"
     << "Model: " << r.model.nodes.size() << " nodes, " << r.model.SolidElementCount() << " solid elements, "
     << r.model.muscles.size() << " muscle tracks. Whole pipeline: " << F(r.totalSeconds, 1) << " s.\n\n";
  if (!r.fieldOfViewMissing.empty())
    md << "**Partial model**: the CT misses the " << r.fieldOfViewMissing
       << " of the face region; there the model is not fitted to the speaker.\n\n";
  if (!r.notImaged.empty())
    md << "**Partial model**: " << r.notImaged << "; its " << r.notImagedNodes
       << " skin nodes there are in node set `notImaged`.\n\n";
  if (!r.poorFit.empty())
    md << "**Poor fit** (accepted by the user): " << r.poorFit << ".\n\n";
  if (r.reorientation.applied)
    md << "**Reoriented**: " << ReorientationInWords(r.reorientation) << ".\n\n";

  md << "## Surface accuracy (mm)\n\n"
     << "Fitted: **" << r.fitted
     << "**. Distances from the model's nodes to the speaker's skin and skull triangle "
        "surfaces (the paper's Tables 1 and 2 measure the same way); the fitted half (its nodes and the mid-sagittal "
        "ones) and the whole model in separate tables, so that no figure mixes them.\n\n";
  auto table = [&](const std::string& title, bool half) {
    md
      << "### " << title << "\n\n"
      << "| Mesh | Skin mean | Skin max | Skin σ | Skull mean | Skull max | Skull σ | Lips mean | Lips max | Lips σ |\n"
      << "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& a : r.accuracy)
    {
      const auto& skin = half ? a.skinHalf : a.skin;
      const auto& skull = half ? a.skullHalf : a.skull;
      const auto& lips = half ? a.lipsHalf : a.lips;
      md << "| "
         << (a.state == "R"     ? "after R (overall)"
             : a.state == "Q∘R" ? "after Q∘R (lips refined)"
                                : "repaired model")
         << " | " << F(skin.mean) << " | " << F(skin.max) << " | " << F(skin.sigma) << " | " << F(skull.mean) << " | "
         << F(skull.max) << " | " << F(skull.sigma) << " | " << F(lips.mean) << " | " << F(lips.max) << " | "
         << F(lips.sigma) << " |\n";
    }
    if (half)
      md
        << "| *paper, Tables 1–2 (half face, repaired)* | *0.3* | *19.2* | *0.4* | *0.5* | *12.4* | *0.5* | *0.02* | *0.29* | "
           "*0.04* |\n";
    const auto& last = r.accuracy.empty() ? ModelAccuracy{} : r.accuracy.back();
    md << "\nNodes: skin " << (half ? last.skinHalf : last.skin).count << ", skull "
       << (half ? last.skullHalf : last.skull).count << ", lips " << (half ? last.lipsHalf : last.lips).count
       << ".\n\n";
  };
  table("Fitted half (left half and mid-sagittal nodes)", true);
  table("Whole model", false);

  md << "## Control points (mm)\n\n| Control point |";
  for (const auto& a : r.accuracy)
    md << " " << a.state << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < r.accuracy.size(); ++i)
    md << "---|";
  md << "\n";
  for (std::size_t i = 0; i < r.controlNames.size(); ++i)
  {
    md << "| " << r.controlNames[i] << " |";
    for (const auto& a : r.accuracy)
      md << " " << F(i < a.controlErrors.size() ? a.controlErrors[i] : NAN) << " |";
    md << "\n";
  }
  md << "| **mean / max** |";
  for (const auto& a : r.accuracy)
    md << " " << F(Mean(a.controlErrors)) << " / " << F(Max(a.controlErrors)) << " |";
  md << "\n\n(The paper: mean 0.7, max 1.0 mm.)\n\n";

  md << "## Element quality (scaled Jacobian)\n\n"
     << "| Mesh | Elements | Min | Mean | Inverted | Below " << F(in.repairThreshold, 2)
     << " | Not valid inside |\n|---|---|---|---|---|---|---|\n"
     << "| before repair (Q∘R) | " << r.model.SolidElementCount() << " | " << F(r.repair.minScaledJacobianBefore)
     << " | " << F(r.repair.meanScaledJacobianBefore) << " | " << r.repair.invertedBefore << " | "
     << r.repair.belowThresholdBefore << " | " << r.repair.notCertifiedBefore << " |\n"
     << "| repaired model | " << r.model.SolidElementCount() << " | " << F(r.repair.minScaledJacobianAfter) << " | "
     << F(r.repair.meanScaledJacobianAfter) << " | " << r.repair.invertedAfter << " | " << r.repair.belowThresholdAfter
     << " | " << r.repair.notCertifiedAfter << " |\n\n"
     << "\"Not valid inside\": elements whose Jacobian determinant is not proved positive over the whole element "
        "(Bézier bounds), although the scaled Jacobian measures only the corners.\n\n"
     << "Repair " << (r.repair.success ? "succeeded" : "**did not reach the threshold**") << ": " << r.repair.movedNodes
     << " nodes moved, " << r.repair.movedSurfaceNodes << " of them on the skin or skull (kept on the surfaces).\n\n";

  md << "## Muscles\n\n"
     << r.muscles.muscles << " tracks, " << r.muscles.points
     << " points carried through Q∘R and embedded in the model's elements";
  if (r.muscles.outside > 0)
    md << " (" << r.muscles.outside << " just outside the repaired boundary, at most "
       << F(r.muscles.maxOutsideDistance) << " mm)";
  md << ".\n\n| Muscle | Insertion (LPS mm) | Moved from the atlas (mm) |\n|---|---|---|\n";
  for (const auto& ins : r.muscles.insertions)
    md << "| " << ins.muscle << " | " << F(ins.subject.x(), 1) << ", " << F(ins.subject.y(), 1) << ", "
       << F(ins.subject.z(), 1) << " | " << F((ins.subject - ins.atlas).norm(), 1) << " |\n";

  md << "\n## Subject\n\nThresholds (" << r.thresholds.source << "): skin " << F(r.thresholds.skin, 1) << ", bone "
     << F(r.thresholds.bone, 1) << ". Skin " << r.skin->GetNumberOfPoints() << " vertices, skull "
     << r.skull->GetNumberOfPoints() << " vertices. Mid-sagittal plane: point (" << F(r.plane.point.x(), 2) << ", "
     << F(r.plane.point.y(), 2) << ", " << F(r.plane.point.z(), 2) << "), normal (" << F(r.plane.normal.x(), 4) << ", "
     << F(r.plane.normal.y(), 4) << ", " << F(r.plane.normal.z(), 4) << "), RMS residual " << F(r.planeResidual, 2)
     << " mm.\n\n";

  md << "## Time (s)\n\n| Stage | Seconds |\n|---|---|\n";
  for (const auto& t : r.times)
    md << "| " << t.name << " | " << F(t.seconds, 2) << " |\n";
  md << "| **total** | " << F(r.totalSeconds, 2) << " |\n";
  if (!in.files.empty())
  {
    md << "\n## Files\n\n";
    for (const auto& [f, what] : in.files)
      md << "- `" << f << "`: " << what << "\n";
  }
  return md.str();
}

} // namespace mmrep
