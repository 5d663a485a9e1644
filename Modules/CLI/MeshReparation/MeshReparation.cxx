// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// MeshReparation: Jacobian-based repair of an FE face model after registration, with a JSON report
// and before/after scaled-Jacobian histograms. The repaired mesh is written only on success.
#include "mmrepCLI.h"
#include "mmrepFEMeshIO.h"
#include "mmrepHistogramPicture.h"
#include "mmrepMeshRepair.h"
#include "mmrepPlane.h"
#include "mmrepSurfaceDistance.h"
#include "mmrepRepairSummary.h"
#include "mmrepSurfaceIO.h"

#include <algorithm>
#include <fstream>
#include <string>

extern const char MeshReparationXML[];

namespace
{
using namespace mmrep;

std::string Extension(const std::string& path) // without the dot
{
  const std::string ext = cli::FileExtension(path);
  return ext.empty() ? ext : ext.substr(1);
}

vtkSmartPointer<vtkPolyData> OptionalSurface(const cli::ModuleContext& ctx, const std::string& name)
{
  if (!ctx.args.Has(name) || ctx.args.String(name).empty())
    return nullptr;
  return ReadSurface(ctx.args.String(name));
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return cli::RunModule(argc, argv, MeshReparationXML, [](cli::ModuleContext& ctx) {
    const std::string input = ctx.args.String("inputMesh");
    const std::string output = ctx.args.String("outputMesh");
    const auto writable = WritableFEMeshExtensions();
    if (std::find(writable.begin(), writable.end(), cli::FileExtension(output)) == writable.end())
      throw cli::ModuleError("outputMesh '" + output + "' must end in .vtu, .vtk, .inp, .feb or .msh");
    const std::string reportPath = ctx.args.Has("report") ? ctx.args.String("report") : "";
    const std::string histogramPath = ctx.args.Has("histogram") ? ctx.args.String("histogram") : "";

    RepairOptions options;
    options.scaledJacobianThreshold = ctx.args.Double("threshold");
    options.maximumSweeps = static_cast<int>(ctx.args.Int("maximumSweeps"));
    if (ctx.args.Given("symmetryPlane"))
    {
      options.symmetryPlane = PlaneFromSixNumbers(ctx.args.Doubles("symmetryPlane"), "--symmetryPlane");
      options.hasSymmetryPlane = true;
    }

    ctx.progress.Start("Repairing mesh");
    FEMesh mesh;
    vtkSmartPointer<vtkPolyData> skin, skull;
    try
    {
      mesh = ReadFEMesh(input);
      skin = OptionalSurface(ctx, "skinSurface");
      skull = OptionalSurface(ctx, "skullSurface");
    }
    catch (const std::exception& e)
    {
      throw cli::ModuleError(e.what());
    }
    options.skinSurface = skin;
    options.skullSurface = skull;
    options.progress = [&](double f) { ctx.progress.ReportRange(0.05, 0.85, f); };

    // Accuracy of the surface node sets, measured against the given surfaces only.
    std::vector<SurfaceAccuracy> accuracy = SurfaceAccuracySets(skin, skull);
    MeasureSurfaceAccuracy(mesh, accuracy, false);
    const std::vector<double> before = histogramPath.empty() ? std::vector<double>() : ScaledJacobianValues(mesh);

    RepairReport report;
    try
    {
      report = RepairMesh(mesh, options);
    }
    catch (const std::invalid_argument& e)
    {
      throw cli::ModuleError("inputMesh '" + input + "': " + e.what());
    }
    ctx.progress.Report(0.85);
    MeasureSurfaceAccuracy(mesh, accuracy, true);

    if (!reportPath.empty())
    {
      cli::AtomicOutput out(reportPath);
      std::ofstream file(out.TempPath());
      file << RepairReportJson(report, mesh, accuracy, input, output, options.scaledJacobianThreshold) << "\n";
      file.close();
      if (!file)
        throw cli::ModuleError("cannot write report '" + reportPath + "'");
      out.CommitEvenIfRunFails(); // the report says why a repair failed
    }
    if (!histogramPath.empty())
    {
      cli::AtomicOutput out(histogramPath);
      try
      {
        WriteHistogramPNG({{"before", before}, {"after", ScaledJacobianValues(mesh)}}, options.scaledJacobianThreshold,
                          out.TempPath());
      }
      catch (const std::exception& e)
      {
        throw cli::ModuleError(std::string("histogram: ") + e.what());
      }
      out.CommitEvenIfRunFails();
    }
    ctx.progress.Report(0.9);

    if (!report.success)
      throw cli::ModuleError(RepairFailureMessage(report, options.scaledJacobianThreshold) +
                             "; no output mesh written");
    {
      cli::AtomicOutput out(output);
      try
      {
        WriteFEMesh(mesh, out.TempPath(), Extension(output));
      }
      catch (const std::exception& e)
      {
        throw cli::ModuleError(e.what());
      }
      out.Commit();
    }
    ctx.progress.End();

    ctx.outputs.Set("success", std::string(report.success ? "true" : "false"));
    ctx.outputs.Set("minScaledJacobianBefore", report.minScaledJacobianBefore);
    ctx.outputs.Set("minScaledJacobianAfter", report.minScaledJacobianAfter);
    ctx.outputs.Set("invertedBefore", static_cast<long long>(report.invertedBefore));
    ctx.outputs.Set("invertedAfter", static_cast<long long>(report.invertedAfter));
    ctx.outputs.Set("belowThresholdAfter", static_cast<long long>(report.belowThresholdAfter));
    ctx.outputs.Set("notCertifiedBefore", static_cast<long long>(report.notCertifiedBefore));
    ctx.outputs.Set("notCertifiedAfter", static_cast<long long>(report.notCertifiedAfter));
    ctx.outputs.Set("certifiedMinimumAfter", report.certifiedMinimumAfter);
    ctx.outputs.Set("movedNodes", static_cast<long long>(report.movedNodes));
    ctx.outputs.Set("seconds", report.seconds);
  });
}
