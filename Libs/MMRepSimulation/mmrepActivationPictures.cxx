// Activation pictures (see the header).
#include "mmrepActivationPictures.h"

#include "mmrepSnapshot.h"

#include <Eigen/Geometry>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cstdio>
#include <map>

namespace mmrep::simulation
{
namespace
{
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

} // namespace

std::string ShortList(const std::vector<std::string>& names)
{
  std::string s;
  if (names.size() > 2)
    return names.front() + " + " + std::to_string(names.size() - 1) + " more";
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + n;
  return s;
}

double MaxSolidDisplacement(const FEMesh& mesh, const ActivationResult& result)
{
  double largest = 0;
  for (const auto& e : mesh.elements)
    if (e.type != ElementType::Cable)
      for (int k = 0; k < NodeCount(e.type); ++k)
        largest = std::max(largest, result.displacements[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])].norm());
  return largest;
}

void WriteActivationPictures(const FEMesh& mesh, const ActivationResult& result, double maxDisplacement,
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
  // Motion lines from rest to rest + u (true scale) at the skin nodes that move noticeably.
  const double magnify = 1.0;
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
  std::snprintf(caption, sizeof caption, "%s: deformed (|u| colour) over rest (white mesh), true scale; lines = u",
                title.c_str());
  const std::string fullTitle = caption;

  if (!picture.empty())
  {
    SnapshotOptions view;
    view.views = {View::Anterior, View::Left};
    view.title = fullTitle;
    WriteSnapshot(layers, view, picture);
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
    WriteSnapshot(layers, view, lipsPicture);
  }
}

} // namespace mmrep::simulation
