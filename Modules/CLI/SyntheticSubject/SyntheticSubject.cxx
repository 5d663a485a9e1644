// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// SyntheticSubject: source CT -> synthetic subject CT with a known transform (see mmrepSyntheticWarp.h).
#include "mmrepCLI.h"
#include "mmrepImageIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepSyntheticSubject.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

extern const char SyntheticSubjectXML[];

namespace
{

void CheckFieldExtension(const std::string& name, const std::string& path)
{
  const std::string ext = mmrep::cli::FileExtension(path);
  if (ext != ".nrrd" && ext != ".nhdr" && ext != ".mha" && ext != ".mhd")
    throw mmrep::cli::ModuleError(name + " '" + path + "' must end in .nrrd, .nhdr, .mha or .mhd");
}

std::string LandmarkFormat(const std::string& path)
{
  const std::string ext = mmrep::cli::FileExtension(path);
  if (ext == ".mrk.json")
    return "mrk.json";
  if (ext == ".fcsv")
    return "fcsv";
  throw mmrep::cli::ModuleError("landmarksOut '" + path + "' must end in .mrk.json or .fcsv");
}

void Run(mmrep::cli::ModuleContext& ctx)
{
  const auto& args = ctx.args;
  if (args.Given("landmarksIn") != args.Given("landmarksOut"))
    throw mmrep::cli::ModuleError("landmarksIn and landmarksOut must be given together");
  const std::vector<double> translation = args.Doubles("translation");
  if (translation.size() != 3)
    throw mmrep::cli::ModuleError("translation needs 3 values, got " + std::to_string(translation.size()));

  mmrep::SyntheticWarpParameters p;
  p.rollDegrees = args.Double("roll");
  p.pitchDegrees = args.Double("pitch");
  p.yawDegrees = args.Double("yaw");
  p.translation = Eigen::Vector3d(translation[0], translation[1], translation[2]);
  p.seed = static_cast<std::uint32_t>(args.Int("seed"));
  p.bumps = static_cast<int>(args.Int("warpBumps"));
  p.amplitude = args.Double("warpAmplitude");
  p.width = args.Double("warpWidth");
  // Parameter problems before any file is touched.
  try
  {
    mmrep::SyntheticWarp check(p);
  }
  catch (const std::invalid_argument& e)
  {
    throw mmrep::cli::ModuleError(e.what());
  }

  // Output files first: an unwritable folder fails before any work.
  std::vector<std::unique_ptr<mmrep::cli::AtomicOutput>> outputs;
  auto out = [&](const std::string& path) -> mmrep::cli::AtomicOutput& {
    outputs.push_back(std::make_unique<mmrep::cli::AtomicOutput>(path));
    return *outputs.back();
  };
  auto& volumeOut = out(args.String("outputVolume"));
  mmrep::cli::AtomicOutput* forwardOut = nullptr;
  mmrep::cli::AtomicOutput* inverseOut = nullptr;
  mmrep::cli::AtomicOutput* landmarksOut = nullptr;
  if (args.Given("forwardField"))
  {
    CheckFieldExtension("forwardField", args.String("forwardField"));
    forwardOut = &out(args.String("forwardField"));
  }
  if (args.Given("inverseField"))
  {
    CheckFieldExtension("inverseField", args.String("inverseField"));
    inverseOut = &out(args.String("inverseField"));
  }
  std::string landmarkFormat;
  if (args.Given("landmarksOut"))
  {
    landmarkFormat = LandmarkFormat(args.String("landmarksOut"));
    landmarksOut = &out(args.String("landmarksOut"));
  }

  ctx.progress.Start("Synthetic subject");
  const auto source = mmrep::ReadCTImage(args.String("inputVolume"));
  std::vector<mmrep::Landmark> landmarks;
  if (landmarksOut)
    landmarks = mmrep::ReadLandmarks(args.String("landmarksIn"));
  ctx.progress.Report(0.05);

  mmrep::FitWarpToImage(p, source);
  const mmrep::SyntheticWarp warp(p);
  const auto subject =
    mmrep::ResampleSyntheticSubject(source, warp, [&](double f) { ctx.progress.ReportRange(0.05, 0.5, f); });
  mmrep::WriteImage(subject.GetPointer(), volumeOut.TempPath());
  ctx.progress.Report(0.55);
  if (forwardOut)
    mmrep::WriteDisplacementField(mmrep::ForwardDisplacementField(source, warp), forwardOut->TempPath());
  ctx.progress.Report(0.8);
  if (inverseOut)
    mmrep::WriteDisplacementField(mmrep::InverseDisplacementField(source, warp), inverseOut->TempPath());
  ctx.progress.Report(0.95);
  if (landmarksOut)
  {
    for (auto& l : landmarks)
      l.position = warp.Forward(l.position);
    mmrep::WriteLandmarks(landmarks, landmarksOut->TempPath(), landmarkFormat, mmrep::CoordinateSystem::LPS);
  }
  for (auto& o : outputs)
    o->Commit();

  std::cout << "Warp: roll " << p.rollDegrees << ", pitch " << p.pitchDegrees << ", yaw " << p.yawDegrees
            << " deg about (" << p.centre.transpose() << "), translation (" << p.translation.transpose() << ") mm, "
            << p.bumps << " bumps of " << p.amplitude << " mm, width " << p.width << " mm; gradient bound "
            << warp.GradientBound() << std::endl;
  ctx.outputs.Set("gradientBound", warp.GradientBound());
  ctx.outputs.Set("jacobianLowerBound", std::pow(1.0 - warp.GradientBound(), 3));
  ctx.progress.End();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, SyntheticSubjectXML, Run);
}
