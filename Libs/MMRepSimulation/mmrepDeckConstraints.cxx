// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The deck's constraints: sliding and symmetry-plane nodes, fixed bone, lip gap elements
// (see mmrepDeckSections.h).
#include "mmrepDeckSections.h"

#include "mmrepHalfModel.h"
#include "mmrepJaw.h"
#include "mmrepLipContact.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

namespace mmrep::simulation::deck
{
namespace
{
// With the jaw open, a lip-support node whose nearest bone node is on the mandible has lost its
// support (the lower teeth moved away with the jaw).
bool OnMandibleSide(const FEMesh& mesh, const DeckPlan& plan, std::int32_t node)
{
  if (plan.mandible.empty())
    return false;
  const Point3& p = mesh.nodes[static_cast<std::size_t>(node)];
  double best = std::numeric_limits<double>::infinity();
  bool lower = false;
  for (const auto* set : {&mesh.nodeSets.at(kMaxillaSet), &mesh.nodeSets.at(kMandibleSet)})
    for (auto b : *set)
      if (const double d = (mesh.nodes[static_cast<std::size_t>(b)] - p).squaredNorm(); d < best)
      {
        best = d;
        lower = set == &mesh.nodeSets.at(kMandibleSet);
      }
  return lower;
}

// The equations n·u = 0 of one node with one or more normals, in reduced row echelon form: each
// equation has its own dependent DOF (its largest term), absent from the node's other equations;
// dependent constraints drop out.
void WriteNormalEquations(std::int32_t node, const std::vector<Point3>& normals, DeckSummary& summary,
                          std::ostream& out)
{
  std::vector<Point3> rows;
  std::vector<int> leads;
  for (Point3 r : normals)
  {
    for (std::size_t i = 0; i < rows.size(); ++i)
      r -= r[leads[i]] / rows[i][leads[i]] * rows[i];
    if (!(r.norm() > 1e-9))
      continue;
    int lead = 0;
    for (int d = 1; d < 3; ++d)
      if (std::abs(r[d]) > std::abs(r[lead]))
        lead = d;
    for (auto& q : rows)
      q -= q[lead] / r[lead] * r;
    rows.push_back(r);
    leads.push_back(lead);
  }
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    const Point3& n = rows[i];
    std::vector<int> others;
    for (int d = 0; d < 3; ++d)
      if (d != leads[i] && std::abs(n[d]) > 1e-12 * std::abs(n[leads[i]]))
        others.push_back(d);
    out << "*EQUATION\n"
        << others.size() + 1 << "\n"
        << node + 1 << ", " << leads[i] + 1 << ", " << FormatDouble(n[leads[i]]);
    for (int d : others)
      out << ", " << node + 1 << ", " << d + 1 << ", " << FormatDouble(n[d]);
    out << "\n";
    ++summary.equations;
  }
}
} // namespace

void WriteConstraints(const FEMesh& mesh, const DeckOptions& options, const DeckPlan& plan, DeckSummary& summary,
                      std::ostream& out)
{
  std::vector<char> isFixed(mesh.nodes.size(), 0);
  for (const auto* set : {&plan.fixed, &plan.mandible})
    for (auto n : *set)
      isFixed[static_cast<std::size_t>(n)] = 1;
  std::vector<std::int32_t> constrained; // in order of first constraint
  std::map<std::int32_t, std::vector<Point3>> normals;
  auto addNormal = [&](std::int32_t node, const Point3& normal) {
    auto [it, fresh] = normals.emplace(node, std::vector<Point3>{});
    if (fresh)
      constrained.push_back(node);
    it->second.push_back(normal.normalized());
  };
  for (const auto& s : options.slidingNodes)
  {
    if (s.node < 0 || static_cast<std::size_t>(s.node) >= mesh.nodes.size() ||
        !plan.solidNode[static_cast<std::size_t>(s.node)])
      throw std::invalid_argument("sliding node " + std::to_string(s.node) + " is not a node of a solid element");
    // A bone node slides on its own bone; only the lips' support can move away with the jaw.
    if (isFixed[static_cast<std::size_t>(s.node)] || (!s.onBone && OnMandibleSide(mesh, plan, s.node)))
      continue;
    addNormal(s.node, s.normal);
    ++summary.slidingNodes;
  }
  if (options.symmetry && IsHalfModel(mesh))
  {
    // Muscle nodes on the plane follow their (left) host element through the embedding.
    const Point3 normal = SymmetryPlaneOf(mesh).normal;
    for (auto n : mesh.nodeSets.at(kSymmetryBoundarySet))
      if (plan.solidNode[static_cast<std::size_t>(n)] && !isFixed[static_cast<std::size_t>(n)])
      {
        addNormal(n, normal);
        ++summary.symmetryNodes;
      }
  }
  for (auto node : constrained)
    WriteNormalEquations(node, normals.at(node), summary, out);

  out << "*NSET, NSET=FIXED\n";
  WriteIds(out, plan.fixed);
  out << "*BOUNDARY\nFIXED, 1, 3\n";
}

void WriteLipGaps(const FEMesh& mesh, const DeckOptions& options, const DeckPlan& plan, DeckSummary& summary,
                  std::ostream& out)
{
  // One uni-directional gap element (GAPUNI) per pair of facing nodes, which coincide at rest, along
  // the upper lip's facing-surface normal at the pair: the lower node may move away from the upper
  // one but not through it (linear penalty). ccx's surface contact searches chatter at the corners,
  // where the slit closes, and do not converge; the pairs stay valid while the lips slide along
  // each other by less than an element (a few mm).
  if (!options.lipContact || !HasMouthSlit(mesh))
    return;
  const auto upperFaces = LipContactFaces(mesh, true);
  std::map<std::int32_t, Point3> normals;
  for (const auto& f : upperFaces)
  {
    const Point3 n =
      0.5 *
      (mesh.nodes[static_cast<std::size_t>(f.nodes[2])] - mesh.nodes[static_cast<std::size_t>(f.nodes[0])])
        .cross(mesh.nodes[static_cast<std::size_t>(f.nodes[3])] - mesh.nodes[static_cast<std::size_t>(f.nodes[1])]);
    for (auto v : f.nodes) // area-weighted, outward of the upper lip: towards the lower lip
      normals.try_emplace(v, Point3::Zero()).first->second += n;
  }
  std::size_t id = mesh.elements.size();
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
  for (const auto& [u, l] : MouthTwins(mesh))
    if (plan.used[static_cast<std::size_t>(u)] && plan.used[static_cast<std::size_t>(l)] && normals.count(u) &&
        normals[u].norm() > 0)
      pairs.emplace_back(u, l);
  if (!pairs.empty())
    out << "** lips: gap elements between the facing nodes of the mouth slit (no interpenetration)\n";
  // On a half model the plane's pairs see only the left faces: their normal is the full model's
  // (in the plane, by symmetry) once the plane-normal part is removed.
  std::vector<char> onPlane(mesh.nodes.size(), 0);
  Point3 planeNormal = Point3::Zero();
  if (IsHalfModel(mesh))
  {
    planeNormal = SymmetryPlaneOf(mesh).normal;
    for (auto n : mesh.nodeSets.at(kSymmetryBoundarySet))
      onPlane[static_cast<std::size_t>(n)] = 1;
  }
  for (const auto& [u, l] : pairs)
  {
    Point3 n = normals[u].normalized();
    if (onPlane[static_cast<std::size_t>(u)])
      n = (n - n.dot(planeNormal) * planeNormal).normalized();
    const std::string set = "G" + std::to_string(++id);
    out << "*ELEMENT, TYPE=GAPUNI, ELSET=" << set << "\n" << id << ", " << u + 1 << ", " << l + 1 << "\n";
    out << "*GAP, ELSET=" << set << "\n0., " << FormatDouble(n.x()) << ", " << FormatDouble(n.y()) << ", "
        << FormatDouble(n.z()) << ", , " << FormatDouble(options.contactStiffness) << ", 1e-7\n";
  }
  summary.contactNodes = pairs.size();
  summary.contactFaces = upperFaces.size();
}

} // namespace mmrep::simulation::deck
