// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// SkinSkullSurfaces: head CT -> outer skin surface and skull surface (LPS mm).
#include "mmrepCLI.h"
#include "mmrepCTThresholds.h"
#include "mmrepHeadSegmentation.h"
#include "mmrepImageIO.h"
#include "mmrepSurfaceExtraction.h"
#include "mmrepSnapshot.h"
#include "mmrepSurfaceIO.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <vector>

extern const char SkinSkullSurfacesXML[];

namespace
{
double OptionalDouble(const mmrep::cli::Arguments& args, const std::string& name)
{
  return args.Given(name) ? args.Double(name) : std::numeric_limits<double>::quiet_NaN();
}

constexpr long long kMinimumSurfaceVertices = 2000;

void Run(mmrep::cli::ModuleContext& ctx)
{
  const auto& args = ctx.args;
  // Output files first: an unwritable folder fails before any work.
  std::vector<std::unique_ptr<mmrep::cli::AtomicOutput>> outputs;
  auto out = [&](const std::string& path) -> mmrep::cli::AtomicOutput& {
    outputs.push_back(std::make_unique<mmrep::cli::AtomicOutput>(path));
    return *outputs.back();
  };
  for (const char* name : {"outputSkin", "outputSkull"})
  {
    const auto ext = mmrep::cli::FileExtension(args.String(name));
    if (ext != ".vtp" && ext != ".vtk" && ext != ".stl" && ext != ".ply" && ext != ".obj")
      throw mmrep::cli::ModuleError(args.String(name) + ": unknown surface format '" + ext +
                                    "' (use .vtp, .vtk, .stl, .ply or .obj)");
  }
  // A decimated head surface must still hold the face's shape (a few mm between vertices at most).
  for (const char* name : {"skinVertexCount", "skullVertexCount"})
    if (args.Int(name) != 0 && args.Int(name) < kMinimumSurfaceVertices)
      throw mmrep::cli::ModuleError("--" + std::string(name) + " " + std::to_string(args.Int(name)) +
                                    " is too few vertices for a head surface: 0 keeps all, else at least " +
                                    std::to_string(kMinimumSurfaceVertices));
  auto& skinOut = out(args.String("outputSkin"));
  auto& skullOut = out(args.String("outputSkull"));
  mmrep::cli::AtomicOutput* skinMaskOut = args.Given("skinMask") ? &out(args.String("skinMask")) : nullptr;
  mmrep::cli::AtomicOutput* boneMaskOut = args.Given("boneMask") ? &out(args.String("boneMask")) : nullptr;
  mmrep::cli::AtomicOutput* snapshotOut = args.Given("snapshot") ? &out(args.String("snapshot")) : nullptr;

  ctx.progress.Start("Skin and skull surfaces");
  const auto ct = mmrep::ReadCTImage(args.String("inputVolume"));
  ctx.progress.Report(0.1);

  const auto thresholds =
    mmrep::ChooseThresholds(ct, mmrep::ThresholdModeFromName(args.String("thresholdMode")),
                            OptionalDouble(args, "skinThreshold"), OptionalDouble(args, "boneThreshold"));
  std::cout << "Thresholds (" << thresholds.source << "): skin " << thresholds.skin << ", bone " << thresholds.bone
            << std::endl;

  mmrep::HeadSegmentationOptions seg;
  seg.skinThreshold = thresholds.skin;
  seg.boneThreshold = thresholds.bone;
  seg.openingRadius = static_cast<unsigned>(args.Int("openingRadius"));
  seg.fillInteriorAir = !args.Bool("keepInteriorAir");
  const auto head = mmrep::SegmentHead(ct, seg, [&](double f) { ctx.progress.ReportRange(0.1, 0.5, f); });

  mmrep::SurfaceExtractionOptions surf;
  // The masks are single components without cavities, so each surface is already one piece (the
  // image-stage tests check it on both sample CTs): skip the connectivity pass.
  surf.largestPieceOnly = false;
  surf.smoothingIterations = static_cast<unsigned>(args.Int("smoothingIterations"));
  surf.targetVertexCount = static_cast<std::size_t>(args.Int("skinVertexCount"));
  auto skin = mmrep::ExtractSurface(mmrep::MaskedIntensities(ct, head.skin, thresholds.skin), thresholds.skin, surf);
  ctx.progress.Report(0.7);
  surf.targetVertexCount = static_cast<std::size_t>(args.Int("skullVertexCount"));
  auto skull = mmrep::ExtractSurface(mmrep::MaskedIntensities(ct, head.bone, thresholds.bone), thresholds.bone, surf);
  ctx.progress.Report(0.9);

  mmrep::WriteSurface(skin, skinOut.TempPath(), mmrep::cli::FileExtension(skinOut.FinalPath()));
  mmrep::WriteSurface(skull, skullOut.TempPath(), mmrep::cli::FileExtension(skullOut.FinalPath()));
  if (skinMaskOut)
    mmrep::WriteImage(head.skin.GetPointer(), skinMaskOut->TempPath());
  if (boneMaskOut)
    mmrep::WriteImage(head.bone.GetPointer(), boneMaskOut->TempPath());
  if (snapshotOut)
  {
    mmrep::SnapshotLayer skullLayer, skinLayer;
    skullLayer.surface = skull;
    skullLayer.color = {0.95, 0.92, 0.80};
    skinLayer.surface = skin;
    skinLayer.color = {0.90, 0.65, 0.55};
    skinLayer.opacity = 0.35;
    mmrep::SnapshotOptions view;
    view.title = "skin (translucent) and skull";
    mmrep::WriteSnapshot({skullLayer, skinLayer}, view, snapshotOut->TempPath());
  }
  for (auto& o : outputs)
    o->Commit();

  std::cout << "Skin: " << skin->GetNumberOfPoints() << " vertices, " << skin->GetNumberOfPolys() << " triangles; head "
            << head.skinVolume / 1000 << " ml\n"
            << "Skull: " << skull->GetNumberOfPoints() << " vertices, " << skull->GetNumberOfPolys()
            << " triangles; bone " << head.boneVolume / 1000 << " ml" << std::endl;
  ctx.outputs.Set("chosenSkinThreshold", thresholds.skin);
  ctx.outputs.Set("chosenBoneThreshold", thresholds.bone);
  ctx.outputs.Set("thresholdSource", thresholds.source);
  ctx.outputs.Set("skinVertices", static_cast<long long>(skin->GetNumberOfPoints()));
  ctx.outputs.Set("skullVertices", static_cast<long long>(skull->GetNumberOfPoints()));
  ctx.outputs.Set("headVolumeMl", head.skinVolume / 1000);
  ctx.outputs.Set("boneVolumeMl", head.boneVolume / 1000);
  ctx.progress.End();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, SkinSkullSurfacesXML, Run);
}
