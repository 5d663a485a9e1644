// MeshReparation: Jacobian-based repair of an FE face model after registration, with a JSON report
// and before/after scaled-Jacobian histograms. The repaired mesh is written only on success.
#include "MeshReparationHistogram.h"
#include "mmrepCLI.h"
#include "mmrepFEMeshIO.h"
#include "mmrepMeshQuality.h"
#include "mmrepMeshRepair.h"
#include "mmrepPlane.h"
#include "mmrepSurfaceDistance.h"
#include "mmrepSurfaceIO.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <optional>
#include <string>

extern const char MeshReparationXML[];

namespace
{
using namespace mmrep;
using nlohmann::json;

json Number(double v) // JSON has no NaN / infinity
{
  return std::isfinite(v) ? json(v) : json(nullptr);
}

// Scaled Jacobian of every solid element, degenerate ones as -infinity (for the histogram).
std::vector<double> ScaledJacobians(const FEMesh& mesh)
{
  std::vector<double> values;
  const auto all = quality::ComputeQuality(mesh, quality::Measure::ScaledJacobian, {1, {}});
  for (const double v : all)
    if (!std::isnan(v))
      values.push_back(quality::IsVerdictFlag(v) ? -std::numeric_limits<double>::infinity() : v);
  return values;
}

struct Accuracy
{
  std::string set, surfaceName;
  vtkPolyData* surface = nullptr;
  SurfaceDistance before, after;
};

json ToJSON(const SurfaceDistance& d)
{
  return {{"nodes", d.count}, {"meanDistance", d.mean}, {"maxDistance", d.max}};
}

std::string Format(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

std::string Extension(const std::string& path) // without the dot
{
  const std::string ext = cli::FileExtension(path);
  return ext.empty() ? ext : ext.substr(1);
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
      if (ctx.args.Has("skinSurface") && !ctx.args.String("skinSurface").empty())
        skin = ReadSurface(ctx.args.String("skinSurface"));
      if (ctx.args.Has("skullSurface") && !ctx.args.String("skullSurface").empty())
        skull = ReadSurface(ctx.args.String("skullSurface"));
    }
    catch (const std::exception& e)
    {
      throw cli::ModuleError(e.what());
    }
    options.skinSurface = skin;
    options.skullSurface = skull;
    options.progress = [&](double f) { ctx.progress.ReportRange(0.05, 0.85, f); };

    // Accuracy of the surface node sets, measured against the given surfaces only.
    std::vector<Accuracy> accuracy;
    if (skin)
    {
      accuracy.push_back({"skin", "skinSurface", skin, {}, {}});
      accuracy.push_back({"lips", "skinSurface", skin, {}, {}});
    }
    if (skull)
      accuracy.push_back({"skull", "skullSurface", skull, {}, {}});
    for (auto& a : accuracy)
      a.before = MeasureSurfaceDistance(mesh, a.set, a.surface);
    const std::vector<double> before = histogramPath.empty() ? std::vector<double>() : ScaledJacobians(mesh);

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
    for (auto& a : accuracy)
      a.after = MeasureSurfaceDistance(mesh, a.set, a.surface);

    if (!reportPath.empty())
    {
      json j;
      j["input"] = input;
      j["output"] = report.success ? json(output) : json(nullptr);
      j["threshold"] = options.scaledJacobianThreshold;
      j["success"] = report.success;
      j["quality"] = {
        {"before", {{"minScaledJacobian", Number(report.minScaledJacobianBefore)},
                    {"meanScaledJacobian", Number(report.meanScaledJacobianBefore)},
                    {"belowThreshold", report.belowThresholdBefore},
                    {"inverted", report.invertedBefore}}},
        {"after", {{"minScaledJacobian", Number(report.minScaledJacobianAfter)},
                   {"meanScaledJacobian", Number(report.meanScaledJacobianAfter)},
                   {"belowThreshold", report.belowThresholdAfter},
                   {"inverted", report.invertedAfter}}}};
      json surfaces = json::object();
      for (const auto& a : accuracy)
        surfaces[a.set] = {{"surface", a.surfaceName}, {"before", ToJSON(a.before)}, {"after", ToJSON(a.after)}};
      j["surfaceAccuracy"] = surfaces;
      j["solidElements"] = mesh.SolidElementCount();
      j["movedNodes"] = report.movedNodes;
      j["movedSurfaceNodes"] = report.movedSurfaceNodes;
      j["symmetricPairs"] = report.symmetricPairs;
      j["seconds"] = report.seconds;
      json failed = json::array();
      for (std::size_t k = 0; k < report.failedElements.size(); ++k)
      {
        const std::size_t e = report.failedElements[k];
        failed.push_back({{"element", e},
                          {"layer", TissueLayerName(mesh.elements[e].layer)},
                          {"scaledJacobian", Number(report.failedValues[k])},
                          {"degenerate", std::isinf(report.failedValues[k])}});
      }
      j["failedElements"] = failed;
      cli::AtomicOutput out(reportPath);
      std::ofstream file(out.TempPath());
      file << j.dump(2) << "\n";
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
        WriteHistogramPNG({{"before", before}, {"after", ScaledJacobians(mesh)}}, options.scaledJacobianThreshold,
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
    {
      char worst[64];
      const double w = report.failedValues.empty() ? std::numeric_limits<double>::quiet_NaN() : report.failedValues[0];
      if (std::isinf(w))
        std::snprintf(worst, sizeof worst, "degenerate");
      else
        std::snprintf(worst, sizeof worst, "%.4g", w);
      throw cli::ModuleError(std::to_string(report.failedElements.size()) +
                             " elements stay below the scaled Jacobian threshold " +
                             Format(options.scaledJacobianThreshold) + " (worst: element " +
                             (report.failedElements.empty() ? std::string("?") : std::to_string(report.failedElements[0])) +
                             ", " + worst + "); no output mesh written");
    }
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
    ctx.outputs.Set("movedNodes", static_cast<long long>(report.movedNodes));
    ctx.outputs.Set("seconds", report.seconds);
  });
}
