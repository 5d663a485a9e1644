// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Test-only CLI module: writes every value it received (through the typed getters) to its output
// report, so the framework can be checked end to end from the command line.
#include "mmrepCLI.h"

#include <itkMacro.h>

#include <fstream>
#include <sstream>
#include <thread>

extern const char CLIFrameworkTestModuleXML[];

namespace
{
using mmrep::cli::ModuleContext;

template <typename T> std::string Join(const std::vector<T>& values)
{
  std::ostringstream s;
  s.precision(17);
  for (size_t i = 0; i < values.size(); ++i)
    s << (i ? "," : "") << values[i];
  return s.str();
}

void Body(ModuleContext& ctx)
{
  const auto& a = ctx.args;
  const std::string failure = a.String("failure");
  if (failure == "module")
    throw mmrep::cli::ModuleError("requested module failure");
  if (failure == "std")
    throw std::out_of_range("requested std failure");
  if (failure == "itk")
    itkGenericExceptionMacro("requested itk failure");

  // Progress from several threads at once: the framework keeps it ordered and whole-line.
  ctx.progress.Start("Testing the CLI framework");
  std::vector<std::thread> workers;
  for (int t = 0; t < 4; ++t)
    workers.emplace_back([&ctx, t] {
      for (int k = t; k <= 200; k += 4)
        ctx.progress.ReportRange(0.0, 0.9, k / 200.0);
    });
  for (auto& w : workers)
    w.join();

  mmrep::cli::AtomicOutput out(a.String("outputFile"));
  {
    std::ofstream f(out.TempPath());
    f.precision(17);
    f << "inputVolume=" << a.String("inputVolume") << "\n"
      << "iterations=" << a.Int("iterations") << "\n"
      << "fraction=" << a.Double("fraction") << "\n"
      << "scale=" << a.Double("scale") << "\n"
      << "verbose=" << a.Bool("verbose") << "\n"
      << "label=" << a.String("label") << "\n"
      << "size=" << Join(a.Ints("size")) << "\n"
      << "weights=" << Join(a.Doubles("weights")) << "\n"
      << "spacing=" << Join(a.Doubles("spacing")) << "\n"
      << "tags=" << Join(a.Strings("tags")) << "\n"
      << "order=" << a.Int("order") << "\n"
      << "ratio=" << a.Double("ratio") << "\n"
      << "sigma=" << a.Double("sigma") << "\n"
      << "mode=" << a.String("mode") << "\n"
      << "workDir=" << (a.Has("workDir") ? a.String("workDir") : "-") << "\n"
      << "inputMesh=" << a.String("inputMesh") << "\n"
      << "inputTransform=" << a.String("inputTransform") << "\n"
      << "outputTable=" << a.String("outputTable") << "\n"
      << "roi=" << Join(a.Doubles("roi")) << "\n";
    for (const auto& p : a.PointsLPS("seedsRAS"))
      f << "seedsRAS=" << p[0] << "," << p[1] << "," << p[2] << "\n";
    for (const auto& p : a.PointsLPS("seedLPS"))
      f << "seedLPS=" << p[0] << "," << p[1] << "," << p[2] << "\n";
    f.flush();
  }
  if (failure == "afterWrite")
    throw mmrep::cli::ModuleError("requested failure after writing '" + out.TempPath() + "'");
  out.Commit();
  if (failure == "afterCommit") // the framework publishes outputs only once the whole run succeeded
    throw mmrep::cli::ModuleError("requested failure after committing the output");

  double checksum = a.Double("scale");
  for (double s : a.Doubles("spacing"))
    checksum += s;
  ctx.outputs.Set("checksum", checksum);
  ctx.outputs.Set("seedCount", static_cast<int>(a.PointsLPS("seedsRAS").size()));
  ctx.outputs.Set("modeUsed", a.String("mode"));
  ctx.progress.Report(0.95);
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, CLIFrameworkTestModuleXML, Body);
}
