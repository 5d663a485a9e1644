// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The files of a speaker model run (see the header); the module FaceModelPipeline stages the directory.
#include "mmrepFaceModelOutputs.h"

#include "mmrepDisplacementFieldMap.h"
#include "mmrepFEMeshIO.h"
#include "mmrepFaceModelPictures.h"
#include "mmrepHalfModel.h"
#include "mmrepImageIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepRepairSummary.h"
#include "mmrepSurfaceIO.h"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace mmrep
{
namespace
{
namespace fs = std::filesystem;

void WriteText(const fs::path& path, const std::string& text)
{
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f)
    throw std::runtime_error(path.string() + ": cannot write");
}

// The output files and what each holds (listed in the report), in the order the report gives them.
std::vector<std::pair<std::string, std::string>> OutputFiles(const FaceModelOutputOptions& options)
{
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
  if (options.pictures)
  {
    files.emplace_back("model-skin-error.png", "model skin coloured by distance to the speaker's skin, front and left");
    files.emplace_back("lips.png", "lips close-up, front and left");
    files.emplace_back("muscles.png", "the speaker's inferred muscle tracks, front and left");
  }
  if (options.halfModel)
    files.emplace_back(
      "half-model.vtu",
      "the left half of the model, symmetry boundary in node set symmetryBoundary (also .inp, .feb, .msh)");
  return files;
}

void WriteModelFormats(const FEMesh& mesh, const fs::path& directory, const std::string& stem)
{
  for (const char* format : {"vtu", "inp", "feb", "msh"})
    WriteFEMesh(mesh, (directory / (stem + "." + format)).string(), format);
}

} // namespace

void WriteFaceModelOutputs(const FaceModelResult& result, const FEMesh& atlas, FaceModelOutputOptions options,
                           const fs::path& dir, const std::function<void(double)>& progress)
{
  const auto report = [&](double f) {
    if (progress)
      progress(f);
  };
  options.report.files = OutputFiles(options);
  WriteModelFormats(result.model, dir, "model");
  if (options.halfModel)
    WriteModelFormats(LeftHalfModel(result.model), dir, "half-model");
  report(0.2);
  const auto field = SampleDisplacementField([&](const Point3& x) { return result.AtlasToSubject(x); }, atlas.nodes,
                                             10.0, options.transformSpacing);
  WriteDisplacementField(field, (dir / "transform.nrrd").string());
  WriteSurface(result.skin, (dir / "skin.vtp").string());
  WriteSurface(result.skull, (dir / "skull.vtp").string());
  WriteLandmarks(result.model.landmarks, (dir / "landmarks.mrk.json").string());
  report(0.5);
  if (options.pictures)
  {
    WriteModelErrorPicture(result, (dir / "model-skin-error.png").string());
    WriteLipsPicture(result, (dir / "lips.png").string());
    WriteMusclesPicture(result.model, result.skin, (dir / "muscles.png").string(),
                        "inferred muscle tracks (one colour per muscle) in the speaker's face");
  }
  WriteText(dir / "report.json", FaceModelReportJson(result, options.report));
  WriteText(dir / "report.md", FaceModelReportMarkdown(result, options.report));
  if (options.intermediates)
  {
    WriteFEMesh(result.registered, (dir / "registered.vtu").string());
    WriteFEMesh(result.refined, (dir / "refined.vtu").string());
  }
  report(1.0);
}

std::string RepairFailureMessage(const FaceModelResult& result, double qualityThreshold, const fs::path& finalDirectory)
{
  return "repair could not make every element valid: " + RepairFailureMessage(result.repair, qualityThreshold) +
         "; nothing written to " + finalDirectory.string() + " (lower --qualityThreshold or check the control points)";
}

double ControlPointMeanError(const FaceModelResult& result)
{
  const auto& a = result.accuracy.back();
  double mean = 0;
  for (double e : a.controlErrors)
    mean += e / static_cast<double>(a.controlErrors.size());
  return mean;
}

std::string FaceModelSummary(const FaceModelResult& result)
{
  const auto& a = result.accuracy.back();
  std::ostringstream s;
  s << "Model: " << result.model.nodes.size() << " nodes, " << result.model.SolidElementCount()
    << " solid elements; fitted " << result.fitted << ": skin " << a.skinHalf.mean << " mm mean, skull "
    << a.skullHalf.mean << " mm mean, lips " << a.lipsHalf.max << " mm max (whole model: skin " << a.skin.mean
    << ", skull " << a.skull.mean << ", lips max " << a.lips.max << "); control points "
    << ControlPointMeanError(result) << " mm mean; min scaled Jacobian " << result.repair.minScaledJacobianAfter << "; "
    << result.totalSeconds << " s";
  return s.str();
}

} // namespace mmrep
