// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// AtlasRegistration: face atlas FE mesh -> subject (skin, skull, control points), symmetric
// elastic registration R (Libs/MMRepElasticRegistration).
#include "mmrepAtlasRegistration.h"
#include "mmrepCLI.h"
#include "mmrepImageIO.h"
#include "mmrepFEMeshIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepPlane.h"
#include "mmrepRegistrationGrids.h"
#include "mmrepResourceBudget.h"
#include "mmrepSurfaceIO.h"
#include "mmrepSymmetryPlane.h"

#include <fstream>
#include <iostream>
#include <memory>

extern const char AtlasRegistrationXML[];

namespace
{
using mmrep::cli::ModuleError;

void CheckExtension(const std::string& path, std::initializer_list<const char*> allowed, const std::string& what)
{
  const auto ext = mmrep::cli::FileExtension(path);
  for (const char* a : allowed)
    if (ext == a)
      return;
  std::string list;
  for (const char* a : allowed)
    list += std::string(list.empty() ? "" : ", ") + a;
  throw ModuleError(path + ": unknown " + what + " format '" + ext + "' (use " + list + ")");
}

void Run(mmrep::cli::ModuleContext& ctx)
{
  const auto& args = ctx.args;
  CheckExtension(args.String("outputMesh"), {".vtu", ".vtk", ".inp", ".feb", ".msh"}, "mesh");
  std::vector<std::unique_ptr<mmrep::cli::AtomicOutput>> outputs;
  outputs.push_back(std::make_unique<mmrep::cli::AtomicOutput>(args.String("outputMesh")));
  mmrep::cli::AtomicOutput* fieldOut = nullptr;
  mmrep::cli::AtomicOutput* reportOut = nullptr;
  if (args.Given("outputTransform"))
  {
    CheckExtension(args.String("outputTransform"), {".nrrd", ".nhdr", ".mha", ".mhd"}, "displacement field");
    outputs.push_back(std::make_unique<mmrep::cli::AtomicOutput>(args.String("outputTransform")));
    fieldOut = outputs.back().get();
  }
  if (args.Given("report"))
  {
    CheckExtension(args.String("report"), {".json", ".md"}, "report");
    outputs.push_back(std::make_unique<mmrep::cli::AtomicOutput>(args.String("report")));
    reportOut = outputs.back().get();
  }

  ctx.progress.Start("Atlas registration");
  // Library errors (bad files, sets, names) become one-line module errors.
  const auto atlas = mmrep::ReadFEMesh(args.String("atlasMesh"));
  // The transform's grid covers the atlas (where the field is defined) with a 10 mm margin; one
  // too large for memory is refused before the registration.
  const auto grid = mmrep::TransformGridAround(atlas.nodes, 10.0, args.Double("transformSpacing"));
  if (fieldOut)
    mmrep::CheckMemoryNeed("--transformSpacing " + args.String("transformSpacing") + ": the transform would be",
                           grid.counts, 3 * sizeof(float));
  mmrep::SubjectData subject;
  subject.skin = mmrep::ReadSurface(args.String("subjectSkin"));
  subject.skull = mmrep::ReadSurface(args.String("subjectSkull"));
  subject.controlPoints = mmrep::ReadLandmarks(args.String("subjectControlPoints"));
  // The maps of R, sized before the work.
  mmrep::CheckSubjectMapGrids(subject, mmrep::AtlasRegistrationOptions{}.mapMargin, args.Double("mapSpacing"),
                              "--mapSpacing");

  const mmrep::Plane atlasPlane = args.Given("atlasPlane")
                                    ? mmrep::PlaneFromSixNumbers(args.Doubles("atlasPlane"), "--atlasPlane")
                                    : mmrep::FitPlaneToNodeSet(atlas, "midsagittal");
  if (args.Given("subjectPlane"))
    subject.plane = mmrep::PlaneFromSixNumbers(args.Doubles("subjectPlane"), "--subjectPlane");
  else
  {
    if (subject.skin->GetNumberOfPolys() == 0)
      throw ModuleError(args.String("subjectSkin") + ": the skin surface has no triangles");
    subject.plane = mmrep::EstimateSymmetryPlane(subject.skin).plane;
    std::cout << "Subject plane (estimated): point " << subject.plane.point.transpose() << ", normal "
              << subject.plane.normal.transpose() << std::endl;
  }
  ctx.progress.Report(0.05);

  mmrep::AtlasRegistrationOptions options;
  options.finestLevel = static_cast<int>(args.Int("levels"));
  options.mapSpacing = args.Double("mapSpacing");
  options.controlPointWeight = args.Double("controlPointWeight");
  options.elementQualityFloor = args.Double("elementQualityFloor");
  options.tieWeight = args.Double("tieWeight");
  mmrep::SetSymmetryMode(options, args.String("symmetry"));
  options.progress = [&](double f) { ctx.progress.ReportRange(0.05, 0.9, f); };
  const auto result = mmrep::RegisterAtlas(atlas, atlasPlane, subject, options);

  mmrep::WriteFEMesh(result.mesh, outputs[0]->TempPath(), mmrep::cli::FileExtension(outputs[0]->FinalPath()).substr(1));
  if (fieldOut)
    mmrep::WriteDisplacementField(result.transform.ToDisplacementField(grid.Image()), fieldOut->TempPath());
  if (reportOut)
  {
    reportOut->WriteText(mmrep::cli::FileExtension(reportOut->FinalPath()) == ".md"
                           ? result.report.ToMarkdown("Atlas registration (R)")
                           : result.report.ToJson() + "\n");
  }
  for (auto& o : outputs)
    o->Commit();

  const auto& r = result.report.Last();
  std::cout << "Skin error " << r.skin.mean << " mm mean, " << r.skin.max << " mm max; skull " << r.skull.mean << " / "
            << r.skull.max << " mm; control points " << r.controlMean << " / " << r.controlMax << " mm; "
            << result.transform.StepCount() << " steps" << std::endl;
  ctx.outputs.Set("skinMeanError", r.skin.mean);
  ctx.outputs.Set("skinMaxError", r.skin.max);
  ctx.outputs.Set("skullMeanError", r.skull.mean);
  ctx.outputs.Set("skullMaxError", r.skull.max);
  ctx.outputs.Set("controlPointMeanError", r.controlMean);
  ctx.outputs.Set("controlPointMaxError", r.controlMax);
  ctx.outputs.Set("seconds", r.seconds);
  ctx.progress.End();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, AtlasRegistrationXML, Run);
}
