// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// MeshQuality: Verdict element quality of an FE face model, as cell arrays and a summary.
#include "mmrepCLI.h"
#include "mmrepFEMeshIO.h"
#include "mmrepMeshQuality.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <iostream>
#include <string>

extern const char MeshQualityXML[];

namespace
{
using namespace mmrep;
using namespace mmrep::quality;

// One line per measure: name, element count where defined, min / mean / max over unflagged values.
void PrintTable(const std::vector<Measure>& measures, const std::vector<std::vector<double>>& values,
                const std::vector<double>& jacobians)
{
  std::printf("%-20s %9s %14s %14s %14s %10s\n", "measure", "elements", "min", "mean", "max", "flagged");
  for (std::size_t m = 0; m < measures.size(); ++m)
  {
    const QualitySummary s = Summarize(values[m], jacobians, -std::numeric_limits<double>::infinity());
    if (s.count == 0)
      continue;
    std::printf("%-20s %9zu %14.6g %14.6g %14.6g %10zu\n", MeasureName(measures[m]), s.count, s.min, s.mean, s.max,
                s.degenerate);
  }
}

void WriteMesh(const FEMesh& mesh, const std::vector<Measure>& measures, const std::vector<std::vector<double>>& values,
               const std::string& path)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = ToVTK(mesh);
  if (grid->GetNumberOfCells() != static_cast<vtkIdType>(mesh.elements.size()))
    throw cli::ModuleError("internal: the VTK grid has " + std::to_string(grid->GetNumberOfCells()) + " cells for " +
                           std::to_string(mesh.elements.size()) + " elements");
  for (std::size_t m = 0; m < measures.size(); ++m)
  {
    vtkNew<vtkDoubleArray> array;
    array->SetName(MeasureName(measures[m]));
    array->SetNumberOfValues(static_cast<vtkIdType>(values[m].size()));
    for (std::size_t e = 0; e < values[m].size(); ++e)
      array->SetValue(static_cast<vtkIdType>(e), values[m][e]);
    grid->GetCellData()->AddArray(array);
  }
  {
    cli::AtomicOutput out(path);
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetFileName(out.TempPath().c_str());
    writer->SetInputData(grid);
    writer->SetDataModeToAppended();
    if (writer->Write() != 1)
      throw cli::ModuleError("cannot write output mesh '" + path + "'");
    out.Commit();
  }
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return cli::RunModule(argc, argv, MeshQualityXML, [](cli::ModuleContext& ctx) {
    const std::string input = ctx.args.String("inputMesh");
    const double threshold = ctx.args.Double("threshold");
    std::string output = ctx.args.Has("outputMesh") ? ctx.args.String("outputMesh") : "";
    if (!output.empty() && cli::FileExtension(output) != ".vtu")
      throw cli::ModuleError("outputMesh '" + output + "' must end in .vtu");

    ctx.progress.Start("Computing element quality");
    FEMesh mesh;
    try
    {
      mesh = ReadFEMesh(input);
    }
    catch (const std::exception& e)
    {
      throw cli::ModuleError(e.what());
    }
    if (mesh.SolidElementCount() == 0)
      throw cli::ModuleError("input mesh '" + input + "' has no solid elements");
    ctx.progress.Report(0.1);

    const std::vector<Measure>& measures = AllMeasures();
    QualityOptions options;
    options.progress = [&ctx](double f) { ctx.progress.ReportRange(0.1, 0.8, f); };
    std::vector<std::vector<double>> values;
    try
    {
      values = ComputeQuality(mesh, measures, options);
    }
    catch (const std::exception& e)
    {
      throw cli::ModuleError("input mesh '" + input + "': " + e.what());
    }
    const auto index = [&measures](Measure m) {
      return static_cast<std::size_t>(std::find(measures.begin(), measures.end(), m) - measures.begin());
    };
    const std::vector<double>& jacobians = values[index(Measure::Jacobian)];
    const QualitySummary summary = Summarize(values[index(Measure::ScaledJacobian)], jacobians, threshold);

    if (!output.empty())
      WriteMesh(mesh, measures, values, output);
    ctx.progress.Report(0.95);

    PrintTable(measures, values, jacobians);
    std::printf("scaled Jacobian: min %.6g mean %.6g; %zu of %zu elements below %g, %zu inverted, %zu degenerate\n",
                summary.min, summary.mean, summary.belowThreshold, summary.count, threshold, summary.inverted,
                summary.degenerate);
    std::fflush(stdout);

    ctx.outputs.Set("minScaledJacobian", summary.min);
    ctx.outputs.Set("meanScaledJacobian", summary.mean);
    ctx.outputs.Set("belowThreshold", static_cast<long long>(summary.belowThreshold));
    ctx.outputs.Set("invertedElements", static_cast<long long>(summary.inverted));
    ctx.outputs.Set("elementCount", static_cast<long long>(summary.count));
    ctx.progress.End();
  });
}
