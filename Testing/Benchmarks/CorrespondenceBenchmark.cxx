// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// CorrespondenceBenchmark: does every atlas node land on the same anatomical point of the subject?
// One run, side by side for every registration mode (the similarity alone, half-face, averaged
// symmetric, full) on
//   self       the atlas onto its own CT (cthead, shipped control points): on the fitted left half
//              the answer is the identity, so every displacement is an error;
//   synthetic  SyntheticSubject warps F of cthead (seeds, rotations up to 12°, 6 bumps of 2.5 mm),
//              control points F(landmark) + 0.5 mm random error: node error |R(a) − F(a)|;
//   headsq     another real person: surface errors only; and its consistency: the model of F(headsq)
//              against F applied to the model of headsq (a registration should commute with F).
// Per mode: node errors (fitted half: all, skin, lips, skull, muscle points, insertions; mean / p95 /
// max), surface errors (skin, skull after R, lips after Q; fitted half and whole model), control
// points, min scaled Jacobian, muscle waviness, times. Subjects' surfaces, planes and maps are made
// once (as FaceModelPipeline makes them) and shared by the modes.
//
//   CorrespondenceBenchmark [--quick] [--modes half-face,averaged,full] [--synthetic N]
//                           [--sliding MU] [--slidingLevel L] [--levels N] [--holding MU] [--qHolding MU]
//                           [--qSliding MU] [--qCells N] [--only self|synthetic|headsq] [--rOnly]
#include "mmrepCorrespondenceMetrics.h"

#include "mmrepAtlasRegistration.h"
#include "mmrepFaceControlPoints.h"
#include "mmrepFEMeshIO.h"
#include "mmrepFaceModelPipeline.h"
#include "mmrepLandmarkIO.h"
#include "mmrepMeshQuality.h"
#include "mmrepSurfaceDistanceMap.h"
#include "mmrepSyntheticSubject.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
using mmrep::bench::Spread;
double Since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

const std::string kSample = MMREP_SAMPLE_DATA;
const std::string kAtlas = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu";

struct Mode
{
  std::string name;
  bool symmetric = true, halfFace = true;
};

struct Subject
{
  std::string name, kind; // kind: self, synthetic, headsq, headsq-warped
  mmrep::CTImage::Pointer ct;
  mmrep::SubjectData data;
  std::shared_ptr<mmrep::SyntheticWarp> warp; // truth F (synthetic), or the warp of headsq-warped
  double prepareSeconds = 0, mapSeconds = 0;
};

struct Run
{
  mmrep::FEMesh registered, refined;
  double seconds[2] = {0, 0}; // R, Q
  mmrep::ElasticTransform r, q;
};

// Landmarks of the atlas rules that are not control points (held out of the registration), in LPS.
std::vector<std::pair<std::string, Eigen::Vector3d>> HeldOutLandmarks(const mmrep::SubjectData& s)
{
  const auto found = mmrep::DetectFaceControlPoints(s.skin, s.skull, s.plane);
  const auto& l = found.landmarks;
  std::vector<std::pair<std::string, Eigen::Vector3d>> out = {{"pronasale", found.frame.ToWorld(l.pronasale.local)},
                                                              {"subnasale", found.frame.ToWorld(l.subnasale.local)},
                                                              {"stomion", found.frame.ToWorld(l.stomion.local)},
                                                              {"nasion", found.frame.ToWorld(l.nasion.local)}};
  return out;
}

// Surfaces, plane and maps exactly as FaceModelPipeline makes them.
void Prepare(Subject& s, const mmrep::FaceModelOptions& options)
{
  const auto t = Clock::now();
  const auto surfaces = mmrep::ExtractSubjectSurfaces(s.ct, options);
  s.data.skin = surfaces.skin;
  s.data.skull = surfaces.skull;
  s.data.plane = mmrep::EstimateSubjectPlane(surfaces.skin, options).plane;
  s.prepareSeconds = Since(t);
  const auto tm = Clock::now();
  mmrep::SurfaceDistanceMapOptions mo;
  mo.spacing = options.registration.mapSpacing;
  mo.margin = options.registration.mapMargin;
  mo.signedDistance = options.registration.signedMaps;
  s.data.skinMap = mmrep::ComputeSurfaceDistanceMap(s.data.skin, mo);
  s.data.skullMap = mmrep::ComputeSurfaceDistanceMap(s.data.skull, mo);
  s.mapSeconds = Since(tm);
}

Run Register(const Subject& s, const mmrep::FEMesh& atlas, const mmrep::Plane& atlasPlane,
             mmrep::FaceModelOptions options, const Mode& mode)
{
  options.registration.symmetric = mode.symmetric;
  options.registration.halfFace = mode.halfFace;
  Run run;
  auto t = Clock::now();
  auto r = mmrep::RegisterAtlas(atlas, atlasPlane, s.data, options.registration);
  run.seconds[0] = Since(t);
  t = Clock::now();
  auto q = mmrep::RefineLocally(r.mesh, s.data.skin, mmrep::RefinementOptionsFor(options, s.data.plane));
  run.seconds[1] = Since(t);
  run.registered = std::move(r.mesh);
  run.refined = std::move(q.mesh);
  run.r = std::move(r.transform);
  run.q = std::move(q.transform);
  return run;
}

std::string Cells(const Spread& s)
{
  char b[64];
  std::snprintf(b, sizeof(b), "%.2f / %.2f / %.2f", s.mean, s.p95, s.max);
  return b;
}

std::string Num(double v, int digits = 3)
{
  char b[32];
  std::snprintf(b, sizeof(b), "%.*f", digits, v);
  return b;
}

struct Row
{
  std::string mode;
  std::map<std::string, std::string> cells;
  std::map<std::string, double> values; // for the target checks
};

void PrintTable(const std::string& title, const std::vector<std::string>& columns, const std::vector<Row>& rows)
{
  std::printf("\n### %s\n\n| mode |", title.c_str());
  for (const auto& c : columns)
    std::printf(" %s |", c.c_str());
  std::printf("\n|---|");
  for (std::size_t i = 0; i < columns.size(); ++i)
    std::printf("---|");
  std::printf("\n");
  for (const auto& r : rows)
  {
    std::printf("| %s |", r.mode.c_str());
    for (const auto& c : columns)
    {
      const auto it = r.cells.find(c);
      std::printf(" %s |", it == r.cells.end() ? "—" : it->second.c_str());
    }
    std::printf("\n");
  }
}

} // namespace

int main(int argc, char* argv[])
{
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  vtkSMPTools::SetBackend("Sequential"); // the plane's ICP gives the same bytes on every run
  bool quick = false, registrationOnly = false;
  std::string only; // run only the subjects of this kind (self, synthetic, headsq)
  int syntheticCount = 6;
  std::vector<Mode> modes = {{"half-face", true, true}, {"averaged", true, false}, {"full", false, false}};
  mmrep::FaceModelOptions options;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc)
        throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--quick")
      quick = true;
    else if (a == "--rOnly")
      registrationOnly = true; // also a row per mode for R alone (before Q)
    else if (a == "--only")
      only = next();
    else if (a == "--synthetic")
      syntheticCount = std::stoi(next());
    else if (a == "--sliding")
      options.registration.slidingWeight = std::stod(next());
    else if (a == "--holding")
      options.registration.holdingWeight = std::stod(next());
    else if (a == "--qCells")
      options.refinement.minimumCellVoxels = std::stod(next());
    else if (a == "--qSliding")
      options.refinement.slidingWeight = std::stod(next());
    else if (a == "--qHolding")
      options.refinement.holdingWeight = std::stod(next());
    else if (a == "--slidingLevel")
      options.registration.regularizationFirstLevel = std::stoi(next());
    else if (a == "--levels")
      options.registration.finestLevel = std::stoi(next());
    else if (a == "--modes")
    {
      std::vector<Mode> chosen;
      std::stringstream list(next());
      for (std::string m; std::getline(list, m, ',');)
        for (const auto& x : modes)
          if (x.name == m)
            chosen.push_back(x);
      modes = chosen;
    }
    else
    {
      std::fprintf(
        stderr,
        "usage: CorrespondenceBenchmark [--quick] [--modes half-face,averaged,full] [--synthetic N] "
        "[--sliding MU] [--slidingLevel L] [--levels N] [--holding MU] [--qHolding MU] [--qSliding MU] [--qCells N] "
        "[--only KIND] [--rOnly]\n");
      return 2;
    }
  }
  if (quick)
    syntheticCount = std::min(syntheticCount, 2);
  try
  {
    const auto atlas = mmrep::ReadFEMesh(kAtlas);
    const auto atlasPlane = mmrep::FitPlaneToNodeSet(atlas, "midsagittal");
    const mmrep::bench::AtlasGroups groups(atlas, atlasPlane);
    std::printf("atlas: %zu nodes; fitted (left) half %zu nodes: skin %zu, lips %zu, skull %zu, muscle points %zu, "
                "insertions %zu\n",
                atlas.nodes.size(), groups.Size("all"), groups.Size("skin"), groups.Size("lips"), groups.Size("skull"),
                groups.Size("muscle"), groups.Size("insertions"));
    std::printf("options: sliding %.3g from level %d, finest level %d (0 = auto), map %.2f mm\n",
                options.registration.slidingWeight, options.registration.regularizationFirstLevel,
                options.registration.finestLevel, options.registration.mapSpacing);

    // Subjects.
    std::vector<Subject> subjects;
    const auto cthead = mmrep::ReadCTImage(kSample + "/cthead.nrrd");
    {
      Subject s;
      s.name = "self (cthead)";
      s.kind = "self";
      s.ct = cthead;
      s.data.controlPoints = mmrep::ReadLandmarks(kSample + "/cthead.ControlPoints.mrk.json");
      subjects.push_back(s);
    }
    struct Case
    {
      std::uint32_t seed;
      double roll, pitch, yaw;
    };
    const std::vector<Case> cases = {{11, 8, -6, 10}, {23, -12, 5, -9}, {5, 4, 10, -6},
                                     {7, -6, -8, 12}, {13, 10, 3, 4},   {17, -3, -12, -5}};
    std::mt19937 noise(2026);
    std::normal_distribution<double> gauss(0.0, 1.0);
    auto perturbed = [&](const Eigen::Vector3d& p) {
      Eigen::Vector3d d(gauss(noise), gauss(noise), gauss(noise));
      return Eigen::Vector3d(p + 0.5 * d.normalized());
    };
    for (int k = 0; k < syntheticCount && k < static_cast<int>(cases.size()); ++k)
    {
      const auto& c = cases[static_cast<std::size_t>(k)];
      mmrep::SyntheticWarpParameters p;
      p.seed = c.seed;
      p.rollDegrees = c.roll;
      p.pitchDegrees = c.pitch;
      p.yawDegrees = c.yaw;
      mmrep::FitWarpToImage(p, cthead);
      Subject s;
      char name[96];
      std::snprintf(name, sizeof(name), "synthetic seed %u (roll %.0f, pitch %.0f, yaw %.0f deg)", c.seed, c.roll,
                    c.pitch, c.yaw);
      s.name = name;
      s.kind = "synthetic";
      s.warp = std::make_shared<mmrep::SyntheticWarp>(p);
      s.ct = mmrep::ResampleSyntheticSubject(cthead, *s.warp);
      for (const auto& l : atlas.landmarks)
        s.data.controlPoints.push_back({l.name, perturbed(s.warp->Forward(l.position))});
      subjects.push_back(s);
    }
    if (!quick)
    {
      const auto headsq = mmrep::ReadCTImage(kSample + "/headsq.nrrd");
      Subject h;
      h.name = "headsq (another person)";
      h.kind = "headsq";
      h.ct = headsq;
      h.data.controlPoints = mmrep::ReadLandmarks(kSample + "/headsq.ControlPoints.mrk.json");
      subjects.push_back(h);
      mmrep::SyntheticWarpParameters p;
      p.seed = 31;
      p.rollDegrees = 6;
      p.pitchDegrees = -4;
      p.yawDegrees = 8;
      mmrep::FitWarpToImage(p, headsq);
      Subject w;
      w.name = "F(headsq), seed 31";
      w.kind = "headsq-warped";
      w.warp = std::make_shared<mmrep::SyntheticWarp>(p);
      w.ct = mmrep::ResampleSyntheticSubject(headsq, *w.warp);
      for (const auto& l : h.data.controlPoints)
        w.data.controlPoints.push_back({l.name, w.warp->Forward(l.position)});
      subjects.push_back(w);
    }

    std::map<std::string, std::vector<Row>> summary;                   // subject -> rows
    std::vector<std::pair<std::string, Eigen::Vector3d>> atlasHeldOut; // on the atlas's own CT
    std::vector<Row> heldOutRows;                                      // headsq
    {
      // The atlas's CT with the atlas's plane, as BuildFaceAtlas sees them: the rules find there the
      // atlas's own landmarks.
      const auto surfaces = mmrep::ExtractSubjectSurfaces(mmrep::ReadCTImage(kSample + "/cthead.nrrd"), options);
      mmrep::SubjectData onAtlas;
      onAtlas.skin = surfaces.skin;
      onAtlas.skull = surfaces.skull;
      onAtlas.plane = atlasPlane;
      atlasHeldOut = HeldOutLandmarks(onAtlas);
    }
    std::map<std::string, std::map<std::string, mmrep::FEMesh>> headsqModels; // mode -> kind -> model
    if (!only.empty())
      subjects.erase(
        std::remove_if(subjects.begin(), subjects.end(), [&](const Subject& s) { return s.kind.rfind(only, 0) != 0; }),
        subjects.end());
    for (auto& s : subjects)
    {
      Prepare(s, options);
      std::printf("\n== %s: surfaces + plane %.1f s, maps %.1f s; plane normal (%.4f, %.4f, %.4f)\n", s.name.c_str(),
                  s.prepareSeconds, s.mapSeconds, s.data.plane.normal.x(), s.data.plane.normal.y(),
                  s.data.plane.normal.z());
      std::vector<std::pair<std::string, Eigen::Vector3d>> subjectHeldOut;
      if (s.kind == "headsq" && !atlasHeldOut.empty())
        subjectHeldOut = HeldOutLandmarks(s.data);
      if (s.kind == "self")
        std::printf("   atlas plane vs subject plane: %.4f deg, %.4f mm at the control points\n",
                    mmrep::bench::PlaneAngleDegrees(atlasPlane, s.data.plane),
                    mmrep::bench::PlaneOffset(atlasPlane, s.data.plane, s.data.controlPoints));
      std::function<Eigen::Vector3d(std::size_t)> truth;
      if (s.kind == "self")
        truth = [&](std::size_t i) { return atlas.nodes[i]; };
      else if (s.kind == "synthetic")
        truth = [&](std::size_t i) { return s.warp->Forward(atlas.nodes[i]); };
      std::vector<Row> rows;
      bool similarityDone = false;
      for (const auto& mode : modes)
      {
        const auto run = Register(s, atlas, atlasPlane, options, mode);
        if (s.kind == "headsq" || s.kind == "headsq-warped")
          headsqModels[mode.name][s.kind] = run.refined;
        auto measure = [&](const std::string& label, const mmrep::FEMesh& mesh, const mmrep::FEMesh* registeredOnly,
                           const double* seconds) {
          Row row;
          row.mode = label;
          if (truth)
            for (const char* g : {"all", "skin", "lips", "skull", "muscle", "insertions"})
            {
              const Spread e = groups.NodeError(mesh, g, truth);
              row.cells[std::string(g) + " (mean / p95 / max)"] = Cells(e);
              row.values[std::string("node ") + g] = e.mean;
              row.values[std::string("node max ") + g] = e.max;
            }
          const auto& surfaceMesh = registeredOnly ? *registeredOnly : mesh;
          const auto skinHalf = groups.SurfaceError(surfaceMesh, "skin", s.data.skin, true);
          const auto skinAll = groups.SurfaceError(surfaceMesh, "skin", s.data.skin, false);
          const auto skullHalf = groups.SurfaceError(surfaceMesh, "skull", s.data.skull, true);
          const auto skullAll = groups.SurfaceError(surfaceMesh, "skull", s.data.skull, false);
          const auto lipsHalf = groups.SurfaceError(mesh, "lips", s.data.skin, true);
          const auto lipsAll = groups.SurfaceError(mesh, "lips", s.data.skin, false);
          row.cells["skin half / whole"] = Num(skinHalf.mean) + " / " + Num(skinAll.mean);
          row.cells["skull half / whole"] = Num(skullHalf.mean) + " / " + Num(skullAll.mean);
          row.cells["lips Q half (mean / max) / whole"] =
            Num(lipsHalf.mean) + " / " + Num(lipsHalf.max, 2) + " / " + Num(lipsAll.mean);
          row.values["skin"] =
            mode.halfFace || !mode.symmetric ? (mode.symmetric ? skinHalf.mean : skinAll.mean) : skinHalf.mean;
          row.values["skull"] = mode.symmetric ? skullHalf.mean : skullAll.mean;
          row.values["lips"] = mode.symmetric ? lipsHalf.mean : lipsAll.mean;
          row.values["lips max"] = mode.symmetric ? lipsHalf.max : lipsAll.max;
          const auto cp = groups.ControlPointError(mesh, s.data.controlPoints);
          row.cells["control points (mean / max)"] = Num(cp.first, 2) + " / " + Num(cp.second, 2);
          row.values["cp mean"] = cp.first;
          row.values["cp max"] = cp.second;
          row.cells["min SJ"] = Num(mmrep::quality::SummarizeScaledJacobian(mesh, 0.3).min);
          const Spread wavy = groups.Waviness(mesh);
          row.cells["waviness (mean / max)"] = Num(wavy.mean, 2) + " / " + Num(wavy.max, 2);
          row.values["waviness max"] = wavy.max;
          if (seconds)
          {
            row.cells["time R / Q (s)"] = Num(seconds[0], 1) + " / " + Num(seconds[1], 1);
            row.values["seconds"] = seconds[0] + seconds[1];
          }
          rows.push_back(row);
        };
        if (!similarityDone)
        {
          mmrep::FEMesh sim = atlas;
          for (auto& n : sim.nodes)
            n = run.r.PreApply(n);
          for (auto& l : sim.landmarks)
            l.position = run.r.PreApply(l.position);
          measure("similarity (" + mode.name + ")", sim, nullptr, nullptr);
          similarityDone = true;
        }
        if (registrationOnly)
          measure(mode.name + " (R only)", run.registered, &run.registered, run.seconds);
        measure(mode.name, run.refined, &run.registered, run.seconds);
        if (!subjectHeldOut.empty())
        {
          for (int similarityOnly = 1; similarityOnly >= 0; --similarityOnly)
          {
            if (similarityOnly && !heldOutRows.empty())
              continue;
            Row row;
            row.mode = similarityOnly ? "similarity" : mode.name;
            double sum = 0;
            for (std::size_t k = 0; k < subjectHeldOut.size(); ++k)
            {
              const Eigen::Vector3d& a = atlasHeldOut[k].second;
              const Eigen::Vector3d p = similarityOnly ? run.r.PreApply(a) : run.q.Apply(run.r.Apply(a));
              const double e = (p - subjectHeldOut[k].second).norm();
              row.cells[subjectHeldOut[k].first] = Num(e, 2);
              sum += e;
            }
            row.cells["mean"] = Num(sum / static_cast<double>(subjectHeldOut.size()), 2);
            heldOutRows.push_back(row);
          }
        }
      }
      std::vector<std::string> columns;
      if (truth)
        for (const char* g : {"all", "skin", "lips", "skull", "muscle", "insertions"})
          columns.push_back(std::string(g) + " (mean / p95 / max)");
      for (const char* c : {"skin half / whole", "skull half / whole", "lips Q half (mean / max) / whole",
                            "control points (mean / max)", "min SJ", "waviness (mean / max)", "time R / Q (s)"})
        columns.push_back(c);
      PrintTable(s.name +
                   (truth ? ": node error vs truth on the fitted half, surface errors (mm)" : ": surface errors (mm)"),
                 columns, rows);
      summary[s.name] = rows;
    }

    // Consistency: model of F(headsq) vs F(model of headsq), fitted half.
    if (!quick && headsqModels.size() == modes.size() && !headsqModels.empty() &&
        headsqModels.begin()->second.size() == 2)
    {
      const Subject* warped = nullptr;
      for (const auto& s : subjects)
        if (s.kind == "headsq-warped")
          warped = &s;
      std::vector<Row> rows;
      for (const auto& mode : modes)
      {
        const auto& m = headsqModels[mode.name];
        const auto& plain = m.at("headsq");
        const auto& onWarped = m.at("headsq-warped");
        Row row;
        row.mode = mode.name;
        for (const char* g : {"all", "skin", "lips", "skull", "muscle"})
          row.cells[std::string(g) + " (mean / p95 / max)"] =
            Cells(groups.NodeError(onWarped, g, [&](std::size_t i) { return warped->warp->Forward(plain.nodes[i]); }));
        rows.push_back(row);
      }
      PrintTable("consistency on headsq: |model(F(headsq)) − F(model(headsq))| on the fitted half (mm)",
                 {"all (mean / p95 / max)", "skin (mean / p95 / max)", "lips (mean / p95 / max)",
                  "skull (mean / p95 / max)", "muscle (mean / p95 / max)"},
                 rows);
    }

    if (!heldOutRows.empty())
      PrintTable("headsq: held-out landmarks of the atlas rules (not control points), |Q∘R(atlas landmark) − "
                 "headsq landmark| (mm)",
                 {"pronasale", "subnasale", "stomion", "nasion", "mean"}, heldOutRows);

    // Targets (issue 13), per subject, for the first mode given (the default: half-face).
    std::printf("\n### Targets, mode %s\n\n", modes.front().name.c_str());
    for (const auto& s : subjects)
    {
      const auto& rows = summary[s.name];
      const Row& sim = rows.front();
      const Row& reg = rows[1];
      auto v = [&](const Row& r, const char* k) {
        const auto it = r.values.find(k);
        return it == r.values.end() ? std::nan("") : it->second;
      };
      auto verdict = [](bool ok) { return ok ? "met" : "MISSED"; };
      std::printf("- %s:", s.name.c_str());
      if (s.kind == "self")
        std::printf(" skin slide %.3f (<= 0.3 %s) max %.2f (<= 1.5 %s); lips %.3f (<= 0.2 %s) max %.2f (<= 1.0 %s);",
                    v(reg, "node skin"), verdict(v(reg, "node skin") <= 0.3), v(reg, "node max skin"),
                    verdict(v(reg, "node max skin") <= 1.5), v(reg, "node lips"), verdict(v(reg, "node lips") <= 0.2),
                    v(reg, "node max lips"), verdict(v(reg, "node max lips") <= 1.0));
      if (s.kind == "synthetic")
        std::printf(" node error %.3f vs similarity %.3f (<= 1.0 and <= 0.5x %s); muscle %.3f, insertions %.3f "
                    "(<= 1.0 %s); lips nodes %.3f (<= 0.7 %s);",
                    v(reg, "node all"), v(sim, "node all"),
                    verdict(v(reg, "node all") <= 1.0 && v(reg, "node all") <= 0.5 * v(sim, "node all")),
                    v(reg, "node muscle"), v(reg, "node insertions"),
                    verdict(v(reg, "node muscle") <= 1.0 && v(reg, "node insertions") <= 1.0), v(reg, "node lips"),
                    verdict(v(reg, "node lips") <= 0.7));
      std::printf(" skin %.3f (<= 0.15 %s), skull %.3f (<= 0.25 %s), lips after Q %.3f / %.2f (<= 0.05 / 0.3 %s), "
                  "control points %.2f / %.2f (<= 0.5 / 1.0 %s), waviness max %.2f (<= 0.5 %s), R+Q %.1f s (<= 3 %s)\n",
                  v(reg, "skin"), verdict(v(reg, "skin") <= 0.15), v(reg, "skull"), verdict(v(reg, "skull") <= 0.25),
                  v(reg, "lips"), v(reg, "lips max"), verdict(v(reg, "lips") <= 0.05 && v(reg, "lips max") <= 0.3),
                  v(reg, "cp mean"), v(reg, "cp max"), verdict(v(reg, "cp mean") <= 0.5 && v(reg, "cp max") <= 1.0),
                  v(reg, "waviness max"), verdict(v(reg, "waviness max") <= 0.5), v(reg, "seconds"),
                  verdict(v(reg, "seconds") <= 3.0));
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
