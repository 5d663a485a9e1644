// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The nodes, solids, cables, embedding and step of the CalculiX deck (see mmrepDeckSections.h).
#include "mmrepDeckSections.h"

#include "mmrepFEExport.h"
#include "mmrepJaw.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace mmrep::simulation::deck
{
namespace
{
const char* SolidType(ElementType type, const std::string& hexType)
{
  switch (type)
  {
    case ElementType::Hexahedron:
      return hexType.c_str();
    case ElementType::Wedge:
      return "C3D6";
    case ElementType::Tetrahedron:
      return "C3D4";
    default:
      return nullptr;
  }
}

std::string LayerTag(TissueLayer layer)
{
  std::string name = TissueLayerName(layer);
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return name;
}

void WriteMaterial(const HyperelasticMaterial& m, TissueLayer layer, std::ostream& out)
{
  if (!(m.d1 > 0) || !(m.ShearModulus() > 0))
    throw std::invalid_argument(std::string("material of layer ") + TissueLayerName(layer) +
                                " needs a positive shear modulus and D1 > 0");
  const std::string tag = LayerTag(layer);
  out << "*MATERIAL, NAME=M_" << tag << "\n*HYPERELASTIC, POLYNOMIAL, N=2\n"
      << FormatDouble(m.c10) << ", " << FormatDouble(m.c01) << ", " << FormatDouble(m.c20) << ", "
      << FormatDouble(m.c11) << ", " << FormatDouble(m.c02) << ", " << FormatDouble(m.d1) << ", " << FormatDouble(m.d2)
      << "\n";
  out << "*SOLID SECTION, ELSET=L_" << tag << ", MATERIAL=M_" << tag << "\n";
}
} // namespace

// printf's %g is locale-independent unless a program sets a locale; "-1.23456789012e-100" has 19
// characters.
std::string FormatDouble(double v)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12g", v);
  return buffer;
}

void WriteIds(std::ostream& out, const std::vector<std::int32_t>& ids)
{
  for (std::size_t i = 0; i < ids.size(); ++i)
    out << ids[i] + 1 << ((i % 16 == 15 || i + 1 == ids.size()) ? "\n" : ", ");
}

std::string JoinNames(const std::vector<std::string>& names)
{
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + n;
  return s;
}

void WriteNodes(const FEMesh& mesh, const DeckPlan& plan, std::ostream& out)
{
  out << "** MMRep muscle activation deck (CalculiX). Units: mm, N, N/mm2 (MPa).\n";
  out << "** ids: node/element id = MMRep index + 1\n";
  out << "*NODE, NSET=NALL\n";
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    if (plan.used[i])
    {
      const auto& p = mesh.nodes[i];
      out << i + 1 << ", " << FormatDouble(p.x()) << ", " << FormatDouble(p.y()) << ", " << FormatDouble(p.z()) << "\n";
    }
}

void WriteSolids(const FEMesh& mesh, const DeckOptions& options, DeckSummary& summary, std::ostream& out)
{
  const TissueLayer layers[] = {TissueLayer::None, TissueLayer::Epidermis, TissueLayer::Dermis,
                                TissueLayer::Hypodermis};
  const ElementType solidTypes[] = {ElementType::Hexahedron, ElementType::Wedge, ElementType::Tetrahedron};
  for (TissueLayer layer : layers)
  {
    std::vector<std::string> blocks;
    for (ElementType type : solidTypes)
    {
      std::vector<std::size_t> ids;
      for (std::size_t i = 0; i < mesh.elements.size(); ++i)
        if (mesh.elements[i].type == type && mesh.elements[i].layer == layer)
          ids.push_back(i);
      if (ids.empty())
        continue;
      const std::string name = "E_" + LayerTag(layer) + "_" + ElementTypeName(type);
      blocks.push_back(name);
      out << "*ELEMENT, TYPE=" << SolidType(type, options.hexahedronType) << ", ELSET=" << name << "\n";
      for (auto i : ids)
      {
        out << i + 1;
        for (auto n : detail::SolverNodeOrder(mesh.elements[i]))
          out << ", " << n + 1;
        out << "\n";
      }
      summary.solids += ids.size();
    }
    if (blocks.empty())
      continue;
    out << "*ELSET, ELSET=L_" << LayerTag(layer) << "\n" << JoinNames(blocks) << "\n";
    WriteMaterial(options.materials[static_cast<std::size_t>(layer)], layer, out);
  }
}

void WriteCables(const FEMesh& mesh, const DeckOptions& options, const DeckPlan& plan, DeckSummary& summary,
                 std::ostream& out)
{
  const CableModel& cm = options.cables;
  for (const auto* a : plan.active)
  {
    const MuscleTrack& track = mesh.muscles.at(a->muscle);
    if (!(track.maximumForce > 0) || !std::isfinite(track.maximumForce))
      throw std::invalid_argument("muscle '" + a->muscle + "' has no positive maximum force");
    out << "** muscle '" << a->muscle << "', activation " << FormatDouble(a->level) << ", maximum force "
        << FormatDouble(cm.forceScale * track.maximumForce) << " N\n";
    for (std::size_t c = 0; c < track.cables.size(); ++c)
    {
      const auto id = track.cables[c];
      const Element& e = mesh.elements[static_cast<std::size_t>(id)];
      const double L0 =
        (mesh.nodes[static_cast<std::size_t>(e.nodes[1])] - mesh.nodes[static_cast<std::size_t>(e.nodes[0])]).norm();
      if (!(L0 > 0))
        throw std::invalid_argument("muscle '" + a->muscle + "': cable " + std::to_string(c) + " has zero length");
      const std::string set = "C" + std::to_string(id + 1);
      out << "*ELEMENT, TYPE=SPRINGA, ELSET=" << set << "\n"
          << id + 1 << ", " << e.nodes[0] + 1 << ", " << e.nodes[1] + 1 << "\n";
      out << "*SPRING, ELSET=" << set << ", NONLINEAR\n";
      // Two curves: load parameter 0 (relaxed) and 1 (the muscle's level); the law is linear in the
      // level, so ccx's interpolation between them is the law at the ramped level.
      for (int t = 0; t <= 1; ++t)
        for (const auto& [elong, force] : CableCurve(cm, track.maximumForce, L0, t * a->level))
          out << FormatDouble(force) << ", " << FormatDouble(elong) << ", " << t << ".\n";
      ++summary.springs;
    }
  }
}

void WriteEmbedding(const FEMesh& mesh, const DeckPlan& plan, DeckSummary& summary, std::ostream& out)
{
  // u_m - sum N_i u_i = 0 for each direction (4 terms per line at most). A node shared by two tracks
  // (the orbicularis rings meet on the mid-sagittal plane) gets its equations once.
  std::vector<char> tied(mesh.nodes.size(), 0);
  for (const auto* a : plan.active)
  {
    const MuscleTrack& track = mesh.muscles.at(a->muscle);
    for (std::size_t i = 0; i < track.nodes.size(); ++i)
    {
      if (tied[static_cast<std::size_t>(track.nodes[i])])
        continue;
      tied[static_cast<std::size_t>(track.nodes[i])] = 1;
      const Element& host = mesh.elements[static_cast<std::size_t>(track.embedding[i].element)];
      const std::vector<double> w = ShapeFunctions(host.type, track.embedding[i].pcoords);
      std::vector<std::pair<std::int32_t, double>> terms;
      for (std::size_t k = 0; k < w.size(); ++k)
        if (std::abs(w[k]) > 1e-12)
          terms.emplace_back(host.nodes[k], -w[k]);
      for (int dof = 1; dof <= 3; ++dof)
      {
        out << (dof == 1 ? "*EQUATION\n" : "") << terms.size() + 1 << "\n"
            << track.nodes[i] + 1 << ", " << dof << ", 1.";
        for (std::size_t k = 0; k < terms.size(); ++k)
          out << (((k + 1) % 4 == 0) ? "\n" : ", ") << terms[k].first + 1 << ", " << dof << ", "
              << FormatDouble(terms[k].second);
        out << "\n";
        ++summary.equations;
      }
    }
  }
}

void WriteStep(const FEMesh& mesh, const DeckOptions& options, const DeckPlan& plan, DeckSummary& summary,
               std::ostream& out)
{
  const StepControl& step = options.step;
  // The load parameter ("temperature") starts at 0 and is ramped to 1 during the static step.
  out << "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 0.\n";
  out << "*STEP, NLGEOM, INC=" << step.maxIncrements << "\n*STATIC\n"
      << FormatDouble(step.initialIncrement) << ", 1., " << FormatDouble(step.minIncrement) << ", "
      << FormatDouble(step.maxIncrement) << "\n";
  if (!plan.mandible.empty())
  {
    // The mandible's rigid rotation, ramped with the step (exact at its end).
    const Eigen::Isometry3d rotation = JawRotation(mesh, options.jawAngle);
    out << "** jaw opening " << FormatDouble(options.jawAngle) << " deg about the condylar axis\n*BOUNDARY\n";
    for (auto n : plan.mandible)
    {
      const Point3& p = mesh.nodes[static_cast<std::size_t>(n)];
      const Point3 u = rotation * p - p;
      for (int d = 0; d < 3; ++d)
        out << n + 1 << ", " << d + 1 << ", " << d + 1 << ", " << FormatDouble(u[d]) << "\n";
    }
    summary.jawNodes = plan.mandible.size();
  }
  out << "*TEMPERATURE\nNALL, 1.\n";
  if (!options.loads.empty())
  {
    out << "*CLOAD\n";
    for (const auto& load : options.loads)
    {
      for (int dof = 0; dof < 3; ++dof)
        if (load.force[dof] != 0)
          out << load.node + 1 << ", " << dof + 1 << ", " << FormatDouble(load.force[dof]) << "\n";
    }
  }
  out << "*NODE FILE\nU\n*END STEP\n";
}

} // namespace mmrep::simulation::deck
