// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// MuscleInference: atlas muscle tracks -> speaker model through an atlas-to-speaker displacement
// field (Libs/MMRepPipeline/mmrepMuscleInference.h).
#include "mmrepCLI.h"
#include "mmrepDisplacementFieldMap.h"
#include "mmrepFEMeshIO.h"
#include "mmrepImageIO.h"
#include "mmrepMuscleInference.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>

extern const char MuscleInferenceXML[];

namespace
{
using mmrep::cli::ModuleError;

void Run(mmrep::cli::ModuleContext& ctx)
{
  const auto& args = ctx.args;
  const std::string output = args.String("outputMesh");
  const auto writable = mmrep::WritableFEMeshExtensions();
  if (std::find(writable.begin(), writable.end(), mmrep::cli::FileExtension(output)) == writable.end())
    throw ModuleError(output + ": unknown mesh format '" + mmrep::cli::FileExtension(output) +
                      "' (use .vtu, .vtk, .inp, .feb or .msh)");
  mmrep::cli::AtomicOutput meshOut(output);
  std::unique_ptr<mmrep::cli::AtomicOutput> reportOut;
  if (args.Given("report"))
    reportOut = std::make_unique<mmrep::cli::AtomicOutput>(args.String("report"));

  ctx.progress.Start("Muscle inference");
  const auto atlas = mmrep::ReadFEMesh(args.String("atlasMesh"));
  auto subject = mmrep::ReadFEMesh(args.String("subjectMesh"));
  const auto field = mmrep::ReadDisplacementField(args.String("transform"));
  ctx.progress.Report(0.3);
  mmrep::MuscleInferenceReport report;
  try
  {
    report = mmrep::InferMuscles(atlas, mmrep::DisplacementFieldMap(field), subject);
  }
  catch (const std::out_of_range& e)
  {
    throw ModuleError(args.String("transform") + ": the field does not cover the atlas muscles (" + e.what() + ")");
  }
  ctx.progress.Report(0.8);
  mmrep::WriteFEMesh(subject, meshOut.TempPath(), mmrep::cli::FileExtension(output).substr(1));
  if (reportOut)
  {
    nlohmann::json insertions = nlohmann::json::object();
    for (const auto& i : report.insertions)
      insertions[i.muscle] = {{"atlas", {i.atlas.x(), i.atlas.y(), i.atlas.z()}},
                              {"subject", {i.subject.x(), i.subject.y(), i.subject.z()}}};
    const nlohmann::json j = {{"muscles", report.muscles},
                              {"points", report.points},
                              {"pointsOutsideElements", report.outside},
                              {"maxOutsideDistance", report.maxOutsideDistance},
                              {"pointsInAnotherElement", report.changedElement},
                              {"insertions", insertions},
                              {"units", "LPS mm"}};
    reportOut->WriteText(j.dump(2) + "\n");
  }
  meshOut.Commit();
  if (reportOut)
    reportOut->Commit();
  std::cout << report.muscles << " muscle tracks, " << report.points << " points carried; " << report.outside
            << " outside the speaker's elements (max " << report.maxOutsideDistance << " mm)" << std::endl;
  ctx.outputs.Set("muscles", static_cast<long long>(report.muscles));
  ctx.outputs.Set("points", static_cast<long long>(report.points));
  ctx.outputs.Set("pointsOutside", static_cast<long long>(report.outside));
  ctx.outputs.Set("maxOutsideDistance", report.maxOutsideDistance);
  ctx.progress.End();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, MuscleInferenceXML, Run);
}
