// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFaceModelPictures.h"

#include "mmrepSnapshot.h"
#include "mmrepSurfaceDistance.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStaticCellLocator.h>

#include <array>
#include <cmath>

namespace mmrep
{
namespace
{
const char* kError = "distance to the speaker's skin (mm)";

vtkSmartPointer<vtkPolyData> ColouredModelSkin(const FaceModelResult& r)
{
  auto surface = ModelSkinSurface(r.model);
  const auto d = NodeSurfaceDistances(r.model, "skin", r.skin);
  vtkNew<vtkDoubleArray> values;
  values->SetName(kError);
  values->SetNumberOfValues(static_cast<vtkIdType>(d.size()));
  for (std::size_t i = 0; i < d.size(); ++i)
    values->SetValue(static_cast<vtkIdType>(i), d[i]);
  surface->GetPointData()->SetScalars(values);
  return surface;
}

vtkSmartPointer<vtkPolyData> NodeCloud(const FEMesh& mesh, const std::string& set)
{
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts;
  if (const auto it = mesh.nodeSets.find(set); it != mesh.nodeSets.end())
    for (const auto n : it->second)
    {
      const vtkIdType id = points->InsertNextPoint(mesh.nodes[static_cast<std::size_t>(n)].data());
      verts->InsertNextCell(1, &id);
    }
  cloud->SetPoints(points);
  cloud->SetVerts(verts);
  return cloud;
}

SnapshotLayer SpeakerSkin(vtkPolyData* skin, double opacity)
{
  SnapshotLayer l;
  l.surface = skin;
  l.color = {0.85, 0.85, 0.85};
  l.opacity = opacity;
  return l;
}

SnapshotLayer ErrorLayer(vtkPolyData* surface)
{
  SnapshotLayer l;
  l.surface = surface;
  l.scalars = kError;
  l.range = {0.0, 1.0};
  l.scalarTitle = "mm";
  return l;
}
} // namespace

std::vector<double> NodeSurfaceDistances(const FEMesh& mesh, const std::string& set, vtkPolyData* surface)
{
  std::vector<double> d(mesh.nodes.size(), 0.0);
  const auto it = mesh.nodeSets.find(set);
  if (it == mesh.nodeSets.end())
    return d;
  const std::vector<double> measured = NodeSurfaceDistances(mesh.nodes, it->second, surface);
  for (std::size_t k = 0; k < measured.size(); ++k)
    d[static_cast<std::size_t>(it->second[k])] = measured[k];
  return d;
}

void WriteModelErrorPicture(const FaceModelResult& r, const std::string& pngPath)
{
  const auto model = ColouredModelSkin(r);
  SnapshotOptions view;
  view.title = "speaker model skin (coloured by distance to the speaker's skin, 0-1 mm) over the speaker's skin";
  // The face region only: the model's bounds plus a margin.
  double b[6];
  model->GetBounds(b);
  view.focus = {b[0] - 15, b[1] + 15, b[2] - 15, b[3] + 15, b[4] - 15, b[5] + 15};
  WriteSnapshot({SpeakerSkin(r.skin, 0.3), ErrorLayer(model)}, view, pngPath);
}

void WriteLipsPicture(const FaceModelResult& r, const std::string& pngPath)
{
  const auto model = ColouredModelSkin(r);
  const auto lips = NodeCloud(r.model, "lips");
  double b[6];
  lips->GetBounds(b);
  SnapshotLayer wire;
  wire.surface = model;
  wire.wireframe = true;
  wire.color = {0.2, 0.2, 0.2};
  wire.opacity = 0.5;
  SnapshotLayer nodes;
  nodes.surface = lips;
  nodes.color = {0.1, 0.3, 0.9};
  nodes.pointSize = 5;
  SnapshotOptions view;
  view.title = "lips close-up: model skin coloured by distance to the speaker's skin (0-1 mm), lips nodes blue";
  view.focus = {b[0] - 8, b[1] + 8, b[2] - 8, b[3] + 8, b[4] - 8, b[5] + 8};
  WriteSnapshot({SpeakerSkin(r.skin, 0.25), ErrorLayer(model), wire, nodes}, view, pngPath);
}

void WriteMusclesPicture(const FEMesh& model, vtkPolyData* skin, const std::string& pngPath, const std::string& title)
{
  // One colour per muscle (both sides share it); names ending in _L/_R or Left/Right pair up by
  // their order, so colours cycle over the sorted names.
  static const std::array<std::array<double, 3>, 13> palette = {{{0.90, 0.10, 0.10},
                                                                 {0.10, 0.50, 0.90},
                                                                 {0.10, 0.70, 0.20},
                                                                 {0.95, 0.60, 0.05},
                                                                 {0.60, 0.20, 0.80},
                                                                 {0.00, 0.75, 0.75},
                                                                 {0.85, 0.20, 0.60},
                                                                 {0.55, 0.35, 0.15},
                                                                 {0.40, 0.40, 0.40},
                                                                 {0.75, 0.75, 0.10},
                                                                 {0.10, 0.20, 0.55},
                                                                 {1.00, 0.40, 0.40},
                                                                 {0.30, 0.90, 0.50}}};
  std::vector<vtkSmartPointer<vtkPolyData>> tracks;
  std::vector<SnapshotLayer> layers;
  layers.push_back(SpeakerSkin(skin, 0.15));
  std::size_t k = 0;
  for (const auto& [name, track] : model.muscles)
  {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    std::vector<vtkIdType> ids;
    for (const auto n : track.nodes)
      ids.push_back(points->InsertNextPoint(model.nodes[static_cast<std::size_t>(n)].data()));
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    poly->SetPoints(points);
    poly->SetLines(lines);
    tracks.push_back(poly);
    SnapshotLayer l;
    l.surface = poly;
    l.color = palette[(k / 2) % palette.size()]; // tracks come in sorted left/right pairs
    l.lineWidth = 4;
    layers.push_back(l);
    ++k;
  }
  SnapshotOptions view;
  view.title = title;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const auto& t : tracks)
  {
    double b[6];
    t->GetBounds(b);
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], b[2 * a]);
      hi[a] = std::max(hi[a], b[2 * a + 1]);
    }
  }
  if (!tracks.empty())
    view.focus = {lo[0] - 20, hi[0] + 20, lo[1] - 20, hi[1] + 20, lo[2] - 20, hi[2] + 20};
  WriteSnapshot(layers, view, pngPath);
}

} // namespace mmrep
