// BuildFaceAtlas: reference head CT -> generic face atlas (mesh, landmarks, QC pictures).
#include "mmrepCLI.h"
#include "mmrepCTThresholds.h"
#include "mmrepFEMeshIO.h"
#include "mmrepFaceAtlas.h"
#include "mmrepHeadSegmentation.h"
#include "mmrepImageIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepMeshQuality.h"
#include "mmrepFaceModelPictures.h"
#include "mmrepFaceModelPipeline.h"
#include "mmrepSnapshot.h"
#include "mmrepSurfaceExtraction.h"
#include "mmrepSurfaceIO.h"
#include "mmrepSymmetryPlane.h"

#include <vtkCellArray.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>

extern const char BuildFaceAtlasXML[];

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// Outer surface of the solid elements selected by `keep` (element index -> bool).
vtkSmartPointer<vtkPolyData> SolidSurface(const mmrep::FEMesh& mesh, const std::function<bool(std::size_t)>& keep)
{
  mmrep::FEMesh part;
  part.nodes = mesh.nodes;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    if (mesh.elements[e].type != mmrep::ElementType::Cable && keep(e))
      part.elements.push_back(mesh.elements[e]);
  auto grid = mmrep::ToVTK(part);
  auto surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
  surface->SetInputData(grid);
  surface->Update();
  vtkSmartPointer<vtkPolyData> out = surface->GetOutput();
  return out;
}

vtkSmartPointer<vtkPolyData> NodePoints(const mmrep::FEMesh& mesh, const std::vector<std::int32_t>& nodes)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  for (auto n : nodes)
  {
    const vtkIdType id = points->InsertNextPoint(mesh.nodes[n].data());
    verts->InsertNextCell(1, &id);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  return poly;
}

vtkSmartPointer<vtkPolyData> LandmarkPoints(const mmrep::FEMesh& mesh)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& l : mesh.landmarks)
  {
    const vtkIdType id = points->InsertNextPoint(l.position.data());
    verts->InsertNextCell(1, &id);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  return poly;
}

void WritePictures(const mmrep::FaceAtlas& atlas, const std::string& folder)
{
  namespace fs = std::filesystem;
  const auto& mesh = atlas.mesh;
  const std::size_t half = mesh.SolidElementCount() / 2; // left elements come first
  auto png = [&](const std::string& name) { return (fs::path(folder) / name).string(); };
  auto layerColor = [](int layer) -> std::array<double, 3> {
    switch (layer)
    {
      case 1: return {0.95, 0.80, 0.70};
      case 2: return {0.85, 0.45, 0.40};
      default: return {0.95, 0.85, 0.35};
    }
  };
  // Layers: the left half (cut at the plane, seen from the right) and the whole face.
  {
    std::vector<vtkSmartPointer<vtkPolyData>> keep;
    std::vector<mmrep::SnapshotLayer> layers;
    for (int layer = 1; layer <= 3; ++layer)
    {
      keep.push_back(SolidSurface(mesh, [&](std::size_t e) {
        return e < half && static_cast<int>(mesh.elements[e].layer) == layer;
      }));
      mmrep::SnapshotLayer l;
      l.surface = keep.back();
      l.color = layerColor(layer);
      layers.push_back(l);
    }
    mmrep::SnapshotOptions view;
    // Two views of 600 px: the default xvfb-run screen is 1280 px wide.
    view.views = {mmrep::View::Anterior, mmrep::View::Right};
    view.title = "left half: epidermis (light), dermis (red), hypodermis (yellow)";
    mmrep::WriteSnapshot(layers, view, png("FaceAtlasLayers.png"));
  }
  auto skin = SolidSurface(mesh, [&](std::size_t e) { return mesh.elements[e].layer == mmrep::TissueLayer::Epidermis; });
  auto lips = NodePoints(mesh, mesh.nodeSets.at("lips"));
  auto marks = LandmarkPoints(mesh);
  {
    mmrep::SnapshotLayer s, w, p, m;
    s.surface = skin;
    s.color = {0.9, 0.75, 0.65};
    w.surface = skin;
    w.wireframe = true;
    w.color = {0.3, 0.3, 0.3};
    p.surface = lips;
    p.color = {0.1, 0.3, 0.9};
    p.pointSize = 6;
    m.surface = marks;
    m.color = {0.0, 0.8, 0.1};
    m.pointSize = 14;
    mmrep::SnapshotOptions view;
    view.views = {mmrep::View::Anterior, mmrep::View::Left};
    view.title = "atlas skin mesh, lips nodes (blue), landmarks (green)";
    mmrep::WriteSnapshot({s, w, p, m}, view, png("FaceAtlasLips.png"));
  }
  mmrep::WriteMusclesPicture(mesh, atlas.skinSurface, png("FaceAtlasMuscles.png"),
                             "atlas muscle tracks, one colour per muscle");
}

double Percentile(std::vector<double> v, double p)
{
  std::sort(v.begin(), v.end());
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(std::floor(p * (v.size() - 1) + 0.5)));
  return v[k];
}

void Run(mmrep::cli::ModuleContext& ctx)
{
  const auto& args = ctx.args;
  const auto start = Clock::now();
  std::vector<std::unique_ptr<mmrep::cli::AtomicOutput>> outputs;
  auto out = [&](const std::string& path) -> mmrep::cli::AtomicOutput& {
    outputs.push_back(std::make_unique<mmrep::cli::AtomicOutput>(path));
    return *outputs.back();
  };
  const std::string meshPath = args.String("outputMesh");
  const std::string meshFormat = mmrep::cli::FileExtension(meshPath);
  const auto writable = mmrep::WritableFEMeshExtensions();
  if (std::find(writable.begin(), writable.end(), meshFormat) == writable.end())
    throw mmrep::cli::ModuleError("outputMesh: unsupported extension '" + meshFormat + "' (use .vtu, .vtk, .inp, .feb or .msh)");
  auto& meshOut = out(meshPath);
  mmrep::cli::AtomicOutput* landmarksOut = args.Given("landmarks") ? &out(args.String("landmarks")) : nullptr;
  mmrep::cli::AtomicOutput* skinOut = args.Given("referenceSkin") ? &out(args.String("referenceSkin")) : nullptr;
  mmrep::cli::AtomicOutput* skullOut = args.Given("referenceSkull") ? &out(args.String("referenceSkull")) : nullptr;
  std::string pictures;
  if (args.Given("pictures"))
  {
    pictures = args.String("pictures");
    if (!std::filesystem::is_directory(pictures))
      throw mmrep::cli::ModuleError("pictures: '" + pictures + "' is not an existing folder");
  }
  if (landmarksOut)
  {
    const auto ext = mmrep::cli::FileExtension(landmarksOut->FinalPath());
    if (ext != ".mrk.json" && ext != ".fcsv")
      throw mmrep::cli::ModuleError("landmarks: unsupported extension '" + ext + "' (use .mrk.json or .fcsv)");
  }

  mmrep::FaceAtlasOptions options;
  options.meshSize = args.Double("meshSize");
  options.lipsMeshSize = args.Double("lipsMeshSize");
  if (options.lipsMeshSize > options.meshSize)
    throw mmrep::cli::ModuleError("lipsMeshSize: must not exceed meshSize");
  options.lateralAngle = args.Double("lateralAngle");
  options.browMargin = args.Double("browMargin");
  options.chinMargin = args.Double("chinMargin");
  options.maxBoneDepth = args.Double("maxBoneDepth");
  options.minThickness = args.Double("minThickness");
  options.normalBlend = args.Double("normalBlend");
  options.qualityThreshold = args.Double("qualityThreshold");
  const auto ratios = args.Doubles("layerRatios");
  if (ratios.size() != 3 || std::any_of(ratios.begin(), ratios.end(), [](double r) { return !(r > 0); }))
    throw mmrep::cli::ModuleError("layerRatios: give three positive values (epidermis, dermis, hypodermis)");
  options.layerRatios = {ratios[0], ratios[1], ratios[2]};

  // VTK's threaded locators (vtkSMPTools sorts) make the symmetry plane's ICP differ in the 5th
  // digit from run to run; the sequential backend makes the atlas reproducible bit for bit.
  vtkSMPTools::SetBackend("Sequential");
  ctx.progress.Start("Building the face atlas");
  // 1. Skin and bone surfaces, symmetry plane.
  const auto ct = mmrep::ReadCTImage(args.String("inputVolume"));
  // Surfaces and plane exactly as FaceModelPipeline makes them for a speaker: the atlas's own CT
  // then gives the atlas's plane to the last bit, and registering the atlas onto it starts from
  // the identity.
  const mmrep::FaceModelOptions pipeline;
  const auto surfaces =
    mmrep::ExtractSubjectSurfaces(ct, pipeline, [&](double f) { ctx.progress.ReportRange(0.0, 0.3, f); });
  const auto& thresholds = surfaces.thresholds;
  auto skin = surfaces.skin;
  auto skull = surfaces.skull;
  const double tSurfaces = Seconds(start);
  ctx.progress.Report(0.4);
  const auto symmetry = mmrep::EstimateSubjectPlane(skin, pipeline);
  const double tPlane = Seconds(start);
  std::cout << "Surfaces " << tSurfaces << " s, plane " << tPlane - tSurfaces << " s" << std::endl;
  std::cout << std::setprecision(6) << "Thresholds (" << thresholds.source << "): skin " << thresholds.skin << ", bone "
            << thresholds.bone << "\nSymmetry plane: point " << symmetry.plane.point.transpose() << ", normal "
            << symmetry.plane.normal.transpose() << ", RMS residual " << symmetry.rmsResidual << " mm\n";
  ctx.progress.Report(0.5);

  // 2-6. The atlas.
  const auto atlas = mmrep::BuildFaceAtlas(skin, skull, symmetry.plane, options,
                                           [&](double f) { ctx.progress.ReportRange(0.5, 0.9, f); });
  const double tAtlas = Seconds(start);
  for (const auto& line : atlas.log)
    std::cout << line << "\n";

  // Quality summary (independent of the construction's own checks).
  const auto& mesh = atlas.mesh;
  mmrep::quality::QualityOptions qo;
  qo.threads = 1;
  const auto sj = mmrep::quality::ComputeQuality(mesh, mmrep::quality::Measure::ScaledJacobian, qo);
  const auto jac = mmrep::quality::ComputeQuality(mesh, mmrep::quality::Measure::Jacobian, qo);
  const auto summary = mmrep::quality::Summarize(sj, jac, options.qualityThreshold);
  std::vector<double> defined;
  for (double v : sj)
    if (!std::isnan(v))
      defined.push_back(v);
  std::cout << "Scaled Jacobian: min " << summary.min << ", 1% " << Percentile(defined, 0.01) << ", 5% "
            << Percentile(defined, 0.05) << ", median " << Percentile(defined, 0.5) << ", mean " << summary.mean
            << ", max " << summary.max << "; inverted " << summary.inverted << ", below " << options.qualityThreshold
            << ": " << summary.belowThreshold << "\n";
  if (summary.inverted > 0 || summary.belowThreshold > 0)
    throw mmrep::cli::ModuleError("the atlas does not reach the quality threshold (" +
                                  std::to_string(summary.belowThreshold) + " elements below " +
                                  std::to_string(options.qualityThreshold) + ", " + std::to_string(summary.inverted) +
                                  " inverted)");

  mmrep::WriteFEMesh(mesh, meshOut.TempPath(), meshFormat.substr(1));
  if (landmarksOut)
  {
    const auto ext = mmrep::cli::FileExtension(landmarksOut->FinalPath());
    mmrep::WriteLandmarks(mesh.landmarks, landmarksOut->TempPath(), ext.substr(1), mmrep::CoordinateSystem::LPS);
  }
  if (skinOut)
    mmrep::WriteSurface(atlas.skinSurface, skinOut->TempPath(), mmrep::cli::FileExtension(skinOut->FinalPath()));
  if (skullOut)
    mmrep::WriteSurface(atlas.skullSurface, skullOut->TempPath(), mmrep::cli::FileExtension(skullOut->FinalPath()));
  ctx.progress.Report(0.95);
  if (!pictures.empty())
    WritePictures(atlas, pictures);
  for (auto& o : outputs)
    o->Commit();

  std::size_t cables = mesh.elements.size() - mesh.SolidElementCount();
  std::cout << "Atlas: " << mesh.nodes.size() << " nodes, " << mesh.SolidElementCount() << " hexahedra, " << cables
            << " cables, " << mesh.muscles.size() << " muscle tracks; lips " << mesh.nodeSets.at("lips").size()
            << ", skin " << mesh.nodeSets.at("skin").size() << ", skull " << mesh.nodeSets.at("skull").size()
            << ", inner " << mesh.nodeSets.at("inner").size() << ", midsagittal "
            << mesh.nodeSets.at("midsagittal").size() << " nodes\n"
            << "Timings: surfaces " << tSurfaces << " s, symmetry plane " << tPlane - tSurfaces << " s, atlas "
            << tAtlas - tPlane << " s, total " << Seconds(start) << " s" << std::endl;
  ctx.outputs.Set("nodeCount", static_cast<long long>(mesh.nodes.size()));
  ctx.outputs.Set("elementCount", static_cast<long long>(mesh.SolidElementCount()));
  ctx.outputs.Set("cableCount", static_cast<long long>(cables));
  ctx.outputs.Set("lipsNodeCount", static_cast<long long>(mesh.nodeSets.at("lips").size()));
  ctx.outputs.Set("minScaledJacobian", summary.min);
  ctx.outputs.Set("meanScaledJacobian", summary.mean);
  ctx.outputs.Set("invertedElements", static_cast<long long>(summary.inverted));
  ctx.progress.End();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, BuildFaceAtlasXML, Run);
}
