// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// BuildFaceAtlas: reference head CT -> generic face atlas (mesh, landmarks, QC pictures).
#include "mmrepCLI.h"
#include "mmrepFEMeshIO.h"
#include "mmrepFaceAtlas.h"
#include "mmrepFaceAtlasPictures.h"
#include "mmrepFaceAtlasSummary.h"
#include "mmrepFaceModelPipeline.h"
#include "mmrepImageIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepSurfaceIO.h"

#include <Eigen/Geometry>
#include <vtkSMPTools.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

extern const char BuildFaceAtlasXML[];

namespace
{
using Clock = std::chrono::steady_clock;
using mmrep::cli::ModuleError;

double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

mmrep::FaceAtlasOptions AtlasOptions(const mmrep::cli::Arguments& args)
{
  mmrep::FaceAtlasOptions options;
  options.meshSize = args.Double("meshSize");
  options.lipsMeshSize = args.Double("lipsMeshSize");
  if (options.lipsMeshSize > options.meshSize)
    throw ModuleError("lipsMeshSize: must not exceed meshSize");
  options.lateralAngle = args.Double("lateralAngle");
  options.browMargin = args.Double("browMargin");
  options.chinMargin = args.Double("chinMargin");
  options.maxBoneDepth = args.Double("maxBoneDepth");
  options.minThickness = args.Double("minThickness");
  options.normalBlend = args.Double("normalBlend");
  options.qualityThreshold = args.Double("qualityThreshold");
  const auto ratios = args.Doubles("layerRatios");
  if (ratios.size() != 3 || std::any_of(ratios.begin(), ratios.end(), [](double r) { return !(r > 0); }))
    throw ModuleError("layerRatios: give three positive values (epidermis, dermis, hypodermis)");
  options.layerRatios = {ratios[0], ratios[1], ratios[2]};
  return options;
}

void Run(mmrep::cli::ModuleContext& ctx)
{
  const auto& args = ctx.args;
  const auto start = Clock::now();
  std::vector<std::unique_ptr<mmrep::cli::AtomicOutput>> outputs;
  auto out = [&](const std::string& name) -> mmrep::cli::AtomicOutput* {
    if (!args.Given(name))
      return nullptr;
    outputs.push_back(std::make_unique<mmrep::cli::AtomicOutput>(args.String(name)));
    return outputs.back().get();
  };
  const std::string meshFormat = mmrep::cli::FileExtension(args.String("outputMesh"));
  const auto writable = mmrep::WritableFEMeshExtensions();
  if (std::find(writable.begin(), writable.end(), meshFormat) == writable.end())
    throw ModuleError("outputMesh: unsupported extension '" + meshFormat + "' (use .vtu, .vtk, .inp, .feb or .msh)");
  auto* meshOut = out("outputMesh");
  auto* landmarksOut = out("landmarks");
  auto* skinOut = out("referenceSkin");
  auto* skullOut = out("referenceSkull");
  const std::string pictures = args.Given("pictures") ? args.String("pictures") : "";
  if (!pictures.empty() && !std::filesystem::is_directory(pictures))
    throw ModuleError("pictures: '" + pictures + "' is not an existing folder");
  const std::string landmarksFormat = landmarksOut ? mmrep::cli::FileExtension(landmarksOut->FinalPath()) : "";
  if (landmarksOut && landmarksFormat != ".mrk.json" && landmarksFormat != ".fcsv")
    throw ModuleError("landmarks: unsupported extension '" + landmarksFormat + "' (use .mrk.json or .fcsv)");
  const mmrep::FaceAtlasOptions options = AtlasOptions(args);

  // VTK's threaded locators (vtkSMPTools sorts) make the symmetry plane's ICP differ in the 5th
  // digit from run to run; the sequential backend makes the atlas reproducible bit for bit.
  vtkSMPTools::SetBackend("Sequential");
  ctx.progress.Start("Building the face atlas");
  // 1. Surfaces and plane exactly as FaceModelPipeline makes them for a speaker: the atlas's own CT
  // then gives the atlas's plane to the last bit, and registering the atlas onto it starts from
  // the identity.
  const auto ct = mmrep::ReadCTImage(args.String("inputVolume"));
  const mmrep::FaceModelOptions pipeline;
  const auto surfaces =
    mmrep::ExtractSubjectSurfaces(ct, pipeline, [&](double f) { ctx.progress.ReportRange(0.0, 0.3, f); });
  const double tSurfaces = Seconds(start);
  ctx.progress.Report(0.4);
  const auto symmetry = mmrep::EstimateSubjectPlane(surfaces.skin, pipeline);
  const double tPlane = Seconds(start);
  std::cout << "Surfaces " << tSurfaces << " s, plane " << tPlane - tSurfaces << " s" << std::endl;
  std::cout << std::setprecision(6) << "Thresholds (" << surfaces.thresholds.source << "): skin "
            << surfaces.thresholds.skin << ", bone " << surfaces.thresholds.bone << "\nSymmetry plane: point "
            << symmetry.plane.point.transpose() << ", normal " << symmetry.plane.normal.transpose() << ", RMS residual "
            << symmetry.rmsResidual << " mm\n";
  ctx.progress.Report(0.5);

  // 2-8. The atlas, and its quality measured independently of the construction's own checks.
  const auto atlas = mmrep::BuildFaceAtlas(surfaces.skin, surfaces.skull, symmetry.plane, options,
                                           [&](double f) { ctx.progress.ReportRange(0.5, 0.9, f); });
  const double tAtlas = Seconds(start);
  for (const auto& line : atlas.log)
    std::cout << line << "\n";
  const auto& mesh = atlas.mesh;
  const auto quality = mmrep::MeasureFaceAtlasQuality(mesh, options.qualityThreshold);
  std::cout << quality.line << "\n";
  mmrep::RequireFaceAtlasQuality(quality, options.qualityThreshold);

  mmrep::WriteFEMesh(mesh, meshOut->TempPath(), meshFormat.substr(1));
  if (landmarksOut)
    mmrep::WriteLandmarks(mesh.landmarks, landmarksOut->TempPath(), landmarksFormat.substr(1),
                          mmrep::CoordinateSystem::LPS);
  if (skinOut)
    mmrep::WriteSurface(atlas.skinSurface, skinOut->TempPath(), mmrep::cli::FileExtension(skinOut->FinalPath()));
  if (skullOut)
    mmrep::WriteSurface(atlas.skullSurface, skullOut->TempPath(), mmrep::cli::FileExtension(skullOut->FinalPath()));
  ctx.progress.Report(0.95);
  if (!pictures.empty())
    mmrep::WriteFaceAtlasPictures(atlas, pictures);
  for (auto& o : outputs)
    o->Commit();

  std::cout << mmrep::FaceAtlasCounts(mesh) << "\nTimings: surfaces " << tSurfaces << " s, symmetry plane "
            << tPlane - tSurfaces << " s, atlas " << tAtlas - tPlane << " s, total " << Seconds(start) << " s"
            << std::endl;
  ctx.outputs.Set("nodeCount", static_cast<long long>(mesh.nodes.size()));
  ctx.outputs.Set("elementCount", static_cast<long long>(mesh.SolidElementCount()));
  ctx.outputs.Set("cableCount", static_cast<long long>(mesh.elements.size() - mesh.SolidElementCount()));
  ctx.outputs.Set("lipsNodeCount", static_cast<long long>(mesh.nodeSets.at("lips").size()));
  ctx.outputs.Set("minScaledJacobian", quality.summary.min);
  ctx.outputs.Set("meanScaledJacobian", quality.summary.mean);
  ctx.outputs.Set("invertedElements", static_cast<long long>(quality.summary.inverted));
  ctx.progress.End();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, BuildFaceAtlasXML, Run);
}
