// FaceModelPipeline: speaker CT + five control points -> FE face model with muscles, exports for
// VTK, CalculiX/Abaqus, FEBio and Gmsh, the transform, a report and QC pictures, in one directory
// that appears only when complete (Libs/MMRepPipeline).
#include "FaceModelOutputDirectory.h"
#include "mmrepCLI.h"
#include "mmrepDisplacementFieldMap.h"
#include "mmrepFEMeshIO.h"
#include "mmrepFaceModelPictures.h"
#include "mmrepFaceModelPipeline.h"
#include "mmrepFaceModelReport.h"
#include "mmrepHalfModel.h"
#include "mmrepImageIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepSnapshot.h"
#include "mmrepSurfaceIO.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>

extern const char FaceModelPipelineXML[];

namespace
{
using mmrep::cli::ModuleError;
namespace fs = std::filesystem;

void WriteText(const fs::path& path, const std::string& text)
{
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f)
    throw ModuleError(path.string() + ": cannot write");
}

void Run(mmrep::cli::ModuleContext& ctx)
{
  const auto& args = ctx.args;
  if (!args.Given("outputDirectory") || args.String("outputDirectory").empty())
    throw ModuleError("--outputDirectory is required (where the model, report and pictures go)");
  const bool pictures = !args.Bool("noPictures");
  if (pictures)
    mmrep::RequireDisplay(args.String("outputDirectory") + "/*.png (or pass --noPictures)");
  const double qualityThreshold = args.Double("qualityThreshold");
  if (!(qualityThreshold >= -1 && qualityThreshold <= 1))
    throw ModuleError("--qualityThreshold must lie in [-1, 1]");
  if (!(args.Double("transformSpacing") > 0))
    throw ModuleError("--transformSpacing must be > 0");
  if (args.Bool("halfModel") && args.String("symmetry") == "full")
    throw ModuleError("--halfModel needs a symmetric model: use --symmetry half-face (the default) or averaged");

  // The directory is staged first: an unwritable place fails before any work.
  FaceModelOutputDirectory out(args.String("outputDirectory"));

  ctx.progress.Start("Face model pipeline");
  const std::string atlasPath = args.Given("atlas") ? args.String("atlas") : mmrep::cli::ModuleResourcePath(MMREP_DEFAULT_ATLAS);
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
  options.refinement.elementQualityFloor = options.registration.elementQualityFloor;
  mmrep::SetSymmetryMode(options.registration, args.String("symmetry"));
  options.refine = !args.Bool("noRefinement");
  options.refinement.spacing = args.Double("lipsSpacing");
  options.repairThreshold = qualityThreshold;
  options.allowPartialFieldOfView = args.Bool("allowPartialFieldOfView");
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
  if (!result.fieldOfViewMissing.empty())
    std::cerr << ctx.moduleName << ": warning: partial model: the CT misses the " << result.fieldOfViewMissing
              << " of the face region; there the model is not fitted to the speaker (report.md)" << std::endl;

  std::cout << "Scaled Jacobian after Q∘R: min " << result.qualityAfterQ.min << ", " << result.qualityAfterQ.inverted
            << " inverted, " << result.qualityAfterQ.belowThreshold << " below " << qualityThreshold
            << "; repaired: min " << result.repair.minScaledJacobianAfter << " in " << result.repair.seconds
            << " s" << std::endl;
  // Files.
  const fs::path dir = out.StagingPath();
  std::vector<std::pair<std::string, std::string>> files = {
    {"model.vtu", "FE model for VTK/ParaView/Slicer: layers, node and element sets, muscles with embedding, landmarks"},
    {"model.inp", "FE model for CalculiX/Abaqus (*NSET/*ELSET per set, layer and muscle)"},
    {"model.feb", "FE model for FEBio (NodeSet/ElementSet)"},
    {"model.msh", "FE model for Gmsh (physical groups)"},
    {"transform.nrrd", "displacement field u(x) = Q(R(x)) - x over the atlas, atlas to speaker (LPS mm)"},
    {"skin.vtp", "the speaker's skin surface from the CT"},
    {"skull.vtp", "the speaker's skull surface from the CT"},
    {"landmarks.mrk.json", "the model's landmarks (atlas landmarks through Q∘R)"},
    {"report.json", "accuracy, quality, muscles and times (machine-readable)"},
    {"report.md", "the same as tables"}};
  if (pictures)
  {
    files.emplace_back("model-skin-error.png", "model skin coloured by distance to the speaker's skin, front and left");
    files.emplace_back("lips.png", "lips close-up, front and left");
    files.emplace_back("muscles.png", "the speaker's inferred muscle tracks, front and left");
  }
  for (const char* format : {"vtu", "inp", "feb", "msh"})
    mmrep::WriteFEMesh(result.model, (dir / (std::string("model.") + format)).string(), format);
  if (args.Bool("halfModel"))
  {
    files.emplace_back("half-model.vtu", "the left half of the model, symmetry boundary in node set symmetryBoundary (also .inp, .feb, .msh)");
    const auto half = mmrep::LeftHalfModel(result.model);
    for (const char* format : {"vtu", "inp", "feb", "msh"})
      mmrep::WriteFEMesh(half, (dir / (std::string("half-model.") + format)).string(), format);
  }
  ctx.progress.Report(0.88);
  const auto field = mmrep::SampleDisplacementField([&](const mmrep::Point3& x) { return result.AtlasToSubject(x); },
                                                    atlas.nodes, 10.0, args.Double("transformSpacing"));
  mmrep::WriteDisplacementField(field, (dir / "transform.nrrd").string());
  mmrep::WriteSurface(result.skin, (dir / "skin.vtp").string());
  mmrep::WriteSurface(result.skull, (dir / "skull.vtp").string());
  mmrep::WriteLandmarks(result.model.landmarks, (dir / "landmarks.mrk.json").string());
  ctx.progress.Report(0.92);
  if (pictures)
  {
    mmrep::WriteModelErrorPicture(result, (dir / "model-skin-error.png").string());
    mmrep::WriteLipsPicture(result, (dir / "lips.png").string());
    mmrep::WriteMusclesPicture(result.model, result.skin, (dir / "muscles.png").string(),
                               "inferred muscle tracks (one colour per muscle) in the speaker's face");
  }
  mmrep::FaceModelReportInputs inputs;
  inputs.ct = args.String("inputVolume");
  inputs.controlPoints = args.String("controlPoints");
  inputs.atlas = atlasPath;
  inputs.repairThreshold = qualityThreshold;
  inputs.files = files;
  WriteText(dir / "report.json", mmrep::FaceModelReportJson(result, inputs));
  WriteText(dir / "report.md", mmrep::FaceModelReportMarkdown(result, inputs));
  if (args.Bool("intermediates"))
  {
    mmrep::WriteFEMesh(result.registered, (dir / "registered.vtu").string());
    mmrep::WriteFEMesh(result.refined, (dir / "refined.vtu").string());
  }
  out.Commit();
  if (!result.repair.success)
  {
    // The model does not meet the quality threshold: the run fails and publishes nothing (an
    // earlier result in the output directory stays as it was).
    std::string worst;
    for (std::size_t i = 0; i < result.repair.failedElements.size() && i < 5; ++i)
      worst += (i ? ", " : "") + std::to_string(result.repair.failedElements[i]) + " (" +
               std::to_string(result.repair.failedValues[i]) + ")";
    throw ModuleError("repair could not bring every element to scaled Jacobian " + std::to_string(qualityThreshold) +
                      ": " + std::to_string(result.repair.failedElements.size()) + " elements remain below (worst: " +
                      worst + "); nothing written to " + out.FinalPath().string() +
                      " (lower --qualityThreshold or check the control points)");
  }

  const auto& a = result.accuracy.back();
  double cpMean = 0;
  for (double e : a.controlErrors)
    cpMean += e / static_cast<double>(a.controlErrors.size());
  std::cout << "Model: " << result.model.nodes.size() << " nodes, " << result.model.SolidElementCount()
            << " solid elements; fitted " << result.fitted << ": skin " << a.skinHalf.mean << " mm mean, skull "
            << a.skullHalf.mean << " mm mean, lips " << a.lipsHalf.max << " mm max (whole model: skin " << a.skin.mean
            << ", skull " << a.skull.mean << ", lips max " << a.lips.max << "); control points " << cpMean << " mm mean; min scaled Jacobian "
            << result.repair.minScaledJacobianAfter << "; " << result.totalSeconds << " s\n"
            << "Results in " << out.FinalPath() << " (report.md, model.vtu/.inp/.feb/.msh"
            << (pictures ? ", pictures *.png" : "") << ")" << std::endl;
  ctx.outputs.Set("skinMeanError", a.skin.mean);
  ctx.outputs.Set("skullMeanError", a.skull.mean);
  ctx.outputs.Set("lipsMaxError", a.lips.max);
  ctx.outputs.Set("controlPointMeanError", cpMean);
  ctx.outputs.Set("minScaledJacobian", result.repair.minScaledJacobianAfter);
  ctx.outputs.Set("seconds", result.totalSeconds);
  ctx.progress.End();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, FaceModelPipelineXML, Run);
}
