// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// SimulateMuscleActivation: muscle activation of a speaker FE face model with CalculiX; deformed
// model (.vtu with the displacement), before/after pictures, landmark displacements and mouth measures.
#include "mmrepActivationPictures.h"
#include "mmrepActivationReport.h"
#include "mmrepActivationRequest.h"
#include "mmrepCLI.h"
#include "mmrepDeformedModelIO.h"
#include "mmrepFEMeshIO.h"
#include "mmrepSnapshot.h"

#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

extern const char SimulateMuscleActivationXML[];

namespace
{
using namespace mmrep;
namespace sim = mmrep::simulation;

sim::ActivationRequest Request(const cli::Arguments& args)
{
  sim::ActivationRequest r;
  r.muscles = args.Strings("muscles");
  r.levels = args.Doubles("activations");
  r.gesture = args.Has("gesture") ? args.String("gesture") : "";
  r.hasJawAngle = args.Has("jawAngle");
  r.jawAngle = r.hasJawAngle ? args.Double("jawAngle") : 0;
  r.c10 = args.Double("c10");
  r.c20 = args.Double("c20");
  r.poissonRatio = args.Double("poissonRatio");
  const std::vector<double> scale = args.Doubles("layerScale");
  if (scale.size() != 3)
    throw cli::ModuleError("--layerScale needs three positive factors (epidermis, dermis, hypodermis)");
  r.layerScale = {scale[0], scale[1], scale[2]};
  r.elementType = args.String("elementType");
  r.forceScale = args.Double("forceScale");
  r.initialIncrement = args.Has("initialIncrement") ? args.Double("initialIncrement") : 0;
  r.maxIncrements = static_cast<int>(args.Int("maxIncrements"));
  r.lipContact = !args.Bool("noLipContact");
  r.lipSupport = !args.Bool("noLipSupport");
  r.boneSliding = args.Bool("boneSliding");
  return r;
}

} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return cli::RunModule(argc, argv, SimulateMuscleActivationXML, [](cli::ModuleContext& ctx) {
    const std::string input = ctx.args.String("inputModel"), output = ctx.args.String("outputModel");
    const std::string picture = ctx.args.Has("picture") ? ctx.args.String("picture") : "";
    const std::string lipsPicture = ctx.args.Has("lipsPicture") ? ctx.args.String("lipsPicture") : "";
    if (cli::FileExtension(output) != ".vtu")
      throw cli::ModuleError("outputModel '" + output + "' must end in .vtu");
    for (const auto& png : {picture, lipsPicture})
      if (!png.empty() && cli::FileExtension(png) != ".png")
        throw cli::ModuleError("picture '" + png + "' must end in .png");

    ctx.progress.Start("Simulating muscle activation with CalculiX");
    const FEMesh mesh = cli::AsModuleError([&] { return ReadFEMesh(input); });
    if (mesh.muscles.empty())
      throw cli::ModuleError("input model '" + input +
                             "' has no muscles: a speaker model with muscle tracks is needed");
    sim::Gesture gesture;
    sim::ActivationOptions options;
    cli::AsModuleError([&] {
      options.deck = sim::MakeDeckOptions(mesh, Request(ctx.args), input, gesture);
      options.run.executable = ctx.args.Has("ccx") ? ctx.args.String("ccx") : "";
      sim::FindCalculiX(options.run.executable);
      for (const auto& png : {picture, lipsPicture})
        if (!png.empty())
          RequireDisplay(png);
      return 0;
    });
    if (const std::string warning = sim::LipContactWarning(mesh, options.deck, input); !warning.empty())
      std::cerr << ctx.moduleName << ": warning: " << warning << std::endl;
    options.run.threads = static_cast<int>(ctx.args.Int("threads"));
    options.run.keepDirectory = ctx.args.Bool("keepJob");
    options.run.progress = [&ctx](double t) { ctx.progress.ReportRange(0.1, 0.8, t); };
    ctx.progress.Report(0.1);

    const sim::ActivationResult result =
      cli::AsModuleError([&] { return sim::SimulateMuscleActivation(mesh, options); }, "input model '" + input + "': ");
    if (options.run.keepDirectory)
      std::printf("CalculiX job folder kept: %s\n", result.run.directory.c_str());
    ctx.progress.Report(0.8);
    const double maxDisplacement = sim::MaxSolidDisplacement(mesh, result);
    const sim::MouthMeasures mouth = sim::MeasureMouth(mesh, result);
    std::printf(
      "%s", sim::ActivationReport(result, options.run.threads, options.deck.jawAngle, mouth, maxDisplacement).c_str());
    std::fflush(stdout);

    cli::AtomicOutput model(output);
    cli::AsModuleError([&] {
      sim::WriteDeformedModel(mesh, result, model.TempPath());
      return 0;
    });
    model.Commit();
    ctx.progress.Report(0.85);
    std::optional<cli::AtomicOutput> front, lips;
    if (!picture.empty())
      front.emplace(picture);
    if (!lipsPicture.empty())
      lips.emplace(lipsPicture);
    if (front || lips)
    {
      const std::string title = gesture.name.empty() ? sim::ShortList(result.deck.activeMuscles) : gesture.name;
      cli::AsModuleError([&] {
        sim::WriteActivationPictures(mesh, result, maxDisplacement, front ? front->TempPath() : "",
                                     lips ? lips->TempPath() : "", title);
        return 0;
      });
      for (auto* png : {&front, &lips})
        if (*png)
          (*png)->Commit();
    }

    for (const auto& [param, name] :
         std::vector<std::pair<std::string, std::string>>{{"leftLipCornerDisplacement", "LeftLipCorner"},
                                                          {"upperLipCenterDisplacement", "UpperLipCenter"},
                                                          {"lowerLipCenterDisplacement", "LowerLipCenter"}})
      for (const auto& m : result.landmarks)
        if (m.name == name)
          ctx.outputs.Set(param, std::vector<double>{m.displacement.x(), m.displacement.y(), m.displacement.z()});
    double meanForce = 0;
    for (const auto& m : result.muscles)
      meanForce += m.meanForce / static_cast<double>(result.muscles.size());
    ctx.outputs.Set("mouthWidthChange", mouth.width - mouth.restWidth);
    ctx.outputs.Set("apertureHeight", mouth.apertureHeight);
    ctx.outputs.Set("upperLipProtrusion", mouth.upperProtrusion);
    ctx.outputs.Set("lowerLipProtrusion", mouth.lowerProtrusion);
    ctx.outputs.Set("minimumLipGap", mouth.minimumLipGap);
    ctx.outputs.Set("maxDisplacement", maxDisplacement);
    ctx.outputs.Set("meanMuscleForce", meanForce);
    ctx.outputs.Set("ccxSeconds", result.run.seconds);
    ctx.outputs.Set("increments", result.run.increments);
    ctx.outputs.Set("iterations", result.run.iterations);
    ctx.progress.End();
  });
}
