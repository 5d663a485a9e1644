// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Muscle activation: runs the deck through ccx and maps the results back onto the model.
#include "mmrepMuscleActivation.h"

#include "mmrepElementLocation.h"

#include <Eigen/Geometry>

#include <vtkNew.h>
#include <vtkPoints.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mmrep::simulation
{
LandmarkMotion InterpolateDisplacement(const FEMesh& mesh, const std::vector<Point3>& displacements,
                                       const Point3& point, double tolerance)
{
  LandmarkMotion best;
  best.rest = point;
  best.distance = std::numeric_limits<double>::infinity();
  std::vector<double> bestWeights;
  for (std::size_t i = 0; i < mesh.elements.size(); ++i)
  {
    const Element& e = mesh.elements[i];
    if (e.type == ElementType::Cable)
      continue;
    Eigen::AlignedBox3d box;
    for (int k = 0; k < NodeCount(e.type); ++k)
      box.extend(mesh.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])]);
    if (box.exteriorDistance(point) > std::min(best.distance, tolerance))
      continue;
    const ElementLocation hit = LocateInElement(mesh, e, point);
    const double d = hit.distance;
    if (d < best.distance)
    {
      best.distance = d;
      best.element = static_cast<int>(i);
      bestWeights = hit.weights;
      if (hit.inside)
        break;
    }
  }
  if (best.element >= 0 && best.distance <= tolerance)
  {
    const Element& e = mesh.elements[static_cast<std::size_t>(best.element)];
    for (std::size_t k = 0; k < bestWeights.size(); ++k)
      best.displacement += bestWeights[k] * displacements[static_cast<std::size_t>(e.nodes[k])];
    return best;
  }
  // Far from every element: nearest node of a solid.
  best.element = -1;
  best.distance = std::numeric_limits<double>::infinity();
  for (const auto& e : mesh.elements)
    if (e.type != ElementType::Cable)
      for (int k = 0; k < NodeCount(e.type); ++k)
      {
        const auto n = static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)]);
        const double d = (mesh.nodes[n] - point).norm();
        if (d < best.distance)
        {
          best.distance = d;
          best.displacement = displacements[n];
        }
      }
  return best;
}

ActivationResult SimulateMuscleActivation(const FEMesh& mesh, const ActivationOptions& options)
{
  ActivationResult result;
  std::ostringstream deck;
  result.deck = WriteCalculiXDeck(mesh, options.deck, deck);
  result.run = RunCalculiX(deck.str(), options.run);
  if (!result.run.converged)
    throw std::runtime_error(DescribeFailure(result.run));
  const FrdBlock* disp = LastBlock(result.run.results, "DISP");
  if (disp == nullptr || disp->components < 3)
    throw std::runtime_error("the CalculiX results hold no displacements");

  // Nodes of the deck take ccx's values; muscle nodes left out follow their embedding.
  result.displacements.assign(mesh.nodes.size(), Point3::Zero());
  std::vector<char> known(mesh.nodes.size(), 0);
  for (const auto& [id, v] : disp->values)
  {
    if (id < 1 || static_cast<std::size_t>(id) > mesh.nodes.size() || v.size() < 3)
      throw std::runtime_error("the CalculiX results name node " + std::to_string(id) +
                               ", which the model does not have");
    result.displacements[static_cast<std::size_t>(id - 1)] = Point3(v[0], v[1], v[2]);
    known[static_cast<std::size_t>(id - 1)] = 1;
  }
  for (const auto& [name, track] : mesh.muscles)
    for (std::size_t i = 0; i < track.nodes.size() && i < track.embedding.size(); ++i)
    {
      const auto n = static_cast<std::size_t>(track.nodes[i]);
      const auto& emb = track.embedding[i];
      if (known[n] || emb.element < 0)
        continue;
      const Element& host = mesh.elements[static_cast<std::size_t>(emb.element)];
      const std::vector<double> w = ShapeFunctions(host.type, emb.pcoords);
      Point3 u = Point3::Zero();
      for (std::size_t k = 0; k < w.size(); ++k)
        u += w[k] * result.displacements[static_cast<std::size_t>(host.nodes[k])];
      result.displacements[n] = u;
    }

  for (const auto& lm : mesh.landmarks)
  {
    LandmarkMotion m = InterpolateDisplacement(mesh, result.displacements, lm.position);
    m.name = lm.name;
    result.landmarks.push_back(m);
  }

  for (const auto& a : options.deck.activations)
  {
    if (!(a.level > 0))
      continue;
    const MuscleTrack& track = mesh.muscles.at(a.muscle);
    MuscleForces f;
    f.muscle = a.muscle;
    f.level = a.level;
    for (auto c : track.cables)
    {
      const Element& e = mesh.elements[static_cast<std::size_t>(c)];
      const auto n0 = static_cast<std::size_t>(e.nodes[0]), n1 = static_cast<std::size_t>(e.nodes[1]);
      const double L0 = (mesh.nodes[n1] - mesh.nodes[n0]).norm();
      const double L = (mesh.nodes[n1] + result.displacements[n1] - mesh.nodes[n0] - result.displacements[n0]).norm();
      const double force = CableForce(options.deck.cables, track.maximumForce, L0, a.level, L - L0);
      f.meanForce += force / static_cast<double>(track.cables.size());
      f.maxForce = std::max(f.maxForce, force);
      f.restLength += L0;
      f.length += L;
    }
    result.muscles.push_back(f);
  }
  return result;
}

FEMesh DeformedMesh(const FEMesh& mesh, const ActivationResult& result)
{
  if (result.displacements.size() != mesh.nodes.size())
    throw std::invalid_argument("the displacements do not match the mesh's nodes");
  FEMesh out = mesh;
  for (std::size_t i = 0; i < out.nodes.size(); ++i)
    out.nodes[i] += result.displacements[i];
  for (std::size_t i = 0; i < out.landmarks.size() && i < result.landmarks.size(); ++i)
    out.landmarks[i].position += result.landmarks[i].displacement;
  return out;
}

} // namespace mmrep::simulation
