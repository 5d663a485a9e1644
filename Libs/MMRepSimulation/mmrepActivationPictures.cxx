// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Activation pictures (see the header).
#include "mmrepActivationPictures.h"
#include "mmrepPointCloud.h"

#include "mmrepBoundaryFaces.h"
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
  const std::vector<char> skin = NodeSetMask(mesh, "skin");
  vtkSmartPointer<vtkPolyData> poly = BoundaryPolygons(mesh, &skin);
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
  poly->SetPoints(points);
  poly->GetPointData()->AddArray(magnitude);
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
        largest = std::max(largest,
                           result.displacements[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])].norm());
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
      const vtkIdType ids[2] = {linePoints->InsertNextPoint(mesh.nodes[i].data()),
                                linePoints->InsertNextPoint(end.data())};
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
