// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Mouth slit: closing and reopening it, its facing surfaces and the gap between them.
#include "mmrepLipContact.h"

#include "mmrepBoundaryFaces.h"

#include <Eigen/Geometry>

#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <limits>
#include <stdexcept>

namespace mmrep
{
namespace
{

const std::vector<std::int32_t>* Set(const FEMesh& mesh, const std::string& name)
{
  const auto it = mesh.nodeSets.find(name);
  return it == mesh.nodeSets.end() || it->second.empty() ? nullptr : &it->second;
}

const std::vector<std::int32_t>* ElementSet(const FEMesh& mesh, const std::string& name)
{
  const auto it = mesh.elementSets.find(name);
  return it == mesh.elementSets.end() || it->second.empty() ? nullptr : &it->second;
}

} // namespace

bool HasMouthSlit(const FEMesh& mesh)
{
  return Set(mesh, kUpperLipContactSet) && Set(mesh, kLowerLipContactSet) && ElementSet(mesh, kUpperLipSet) &&
         ElementSet(mesh, kLowerLipSet);
}

std::vector<std::pair<std::int32_t, std::int32_t>> MouthTwins(const FEMesh& mesh)
{
  std::vector<std::pair<std::int32_t, std::int32_t>> twins;
  if (!HasMouthSlit(mesh))
    return twins;
  const auto& upper = *Set(mesh, kUpperLipContactSet);
  const auto& lower = *Set(mesh, kLowerLipContactSet);
  std::vector<std::int32_t> upperOnly, lowerOnly;
  std::set_difference(upper.begin(), upper.end(), lower.begin(), lower.end(), std::back_inserter(upperOnly));
  std::set_difference(lower.begin(), lower.end(), upper.begin(), upper.end(), std::back_inserter(lowerOnly));
  if (upperOnly.size() != lowerOnly.size())
    throw std::invalid_argument("mouth slit: " + std::to_string(lowerOnly.size()) + " lower-lip and " +
                                std::to_string(upperOnly.size()) + " upper-lip facing nodes (they must pair up)");
  for (std::size_t i = 0; i < upperOnly.size(); ++i)
    twins.emplace_back(upperOnly[i], lowerOnly[i]);
  return twins;
}

ClosedMouth CloseMouth(FEMesh& mesh)
{
  ClosedMouth closed;
  closed.twins = MouthTwins(mesh);
  if (closed.twins.empty())
    return closed;
  std::vector<std::int32_t> partner(mesh.nodes.size(), -1);
  for (const auto& [u, l] : closed.twins)
    partner[static_cast<std::size_t>(l)] = u;
  for (const auto e : *ElementSet(mesh, kLowerLipSet))
  {
    Element& element = mesh.elements[static_cast<std::size_t>(e)];
    for (int k = 0; k < NodeCount(element.type); ++k)
    {
      auto& node = element.nodes[static_cast<std::size_t>(k)];
      if (const std::int32_t u = partner[static_cast<std::size_t>(node)]; u >= 0)
      {
        closed.slots.emplace_back(static_cast<std::size_t>(e), k);
        node = u;
      }
    }
  }
  return closed;
}

void ReopenMouth(FEMesh& mesh, const ClosedMouth& closed)
{
  std::vector<std::int32_t> twinOf(mesh.nodes.size(), -1);
  for (const auto& [u, l] : closed.twins)
  {
    mesh.nodes[static_cast<std::size_t>(l)] = mesh.nodes[static_cast<std::size_t>(u)];
    twinOf[static_cast<std::size_t>(u)] = l;
  }
  for (const auto& [e, k] : closed.slots)
  {
    auto& node = mesh.elements[e].nodes[static_cast<std::size_t>(k)];
    node = twinOf[static_cast<std::size_t>(node)];
  }
}

std::vector<LipContactFace> LipContactFaces(const FEMesh& mesh, bool upperLip)
{
  std::vector<LipContactFace> faces;
  if (!HasMouthSlit(mesh))
    return faces;
  const auto& contact = *Set(mesh, upperLip ? kUpperLipContactSet : kLowerLipContactSet);
  for (const auto e : *ElementSet(mesh, upperLip ? kUpperLipSet : kLowerLipSet))
  {
    const Element& element = mesh.elements[static_cast<std::size_t>(e)];
    if (element.type != ElementType::Hexahedron)
      continue;
    // Local face f is the C3D8 face S(f+1).
    const auto& hexFaces = LocalFaces(ElementType::Hexahedron);
    for (int f = 0; f < 6; ++f)
    {
      LipContactFace face{e, f + 1, {}};
      bool all = true;
      for (int c = 0; c < 4 && all; ++c)
      {
        face.nodes[static_cast<std::size_t>(c)] =
          element.nodes[static_cast<std::size_t>(hexFaces[static_cast<std::size_t>(f)][static_cast<std::size_t>(c)])];
        all = std::binary_search(contact.begin(), contact.end(), face.nodes[static_cast<std::size_t>(c)]);
      }
      if (all)
        faces.push_back(face);
    }
  }
  return faces;
}

LipGap MeasureLipGap(const FEMesh& mesh, const std::vector<Point3>& displacements)
{
  LipGap gap;
  const auto faces = LipContactFaces(mesh, true);
  if (faces.empty())
    return gap;
  auto at = [&](std::int32_t n) {
    const auto i = static_cast<std::size_t>(n);
    return Point3(displacements.empty() ? mesh.nodes[i] : Point3(mesh.nodes[i] + displacements[i]));
  };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> triangles;
  std::vector<Point3> normals;
  for (const auto& f : faces)
    for (const auto& tri : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}})
    {
      vtkIdType ids[3];
      for (int c = 0; c < 3; ++c)
        ids[c] =
          points->InsertNextPoint(at(f.nodes[static_cast<std::size_t>(tri[static_cast<std::size_t>(c)])]).data());
      triangles->InsertNextCell(3, ids);
      const Point3 a = at(f.nodes[static_cast<std::size_t>(tri[0])]), b = at(f.nodes[static_cast<std::size_t>(tri[1])]),
                   c = at(f.nodes[static_cast<std::size_t>(tri[2])]);
      normals.push_back((b - a).cross(c - a).normalized());
    }
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetPolys(triangles);
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  // Rim of the facing surface: quad edges used by one face only.
  std::map<std::pair<std::int32_t, std::int32_t>, int> edgeUses;
  for (const auto& f : faces)
    for (int c = 0; c < 4; ++c)
    {
      const auto a = f.nodes[static_cast<std::size_t>(c)], b = f.nodes[static_cast<std::size_t>((c + 1) % 4)];
      ++edgeUses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<Point3, Point3>> rim;
  for (const auto& [edge, uses] : edgeUses)
    if (uses == 1)
      rim.emplace_back(at(edge.first), at(edge.second));
  const auto& upper = *Set(mesh, kUpperLipContactSet);
  gap.minimum = std::numeric_limits<double>::infinity();
  vtkNew<vtkGenericCell> cell;
  for (const auto n : *Set(mesh, kLowerLipContactSet))
  {
    if (std::binary_search(upper.begin(), upper.end(), n))
      continue;
    const Point3 p = at(n);
    Point3 closest;
    vtkIdType id = -1;
    int sub = 0;
    double d2 = 0;
    locator->FindClosestPoint(p.data(), closest.data(), cell, id, sub, d2);
    // A closest point on the facing surface's rim with the node off to the side: the node lies beyond
    // the facing region (e.g. a protruding lower lip in front of the upper lip's edge), not inside.
    const bool onRim = std::any_of(rim.begin(), rim.end(), [&](const std::pair<Point3, Point3>& e) {
      const Point3 a = e.first, ab = e.second - e.first;
      const double t = std::clamp((closest - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      return (a + t * ab - closest).norm() < 1e-6;
    });
    const double along = (p - closest).dot(normals[static_cast<std::size_t>(id)]);
    const bool beyond = onRim && std::abs(along) < 0.7 * std::sqrt(d2); // off the rim sideways
    const double d = std::sqrt(d2) * (along < 0 && !beyond ? -1.0 : 1.0);
    gap.minimum = std::min(gap.minimum, d);
    gap.mean += d;
    ++gap.nodes;
  }
  if (gap.nodes == 0)
    gap.minimum = 0;
  else
    gap.mean /= static_cast<double>(gap.nodes);
  return gap;
}

} // namespace mmrep
