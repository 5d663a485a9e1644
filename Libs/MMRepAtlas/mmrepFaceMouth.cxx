// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The atlas's mouth slit and jaw (rules in mmrepFaceMouth.h).
#include "mmrepFaceMouth.h"

#include <Eigen/Geometry>

#include "mmrepJaw.h"
#include "mmrepLipContact.h"

#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace mmrep
{
namespace
{

int Nearest(const std::vector<double>& values, double x)
{
  int best = 0;
  for (int i = 1; i < static_cast<int>(values.size()); ++i)
    if (std::abs(values[static_cast<std::size_t>(i)] - x) < std::abs(values[static_cast<std::size_t>(best)] - x))
      best = i;
  return best;
}

} // namespace

MouthSlitCells MouthSlitCellsOf(const FaceGrid& grid, const FaceLandmarkSet& landmarks)
{
  MouthSlitCells c;
  c.slitRow = Nearest(grid.phi, landmarks.stomion.phi);
  c.cornerColumn = Nearest(grid.theta, landmarks.lipCorner.theta);
  c.lowRow = Nearest(grid.phi, landmarks.labiomental.phi);
  c.highRow = Nearest(grid.phi, landmarks.subnasale.phi);
  if (!(c.lowRow < c.slitRow && c.slitRow < c.highRow && c.cornerColumn >= 1 && c.cornerColumn + 1 < grid.Cols()))
    throw std::runtime_error(
      "face atlas: the mouth (labiomental fold, stomion, subnasale, corner) does not span the grid");
  return c;
}

std::size_t CutMouthSlit(FEMesh& mesh, const FaceGrid& grid, const MouthSlitCells& cells)
{
  const int s = cells.slitRow, jc = cells.cornerColumn;
  std::map<std::int32_t, std::int32_t> twin;
  std::vector<std::int32_t> upperContact, lowerContact;
  for (int side = 0; side < 2; ++side)
    for (int j = side; j <= jc; ++j)
      for (int k = 0; k < 4; ++k)
      {
        const auto n = static_cast<std::int32_t>(grid.Node(s, j, k, side));
        upperContact.push_back(n);
        if (j == jc)
        {
          lowerContact.push_back(n);
          continue;
        }
        const auto t = static_cast<std::int32_t>(mesh.nodes.size());
        mesh.nodes.push_back(mesh.nodes[static_cast<std::size_t>(n)]);
        twin[n] = t;
        lowerContact.push_back(t);
      }
  // A twin mirrors its partner's mirror's twin (the slit is cut on both sides alike).
  for (const auto& [node, t] : twin)
    if (mesh.HasMirrorMap())
      mesh.SetMirrorPartners(t, twin.at(mesh.mirror[static_cast<std::size_t>(node)]));
  auto& upperLip = mesh.elementSets[kUpperLipSet];
  auto& lowerLip = mesh.elementSets[kLowerLipSet];
  for (int side = 0; side < 2; ++side)
    for (int i = cells.lowRow; i < cells.highRow; ++i)
      for (int j = 0; j < jc; ++j)
        for (int layer = 0; layer < 3; ++layer)
        {
          const auto e = static_cast<std::int32_t>(grid.Element(i, j, layer, side));
          if (i >= s)
          {
            upperLip.push_back(e);
            continue;
          }
          lowerLip.push_back(e);
          for (auto& node : mesh.elements[static_cast<std::size_t>(e)].nodes)
            if (const auto it = twin.find(node); it != twin.end())
              node = it->second;
        }
  // A twin is the same anatomical point as its partner: same sets.
  for (auto& [name, ids] : mesh.nodeSets)
  {
    const std::size_t count = ids.size();
    for (std::size_t a = 0; a < count; ++a)
      if (const auto it = twin.find(ids[a]); it != twin.end())
        ids.push_back(it->second);
    std::sort(ids.begin(), ids.end());
  }
  for (auto* set : {&upperContact, &lowerContact, &upperLip, &lowerLip})
    std::sort(set->begin(), set->end());
  mesh.nodeSets[kUpperLipContactSet] = upperContact;
  mesh.nodeSets[kLowerLipContactSet] = lowerContact;
  return twin.size();
}

std::string AddJaw(FEMesh& mesh, vtkPolyData* skullLocal, const FaceFrame& frame, const FaceLandmarkSet& landmarks,
                   const CondyleOffsets& offsets)
{
  const auto skullIt = mesh.nodeSets.find("skull");
  if (skullIt == mesh.nodeSets.end() || skullIt->second.empty())
    throw std::runtime_error("face atlas: no skull nodes to split into maxilla and mandible");
  Eigen::Vector3d estimate = landmarks.eyeOuter.local;
  estimate.x() = offsets.lateral;
  estimate.y() -= offsets.posterior;
  estimate.z() -= offsets.inferior;
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(skullLocal);
  locator->BuildLocator();
  Eigen::Vector3d condyle;
  vtkNew<vtkGenericCell> cell;
  vtkIdType id = -1;
  int sub = 0;
  double d2 = 0;
  locator->FindClosestPoint(estimate.data(), condyle.data(), cell, id, sub, d2);
  // The atlas is symmetric: the right condyle is the left one's mirror image.
  Eigen::Vector3d mirrored = condyle;
  mirrored.x() = -mirrored.x();
  const Point3 left = frame.ToWorld(condyle), right = frame.ToWorld(mirrored);
  const auto leftNode = static_cast<std::int32_t>(mesh.nodes.size());
  mesh.nodes.push_back(left);
  mesh.nodes.push_back(right);
  mesh.nodeSets[kJawAxisSet] = {leftNode, leftNode + 1};
  mesh.SetMirrorPartners(leftNode, leftNode + 1);

  const Point3 stomion = frame.ToWorld(landmarks.stomion.local);
  Point3 normal = (right - left).cross(stomion - left).normalized();
  if (normal.dot(frame.ToWorld(landmarks.pogonion.local) - left) > 0)
    normal = -normal; // below the plane: normal·(p − left) < 0
  auto& mandible = mesh.nodeSets[kMandibleSet];
  auto& maxilla = mesh.nodeSets[kMaxillaSet];
  mandible.clear();
  maxilla.clear();
  std::size_t free = 0;
  for (const auto n : mesh.nodeSets.at("skull"))
  {
    const double d = normal.dot(mesh.nodes[static_cast<std::size_t>(n)] - left);
    if (std::abs(d) < offsets.vestibule)
      ++free; // over the teeth: the cheek's mucosa covers them without attaching
    else
      (d < 0 ? mandible : maxilla).push_back(n);
  }
  char line[256];
  std::snprintf(
    line, sizeof line,
    "jaw: left condyle (local) %.1f, %.1f, %.1f mm (%.1f mm from the estimate); %zu mandible, %zu maxilla nodes, "
    "%zu bone nodes over the teeth attached to neither",
    condyle.x(), condyle.y(), condyle.z(), std::sqrt(d2), mandible.size(), maxilla.size(), free);
  return line;
}

} // namespace mmrep
