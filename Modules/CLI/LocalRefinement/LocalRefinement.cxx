// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// LocalRefinement: finer elastic deformation Q over a node set's box (lips), boundary fixed.
#include "mmrepAtlasRegistration.h"
#include "mmrepCLI.h"
#include "mmrepFEMeshIO.h"
#include "mmrepPlane.h"
#include "mmrepSurfaceIO.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>
#include <memory>

extern const char LocalRefinementXML[];

namespace
{
using mmrep::cli::ModuleError;

nlohmann::json Stats(const mmrep::SurfaceDistance& s)
{
  return {{"count", s.count}, {"mean", s.mean}, {"max", s.max}, {"sigma", s.sigma}};
}

void Run(mmrep::cli::ModuleContext& ctx)
{
  const auto& args = ctx.args;
  const auto ext = mmrep::cli::FileExtension(args.String("outputMesh"));
  if (ext != ".vtu" && ext != ".vtk" && ext != ".inp" && ext != ".feb" && ext != ".msh")
    throw ModuleError(args.String("outputMesh") + ": unknown mesh format '" + ext +
                      "' (use .vtu, .vtk, .inp, .feb or .msh)");
  mmrep::cli::AtomicOutput meshOut(args.String("outputMesh"));
  std::unique_ptr<mmrep::cli::AtomicOutput> reportOut;
  bool markdown = false;
  if (args.Given("report"))
  {
    const auto reportExt = mmrep::cli::FileExtension(args.String("report"));
    if (reportExt != ".json" && reportExt != ".md")
      throw ModuleError(args.String("report") + ": unknown report format '" + reportExt + "' (use .json or .md)");
    markdown = reportExt == ".md";
    reportOut = std::make_unique<mmrep::cli::AtomicOutput>(args.String("report"));
  }

  ctx.progress.Start("Local refinement");
  const auto mesh = mmrep::ReadFEMesh(args.String("registeredMesh"));
  const auto skin = mmrep::ReadSurface(args.String("subjectSkin"));
  mmrep::LocalRefinementOptions options;
  options.regionSet = args.String("nodeSet");
  options.spacing = args.Double("spacing");
  options.elementQualityFloor = args.Double("elementQualityFloor");
  options.finestLevel = static_cast<int>(args.Int("levels"));
  if (args.Given("subjectPlane"))
  {
    options.plane = mmrep::PlaneFromSixNumbers(args.Doubles("subjectPlane"), "--subjectPlane");
    options.symmetric = true;
  }
  options.progress = [&](double f) { ctx.progress.ReportRange(0.05, 0.95, f); };
  const auto result = mmrep::RefineLocally(mesh, skin, options);

  mmrep::WriteFEMesh(result.mesh, meshOut.TempPath(), ext.substr(1));
  if (reportOut)
  {
    const nlohmann::json j = {{"regionSet", options.regionSet},
                              {"before", {{"region", Stats(result.before.lips)}, {"skin", Stats(result.before.skin)}}},
                              {"after", {{"region", Stats(result.after.lips)}, {"skin", Stats(result.after.skin)}}},
                              {"seconds", result.after.seconds},
                              {"stepsPerLevel", result.after.stepsPerLevel},
                              {"sweepsPerLevel", result.after.sweepsPerLevel}};
    reportOut->WriteText(markdown
                           ? result.Report().ToMarkdown("Local refinement (Q) of node set '" + options.regionSet + "'")
                           : j.dump(2) + "\n");
  }
  meshOut.Commit();
  if (reportOut)
    reportOut->Commit();
  std::cout << "Region '" << options.regionSet << "': mean " << result.before.lips.mean << " -> "
            << result.after.lips.mean << " mm, max " << result.before.lips.max << " -> " << result.after.lips.max
            << " mm; " << result.transform.StepCount() << " steps" << std::endl;
  ctx.outputs.Set("lipsMeanBefore", result.before.lips.mean);
  ctx.outputs.Set("lipsMaxBefore", result.before.lips.max);
  ctx.outputs.Set("lipsMeanAfter", result.after.lips.mean);
  ctx.outputs.Set("lipsMaxAfter", result.after.lips.max);
  ctx.outputs.Set("seconds", result.after.seconds);
  ctx.progress.End();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, LocalRefinementXML, Run);
}
