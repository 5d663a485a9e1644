// SimulateMuscleActivation: muscle activation of a speaker FE face model with CalculiX; deformed
// model (.vtu with the displacement), before/after pictures, landmark displacements.
#include "mmrepCLI.h"
#include "mmrepFEMeshIO.h"
#include "mmrepMuscleActivation.h"
#include "mmrepSnapshot.h"

#include <Eigen/Geometry>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

extern const char SimulateMuscleActivationXML[];

namespace
{
using namespace mmrep;
namespace sim = mmrep::simulation;

std::string JoinNames(const std::vector<std::string>& names)
{
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + n;
  return s;
}

// "A", "A + B", or "A + 3 more": fits a picture title.
std::string ShortList(const std::vector<std::string>& names)
{
  if (names.size() <= 2)
    return JoinNames(names);
  return names.front() + " + " + std::to_string(names.size() - 1) + " more";
}

// Boundary faces of the solids whose nodes all belong to the skin set, at the given positions, with
// the displacement magnitude as point data.
vtkSmartPointer<vtkPolyData> SkinSurface(const FEMesh& mesh, const std::vector<Point3>& positions,
                                         const std::vector<Point3>& displacements)
{
  static const std::vector<std::vector<int>> hexFaces{{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                                      {3, 0, 4, 7}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  static const std::vector<std::vector<int>> wedgeFaces{{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
  static const std::vector<std::vector<int>> tetFaces{{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {0, 2, 1}};
  std::vector<char> skin(mesh.nodes.size(), 0);
  if (const auto it = mesh.nodeSets.find("skin"); it != mesh.nodeSets.end())
    for (auto n : it->second)
      skin[static_cast<std::size_t>(n)] = 1;
  std::map<std::vector<std::int32_t>, std::pair<int, std::vector<std::int32_t>>> faces;
  for (const auto& e : mesh.elements)
  {
    const auto* table = e.type == ElementType::Hexahedron ? &hexFaces
                        : e.type == ElementType::Wedge    ? &wedgeFaces
                        : e.type == ElementType::Tetrahedron ? &tetFaces
                                                             : nullptr;
    if (table == nullptr)
      continue;
    for (const auto& f : *table)
    {
      std::vector<std::int32_t> ids;
      for (int k : f)
        ids.push_back(e.nodes[static_cast<std::size_t>(k)]);
      auto key = ids;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      ++entry.first;
      entry.second = ids;
    }
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
  vtkNew<vtkDoubleArray> magnitude;
  magnitude->SetName("DisplacementMagnitude");
  magnitude->SetNumberOfValues(static_cast<vtkIdType>(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), positions[i].data());
    magnitude->SetValue(static_cast<vtkIdType>(i), displacements[i].norm());
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& [key, entry] : faces)
  {
    if (entry.first != 1)
      continue;
    if (!std::all_of(key.begin(), key.end(), [&](std::int32_t n) { return skin[static_cast<std::size_t>(n)] != 0; }))
      continue;
    polys->InsertNextCell(static_cast<vtkIdType>(entry.second.size()));
    for (auto n : entry.second)
      polys->InsertCellPoint(n);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->GetPointData()->AddArray(magnitude);
  return poly;
}

vtkSmartPointer<vtkPolyData> PointCloud(const std::vector<Point3>& pts)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts;
  for (const auto& p : pts)
  {
    const vtkIdType id = points->InsertNextPoint(p.data());
    verts->InsertNextCell(1, &id);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  return poly;
}

void WritePictures(const FEMesh& mesh, const sim::ActivationResult& result, double maxDisplacement,
                   const std::string& picture, const std::string& lipsPicture, const std::string& title)
{
  std::vector<Point3> deformed(mesh.nodes.size());
  for (std::size_t i = 0; i < deformed.size(); ++i)
    deformed[i] = mesh.nodes[i] + result.displacements[i];
  const auto restSkin = SkinSurface(mesh, mesh.nodes, result.displacements);
  const auto newSkin = SkinSurface(mesh, deformed, result.displacements);
  std::vector<Point3> restMarks, newMarks;
  for (const auto& m : result.landmarks)
  {
    restMarks.push_back(m.rest);
    newMarks.push_back(m.rest + m.displacement);
  }
  const auto restPts = PointCloud(restMarks), newPts = PointCloud(newMarks);
  // Motion lines from rest to rest + m·u at the skin nodes that move noticeably (m: longest line 10 mm).
  const double magnify = std::max(1.0, std::round(10 / std::max(maxDisplacement, 1e-6)));
  vtkNew<vtkPoints> linePoints;
  vtkNew<vtkCellArray> lines;
  if (const auto it = mesh.nodeSets.find("skin"); it != mesh.nodeSets.end())
    for (auto n : it->second)
    {
      const auto i = static_cast<std::size_t>(n);
      if (result.displacements[i].norm() < 0.2 * maxDisplacement)
        continue;
      const Point3 end = mesh.nodes[i] + magnify * result.displacements[i];
      const vtkIdType ids[2] = {linePoints->InsertNextPoint(mesh.nodes[i].data()), linePoints->InsertNextPoint(end.data())};
      lines->InsertNextCell(2, ids);
    }
  auto motion = vtkSmartPointer<vtkPolyData>::New();
  motion->SetPoints(linePoints);
  motion->SetLines(lines);

  SnapshotLayer after, before, marksBefore, marksAfter, arrows;
  after.surface = newSkin;
  after.scalars = "DisplacementMagnitude";
  after.range = {0, std::max(maxDisplacement, 1e-6)};
  after.scalarTitle = "|u| (mm)";
  before.surface = restSkin;
  before.wireframe = true;
  before.color = {1, 1, 1};
  before.opacity = 0.3;
  marksBefore.surface = restPts;
  marksBefore.color = {0, 0, 0};
  marksBefore.pointSize = 12;
  marksAfter.surface = newPts;
  marksAfter.color = {1, 1, 1};
  marksAfter.pointSize = 12;
  arrows.surface = motion;
  arrows.color = {0, 0, 0};
  arrows.lineWidth = 2;
  const std::vector<SnapshotLayer> layers{after, before, arrows, marksBefore, marksAfter};
  char caption[160];
  std::snprintf(caption, sizeof caption, "%s: |u| colour, rest = white mesh, lines = u x%g", title.c_str(), magnify);
  const std::string fullTitle = caption;

  if (!picture.empty())
  {
    cli::AtomicOutput out(picture);
    SnapshotOptions view;
    view.views = {View::Anterior, View::Left};
    view.title = fullTitle;
    WriteSnapshot(layers, view, out.TempPath());
    out.Commit();
  }
  if (!lipsPicture.empty())
  {
    Eigen::AlignedBox3d box;
    if (const auto it = mesh.nodeSets.find("lips"); it != mesh.nodeSets.end() && !it->second.empty())
      for (auto n : it->second)
        box.extend(mesh.nodes[static_cast<std::size_t>(n)]);
    else
      for (const auto& m : restMarks)
        box.extend(m);
    SnapshotOptions view;
    view.views = {View::Anterior, View::Left};
    view.title = fullTitle;
    const double margin = 8;
    view.focus = {box.min().x() - margin, box.max().x() + margin, box.min().y() - margin,
                  box.max().y() + margin, box.min().z() - margin, box.max().z() + margin};
    cli::AtomicOutput out(lipsPicture);
    WriteSnapshot(layers, view, out.TempPath());
    out.Commit();
  }
}

void WriteDeformedModel(const FEMesh& mesh, const sim::ActivationResult& result, const std::string& path)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = ToVTK(sim::DeformedMesh(mesh, result));
  vtkNew<vtkDoubleArray> u, magnitude;
  u->SetName("Displacement");
  u->SetNumberOfComponents(3);
  u->SetNumberOfTuples(static_cast<vtkIdType>(mesh.nodes.size()));
  magnitude->SetName("DisplacementMagnitude");
  magnitude->SetNumberOfValues(static_cast<vtkIdType>(mesh.nodes.size()));
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
  {
    u->SetTuple(static_cast<vtkIdType>(i), result.displacements[i].data());
    magnitude->SetValue(static_cast<vtkIdType>(i), result.displacements[i].norm());
  }
  grid->GetPointData()->AddArray(u);
  grid->GetPointData()->AddArray(magnitude);
  grid->GetPointData()->SetActiveVectors("Displacement");
  cli::AtomicOutput out(path);
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(out.TempPath().c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  if (writer->Write() != 1)
    throw cli::ModuleError("cannot write output model '" + path + "'");
  out.Commit();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return cli::RunModule(argc, argv, SimulateMuscleActivationXML, [](cli::ModuleContext& ctx) {
    const std::string input = ctx.args.String("inputModel");
    const std::string output = ctx.args.String("outputModel");
    const std::string picture = ctx.args.Has("picture") ? ctx.args.String("picture") : "";
    const std::string lipsPicture = ctx.args.Has("lipsPicture") ? ctx.args.String("lipsPicture") : "";
    if (cli::FileExtension(output) != ".vtu")
      throw cli::ModuleError("outputModel '" + output + "' must end in .vtu");
    for (const auto& png : {picture, lipsPicture})
      if (!png.empty() && cli::FileExtension(png) != ".png")
        throw cli::ModuleError("picture '" + png + "' must end in .png");

    ctx.progress.Start("Simulating muscle activation with CalculiX");
    FEMesh mesh;
    try
    {
      mesh = ReadFEMesh(input);
    }
    catch (const std::exception& e)
    {
      throw cli::ModuleError(e.what());
    }
    if (mesh.muscles.empty())
      throw cli::ModuleError("input model '" + input + "' has no muscles: a speaker model with muscle tracks is needed");
    const std::vector<std::string> names = ctx.args.Strings("muscles");
    if (names.empty())
      throw cli::ModuleError("no muscle given (--muscles); the model's muscles are: " + JoinNames(sim::MuscleNames(mesh)));
    std::vector<double> levels = ctx.args.Doubles("activations");
    if (levels.size() == 1)
      levels.assign(names.size(), levels.front());
    if (levels.size() != names.size())
      throw cli::ModuleError("--activations has " + std::to_string(levels.size()) + " values for " +
                             std::to_string(names.size()) + " muscles (give one, or one per muscle)");
    const std::vector<double> scale = ctx.args.Doubles("layerScale");
    if (scale.size() != 3 || !std::all_of(scale.begin(), scale.end(), [](double s) { return s > 0; }))
      throw cli::ModuleError("--layerScale needs three positive factors (epidermis, dermis, hypodermis)");

    sim::ActivationOptions options;
    for (std::size_t i = 0; i < names.size(); ++i)
      options.deck.activations.push_back({names[i], levels[i]});
    try
    {
      sim::HyperelasticMaterial base = sim::FaceTissue(ctx.args.Double("poissonRatio"));
      const double c10 = ctx.args.Double("c10") * 1e-6, c20 = ctx.args.Double("c20") * 1e-6; // Pa -> N/mm²
      if (!(c10 > 0) || c20 < 0)
        throw cli::ModuleError("--c10 must be positive and --c20 not negative (Pa)");
      const double d1Factor = base.ShearModulus() / (2 * c10); // keep the Poisson ratio
      base.c10 = c10;
      base.c20 = c20;
      base.d1 *= d1Factor;
      options.deck.materials.fill(base);
      for (int layer = 1; layer <= 3; ++layer)
      {
        sim::HyperelasticMaterial& m = options.deck.materials[static_cast<std::size_t>(layer)];
        const double s = scale[static_cast<std::size_t>(layer - 1)];
        m.c10 *= s;
        m.c20 *= s;
        m.d1 /= s;
      }
      options.deck.hexahedronType = ctx.args.String("elementType");
      options.deck.cables.forceScale = ctx.args.Double("forceScale");
      options.deck.step.maxIncrements = static_cast<int>(ctx.args.Int("maxIncrements"));
      options.deck.step.initialIncrement = ctx.args.Double("initialIncrement");
      options.deck.step.minIncrement = std::min(options.deck.step.minIncrement, options.deck.step.initialIncrement);
      sim::CheckActivations(mesh, options.deck.activations);
      if (ctx.args.Bool("lipSupport"))
        options.deck.slidingNodes = sim::LipSupportNodes(mesh);
      options.run.executable = ctx.args.Has("ccx") ? ctx.args.String("ccx") : "";
      sim::FindCalculiX(options.run.executable);
      if (!picture.empty())
        RequireDisplay(picture);
      if (!lipsPicture.empty())
        RequireDisplay(lipsPicture);
    }
    catch (const cli::ModuleError&)
    {
      throw;
    }
    catch (const std::exception& e)
    {
      throw cli::ModuleError(e.what());
    }
    options.run.threads = static_cast<int>(ctx.args.Int("threads"));
    options.run.keepDirectory = ctx.args.Bool("keepJob");
    options.run.progress = [&ctx](double t) { ctx.progress.ReportRange(0.1, 0.8, t); };
    ctx.progress.Report(0.1);

    sim::ActivationResult result;
    try
    {
      result = sim::SimulateMuscleActivation(mesh, options);
    }
    catch (const std::exception& e)
    {
      throw cli::ModuleError(std::string("input model '") + input + "': " + e.what());
    }
    if (options.run.keepDirectory)
      std::printf("CalculiX job folder kept: %s\n", result.run.directory.c_str());
    ctx.progress.Report(0.8);

    double maxDisplacement = 0;
    for (const auto& e : mesh.elements)
      if (e.type != ElementType::Cable)
        for (int k = 0; k < NodeCount(e.type); ++k)
          maxDisplacement = std::max(maxDisplacement, result.displacements[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])].norm());

    std::printf("CalculiX: converged in %d increments, %d iterations, %d cutbacks, %.1f s (%d threads); "
                "%zu solids, %zu cables, %zu equations, %zu fixed nodes, %zu sliding nodes, %zu symmetry-plane nodes\n",
                result.run.increments, result.run.iterations, result.run.cutbacks, result.run.seconds,
                options.run.threads, result.deck.solids, result.deck.springs, result.deck.equations,
                result.deck.fixedNodes, result.deck.slidingNodes, result.deck.symmetryNodes);
    for (const auto& m : result.muscles)
      std::printf("muscle %-36s activation %.2f  length %.1f -> %.1f mm (%+.1f %%)  cable force mean %.3f N, max %.3f N\n",
                  m.muscle.c_str(), m.level, m.restLength, m.length, 100 * (m.length / m.restLength - 1), m.meanForce,
                  m.maxForce);
    std::printf("%-22s %9s %9s %9s %9s   (mm; +x patient left, -y anterior, +z superior)\n", "landmark", "ux", "uy", "uz", "|u|");
    for (const auto& m : result.landmarks)
      std::printf("%-22s %9.3f %9.3f %9.3f %9.3f   %s\n", m.name.c_str(), m.displacement.x(), m.displacement.y(),
                  m.displacement.z(), m.displacement.norm(),
                  m.element >= 0 ? ("element " + std::to_string(m.element)).c_str() : "nearest node");
    std::printf("largest node displacement %.3f mm\n", maxDisplacement);
    std::fflush(stdout);

    WriteDeformedModel(mesh, result, output);
    ctx.progress.Report(0.85);
    if (!picture.empty() || !lipsPicture.empty())
    {
      try
      {
        WritePictures(mesh, result, maxDisplacement, picture, lipsPicture, ShortList(result.deck.activeMuscles));
      }
      catch (const cli::ModuleError&)
      {
        throw;
      }
      catch (const std::exception& e)
      {
        throw cli::ModuleError(e.what());
      }
    }

    for (const auto& [param, name] : std::vector<std::pair<std::string, std::string>>{
           {"leftLipCornerDisplacement", "LeftLipCorner"},
           {"upperLipCenterDisplacement", "UpperLipCenter"},
           {"lowerLipCenterDisplacement", "LowerLipCenter"}})
      for (const auto& m : result.landmarks)
        if (m.name == name)
          ctx.outputs.Set(param, std::vector<double>{m.displacement.x(), m.displacement.y(), m.displacement.z()});
    double meanForce = 0;
    for (const auto& m : result.muscles)
      meanForce += m.meanForce / static_cast<double>(result.muscles.size());
    ctx.outputs.Set("maxDisplacement", maxDisplacement);
    ctx.outputs.Set("meanMuscleForce", meanForce);
    ctx.outputs.Set("ccxSeconds", result.run.seconds);
    ctx.outputs.Set("increments", result.run.increments);
    ctx.outputs.Set("iterations", result.run.iterations);
    ctx.progress.End();
  });
}
