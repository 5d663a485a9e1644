// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFaceAtlasPictures.h"
#include "mmrepPointCloud.h"

#include "mmrepBoundaryFaces.h"
#include "mmrepFaceModelPictures.h"
#include "mmrepSnapshot.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>

#include <array>
#include <filesystem>
#include <functional>

namespace mmrep
{
namespace
{
// Outer surface of the solid elements selected by `keep` (element index -> bool).
vtkSmartPointer<vtkPolyData> SolidSurface(const FEMesh& mesh, const std::function<bool(std::size_t)>& keep)
{
  FEMesh part;
  part.nodes = mesh.nodes;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    if (mesh.elements[e].type != ElementType::Cable && keep(e))
      part.elements.push_back(mesh.elements[e]);
  return BoundaryPolygons(part);
}

std::array<double, 3> LayerColor(int layer)
{
  switch (layer)
  {
    case 1:
      return {0.95, 0.80, 0.70};
    case 2:
      return {0.85, 0.45, 0.40};
    default:
      return {0.95, 0.85, 0.35};
  }
}

// Layers: the left half (cut at the plane, seen from the right) and the whole face.
void WriteLayersPicture(const FEMesh& mesh, const std::string& png)
{
  const std::size_t half = mesh.SolidElementCount() / 2; // left elements come first
  std::vector<SnapshotLayer> layers;
  for (int layer = 1; layer <= 3; ++layer)
  {
    SnapshotLayer l;
    l.surface =
      SolidSurface(mesh, [&](std::size_t e) { return e < half && static_cast<int>(mesh.elements[e].layer) == layer; });
    l.color = LayerColor(layer);
    layers.push_back(l);
  }
  SnapshotOptions view;
  // Two views of 600 px: the default xvfb-run screen is 1280 px wide.
  view.views = {View::Anterior, View::Right};
  view.title = "left half: epidermis (light), dermis (red), hypodermis (yellow)";
  WriteSnapshot(layers, view, png);
}

void WriteLipsPicture(const FEMesh& mesh, const std::string& png)
{
  SnapshotLayer s, w, p, m;
  s.surface = SolidSurface(mesh, [&](std::size_t e) { return mesh.elements[e].layer == TissueLayer::Epidermis; });
  s.color = {0.9, 0.75, 0.65};
  w.surface = s.surface;
  w.wireframe = true;
  w.color = {0.3, 0.3, 0.3};
  std::vector<Point3> lips, marks;
  for (const auto n : mesh.nodeSets.at("lips"))
    lips.push_back(mesh.nodes[static_cast<std::size_t>(n)]);
  for (const auto& l : mesh.landmarks)
    marks.push_back(l.position);
  p.surface = PointCloud(lips);
  p.color = {0.1, 0.3, 0.9};
  p.pointSize = 6;
  m.surface = PointCloud(marks);
  m.color = {0.0, 0.8, 0.1};
  m.pointSize = 14;
  SnapshotOptions view;
  view.views = {View::Anterior, View::Left};
  view.title = "atlas skin mesh, lips nodes (blue), landmarks (green)";
  WriteSnapshot({s, w, p, m}, view, png);
}
} // namespace

void WriteFaceAtlasPictures(const FaceAtlas& atlas, const std::string& folder)
{
  namespace fs = std::filesystem;
  auto png = [&](const std::string& name) { return (fs::path(folder) / name).string(); };
  WriteLayersPicture(atlas.mesh, png("FaceAtlasLayers.png"));
  WriteLipsPicture(atlas.mesh, png("FaceAtlasLips.png"));
  WriteMusclesPicture(atlas.mesh, atlas.skinSurface, png("FaceAtlasMuscles.png"),
                      "atlas muscle tracks, one colour per muscle");
}

} // namespace mmrep
