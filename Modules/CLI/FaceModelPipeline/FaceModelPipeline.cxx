// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// FaceModelPipeline: speaker CT + five control points -> FE face model with muscles, exports for
// VTK, CalculiX/Abaqus, FEBio and Gmsh, the transform, a report and QC pictures, in one directory
// that appears only when complete (Libs/MMRepPipeline).
#include "FaceModelOutputDirectory.h"
#include "mmrepCLI.h"
#include "mmrepDisplacementFieldMap.h"
#include "mmrepFaceModelOutputs.h"
#include "mmrepFaceModelPipeline.h"
#include "mmrepFEMeshIO.h"
#include "mmrepImageIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepSnapshot.h"

#include <iostream>

extern const char FaceModelPipelineXML[];

namespace
{
using mmrep::cli::ModuleError;

void Run(mmrep::cli::ModuleContext& ctx)
{
  const auto& args = ctx.args;
  if (!args.Given("outputDirectory") || args.String("outputDirectory").empty())
    throw ModuleError("--outputDirectory is required (where the model, report and pictures go)");
  const bool pictures = !args.Bool("noPictures");
  if (pictures)
    mmrep::RequireDisplay(args.String("outputDirectory") + "/*.png (or pass --noPictures)");
  const double qualityThreshold = args.Double("qualityThreshold");
  if (args.Bool("halfModel") && args.String("symmetry") == "full")
    throw ModuleError("--halfModel needs a symmetric model: use --symmetry half-face (the default) or averaged");

  // The directory is staged first: an unwritable place fails before any work.
  FaceModelOutputDirectory out(args.String("outputDirectory"));

  ctx.progress.Start("Face model pipeline");
  const std::string atlasPath =
    args.Given("atlas") ? args.String("atlas") : mmrep::cli::ModuleResourcePath(MMREP_DEFAULT_ATLAS);
  const auto atlas = mmrep::ReadFEMesh(atlasPath);
  const auto controlPoints = mmrep::ReadLandmarks(args.String("controlPoints"));
  const auto ct = mmrep::ReadCTImage(args.String("inputVolume"));
  mmrep::CheckDisplacementFieldSize(atlas.nodes, 10.0, args.Double("transformSpacing"), "--transformSpacing");
  ctx.progress.Report(0.05);

  mmrep::FaceModelOptions options;
  options.thresholdMode = mmrep::ThresholdModeFromName(args.String("thresholdMode"));
  if (args.Given("skinThreshold"))
    options.skinThreshold = args.Double("skinThreshold");
  if (args.Given("boneThreshold"))
    options.boneThreshold = args.Double("boneThreshold");
  options.registration.finestLevel = static_cast<int>(args.Int("levels"));
  options.registration.mapSpacing = args.Double("mapSpacing");
  options.registration.controlPointWeight = args.Double("controlPointWeight");
  options.registration.elementQualityFloor = args.Double("elementQualityFloor");
  options.registration.tieWeight = args.Double("tieWeight");
  mmrep::SetSymmetryMode(options.registration, args.String("symmetry"));
  options.refine = !args.Bool("noRefinement");
  options.refinement.spacing = args.Double("lipsSpacing");
  options.repairThreshold = qualityThreshold;
  options.allowPartialFieldOfView = args.Bool("allowPartialFieldOfView");
  options.trustControlPoints = args.Bool("trustControlPoints");
  options.reorientToFace = args.Bool("reorientToFace");
  std::string lastStage;
  options.progress = [&](const std::string& stage, double f) {
    if (stage != lastStage)
    {
      std::cout << "Stage: " << stage << std::endl;
      ctx.progress.Stage(stage);
      lastStage = stage;
    }
    ctx.progress.ReportRange(0.05, 0.85, f);
  };
  const auto result = mmrep::BuildFaceModel(ct, controlPoints, atlas, options);
  if (!result.fieldOfViewMissing.empty() || !result.notImaged.empty())
  {
    std::string what;
    if (!result.fieldOfViewMissing.empty())
      what = "the CT misses the " + result.fieldOfViewMissing + " of the face region";
    if (!result.notImaged.empty())
      what += (what.empty() ? "" : "; ") + result.notImaged + " (" + std::to_string(result.notImagedNodes) +
              " skin nodes in node set notImaged)";
    std::cerr << ctx.moduleName << ": warning: partial model: " << what
              << "; there the model is not fitted to the speaker (report.md)" << std::endl;
  }
  if (result.reorientation.applied)
    std::cerr << ctx.moduleName << ": warning: " << mmrep::ReorientationInWords(result.reorientation) << std::endl;
  const bool acceptPoorFit = args.Bool("acceptPoorFit");
  if (!result.poorFit.empty() && acceptPoorFit)
    std::cerr << ctx.moduleName << ": warning: poor fit accepted: " << result.poorFit << " (report.md)" << std::endl;

  std::cout << "Scaled Jacobian after Q∘R: min " << result.qualityAfterQ.min << ", " << result.qualityAfterQ.inverted
            << " inverted, " << result.qualityAfterQ.belowThreshold << " below " << qualityThreshold
            << "; repaired: min " << result.repair.minScaledJacobianAfter << " in " << result.repair.seconds << " s"
            << std::endl;
  mmrep::FaceModelOutputOptions output;
  output.pictures = pictures;
  output.halfModel = args.Bool("halfModel");
  output.intermediates = args.Bool("intermediates");
  output.transformSpacing = args.Double("transformSpacing");
  output.report.ct = args.String("inputVolume");
  output.report.controlPoints = args.String("controlPoints");
  output.report.atlas = atlasPath;
  output.report.repairThreshold = qualityThreshold;
  mmrep::WriteFaceModelOutputs(result, atlas, output, out.StagingPath(),
                               [&](double f) { ctx.progress.ReportRange(0.85, 0.95, f); });
  out.Commit();
  // A model below the quality threshold fails the run and publishes nothing (an earlier result stays as it was).
  if (!result.repair.success)
    throw ModuleError(mmrep::RepairFailureMessage(result, qualityThreshold, out.FinalPath()));
  // So does a model whose own report shows it does not fit the speaker, unless the user accepts it.
  if (!result.poorFit.empty() && !acceptPoorFit)
    throw ModuleError("poor fit: " + result.poorFit + "; nothing written to " + out.FinalPath().string() +
                      " (check the control points and the CT, or --acceptPoorFit to keep the model)");

  const auto& a = result.accuracy.back();
  std::cout << mmrep::FaceModelSummary(result) << "\n"
            << "Results in " << out.FinalPath() << " (report.md, model.vtu/.inp/.feb/.msh"
            << (pictures ? ", pictures *.png" : "") << ")" << std::endl;
  ctx.outputs.Set("skinMeanError", a.skin.mean);
  ctx.outputs.Set("skullMeanError", a.skull.mean);
  ctx.outputs.Set("lipsMaxError", a.lips.max);
  ctx.outputs.Set("controlPointMeanError", mmrep::ControlPointMeanError(result));
  ctx.outputs.Set("minScaledJacobian", result.repair.minScaledJacobianAfter);
  ctx.outputs.Set("seconds", result.totalSeconds);
  ctx.progress.End();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, FaceModelPipelineXML, Run);
}
