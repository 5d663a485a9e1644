// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepMuscleInference.h"

#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStaticCellLocator.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace mmrep
{
namespace
{

// The solid elements of a mesh as a VTK grid (cell k = element solids[k]) with a locator.
class SolidLocator
{
public:
  explicit SolidLocator(const FEMesh& mesh)
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.nodes.size()));
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
      points->SetPoint(static_cast<vtkIdType>(i), mesh.nodes[i].data());
    grid_->SetPoints(points);
    cellOf_.assign(mesh.elements.size(), -1);
    for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    {
      const auto& el = mesh.elements[e];
      if (el.type == ElementType::Cable)
        continue;
      vtkIdType ids[8];
      for (int k = 0; k < NodeCount(el.type); ++k)
        ids[k] = el.nodes[static_cast<std::size_t>(k)];
      cellOf_[e] = grid_->InsertNextCell(static_cast<int>(el.type), NodeCount(el.type), ids);
      elementOf_.push_back(static_cast<std::int32_t>(e));
    }
    if (elementOf_.empty())
      throw std::invalid_argument("muscle inference: the subject mesh has no solid element");
    locator_->SetDataSet(grid_);
    locator_->BuildLocator();
  }

  // Where x lies: the element containing it (preferring `hint`, then the lowest index), or the
  // nearest element with extrapolated parametric coordinates; `distance` is 0 inside.
  Embedding Locate(const Point3& x, std::int32_t hint, double& distance)
  {
    std::vector<vtkIdType> candidates = Near(x, 1e-6);
    if (hint >= 0 && static_cast<std::size_t>(hint) < cellOf_.size() && cellOf_[static_cast<std::size_t>(hint)] >= 0)
      candidates.insert(candidates.begin(), cellOf_[static_cast<std::size_t>(hint)]);
    Embedding best;
    for (const vtkIdType c : candidates)
    {
      double d2 = 0;
      std::array<double, 3> pc{};
      if (Evaluate(c, x, pc, d2) == 1)
      {
        distance = 0;
        return {elementOf_[static_cast<std::size_t>(c)], pc};
      }
    }
    // Outside every element: the nearest one within growing boxes; ties to the lowest index.
    double bestD2 = std::numeric_limits<double>::infinity();
    for (double radius : {2.0, 5.0, 10.0, 20.0})
    {
      for (const vtkIdType c : Near(x, radius))
      {
        double d2 = 0;
        std::array<double, 3> pc{};
        if (Evaluate(c, x, pc, d2) < 0)
          continue;
        if (d2 < bestD2)
        {
          bestD2 = d2;
          best = {elementOf_[static_cast<std::size_t>(c)], pc};
        }
      }
      if (best.element >= 0)
        break;
    }
    if (best.element < 0)
      throw std::runtime_error("muscle inference: a muscle point lies more than 20 mm from every element");
    distance = std::sqrt(bestD2);
    return best;
  }

private:
  std::vector<vtkIdType> Near(const Point3& x, double radius)
  {
    double bounds[6] = {x.x() - radius, x.x() + radius, x.y() - radius, x.y() + radius, x.z() - radius, x.z() + radius};
    ids_->Reset();
    locator_->FindCellsWithinBounds(bounds, ids_);
    std::vector<vtkIdType> out(ids_->GetPointer(0), ids_->GetPointer(0) + ids_->GetNumberOfIds());
    std::sort(out.begin(), out.end());
    return out;
  }

  int Evaluate(vtkIdType c, const Point3& x, std::array<double, 3>& pcoords, double& d2)
  {
    grid_->GetCell(c, cell_);
    double p[3] = {x.x(), x.y(), x.z()}, closest[3], weights[8];
    int subId = 0;
    return cell_->EvaluatePosition(p, closest, subId, pcoords.data(), d2, weights);
  }

  vtkNew<vtkUnstructuredGrid> grid_;
  vtkNew<vtkStaticCellLocator> locator_;
  vtkNew<vtkGenericCell> cell_;
  vtkNew<vtkIdList> ids_;
  std::vector<vtkIdType> cellOf_;       // element -> cell (-1 for cables)
  std::vector<std::int32_t> elementOf_; // cell -> element
};

} // namespace

MuscleInferenceReport InferMuscles(const FEMesh& atlas, const PointMap& atlasToSubject, FEMesh& subject)
{
  if (atlas.muscles.empty())
    throw std::invalid_argument("muscle inference: the atlas has no muscle tracks");
  if (atlas.nodes.size() != subject.nodes.size() || atlas.elements.size() != subject.elements.size() ||
      atlas.muscles.size() != subject.muscles.size())
    throw std::invalid_argument(
      "muscle inference: the subject mesh does not have the atlas's topology (" + std::to_string(subject.nodes.size()) +
      " nodes, " + std::to_string(subject.elements.size()) + " elements vs the atlas's " +
      std::to_string(atlas.nodes.size()) + ", " + std::to_string(atlas.elements.size()) + ")");
  for (const auto& [name, track] : atlas.muscles)
  {
    const auto it = subject.muscles.find(name);
    if (it == subject.muscles.end() || it->second.nodes != track.nodes || it->second.cables != track.cables)
      throw std::invalid_argument("muscle inference: muscle '" + name + "' differs between atlas and subject mesh");
  }

  MuscleInferenceReport report;
  // Solid nodes stay where the registration and repair put them; track points follow the transform.
  for (const auto& [name, track] : atlas.muscles)
    for (const auto n : track.nodes)
      subject.nodes[static_cast<std::size_t>(n)] = atlasToSubject(atlas.nodes[static_cast<std::size_t>(n)]);

  SolidLocator locator(subject);
  for (const auto& [name, track] : atlas.muscles)
  {
    auto& out = subject.muscles.at(name);
    out.maximumForce = track.maximumForce;
    out.embedding.resize(track.nodes.size());
    for (std::size_t k = 0; k < track.nodes.size(); ++k)
    {
      const std::int32_t hint = k < track.embedding.size() ? track.embedding[k].element : -1;
      double distance = 0;
      out.embedding[k] = locator.Locate(subject.nodes[static_cast<std::size_t>(track.nodes[k])], hint, distance);
      if (distance > 0)
      {
        ++report.outside;
        report.maxOutsideDistance = std::max(report.maxOutsideDistance, distance);
      }
      if (out.embedding[k].element != hint)
        ++report.changedElement;
      ++report.points;
    }
    ++report.muscles;
    if (!track.nodes.empty())
      report.insertions.push_back({name, atlas.nodes[static_cast<std::size_t>(track.nodes.front())],
                                   subject.nodes[static_cast<std::size_t>(track.nodes.front())]});
  }
  return report;
}

std::vector<std::pair<std::string, Point3>> MuscleInsertions(const FEMesh& mesh)
{
  std::vector<std::pair<std::string, Point3>> out;
  for (const auto& [name, track] : mesh.muscles)
    if (!track.nodes.empty())
      out.emplace_back(name, mesh.nodes[static_cast<std::size_t>(track.nodes.front())]);
  return out;
}

} // namespace mmrep
