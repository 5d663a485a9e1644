// CalculiX deck writer for muscle activation (see the header for the model).
#include "mmrepCalculiXDeck.h"

#include "mmrepFEExport.h"
#include "mmrepHalfModel.h"

#include <Eigen/Geometry>

#include <vtkHexahedron.h>
#include <vtkTetra.h>
#include <vtkWedge.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>

namespace mmrep::simulation
{
namespace
{
// CalculiX reads numbers from fields of at most 20 characters: 12 significant digits always fit
// ("-1.23456789012e-100" has 19). printf's %g is locale-independent unless a program sets a locale.
std::string FormatDouble(double v)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12g", v);
  return buffer;
}

// Abaqus/CalculiX: at most 16 ids per data line.
void WriteIds(std::ostream& out, const std::vector<std::int32_t>& ids)
{
  for (std::size_t i = 0; i < ids.size(); ++i)
    out << ids[i] + 1 << ((i % 16 == 15 || i + 1 == ids.size()) ? "\n" : ", ");
}

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
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return name;
}

std::string JoinNames(const std::vector<std::string>& names)
{
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + n;
  return s;
}
} // namespace

HyperelasticMaterial FaceTissue(double poissonRatio)
{
  if (!(poissonRatio > 0 && poissonRatio < 0.5))
    throw std::invalid_argument("Poisson ratio " + std::to_string(poissonRatio) + " must lie in (0, 0.5)");
  HyperelasticMaterial m;
  m.c10 = 2500e-6; // 2500 Pa in N/mm²
  m.c20 = 1175e-6; // 1175 Pa
  const double mu = m.ShearModulus();
  const double bulk = 2 * mu * (1 + poissonRatio) / (3 * (1 - 2 * poissonRatio));
  m.d1 = 2 / bulk;
  return m;
}

std::vector<std::string> MuscleNames(const FEMesh& mesh)
{
  std::vector<std::string> names;
  for (const auto& [name, track] : mesh.muscles)
    names.push_back(name);
  return names;
}

void CheckActivations(const FEMesh& mesh, const std::vector<MuscleActivation>& activations)
{
  if (mesh.muscles.empty())
    throw std::invalid_argument("the model has no muscles (no muscle tracks stored in the mesh)");
  if (activations.empty())
    throw std::invalid_argument("no muscle to activate was given");
  std::set<std::string> seen;
  bool anyActive = false;
  for (const auto& a : activations)
  {
    if (mesh.muscles.count(a.muscle) == 0 && IsHalfModel(mesh) && a.muscle.size() > 2 &&
        a.muscle.compare(a.muscle.size() - 2, 2, "_R") == 0)
      throw std::invalid_argument("muscle '" + a.muscle + "' is on the right side, which this half model does not hold "
                                  "(it is the left half, with node set '" + kSymmetryBoundarySet + "'): activate '" +
                                  a.muscle.substr(0, a.muscle.size() - 2) + "_L', its mirror image");
    if (mesh.muscles.count(a.muscle) == 0)
      throw std::invalid_argument("unknown muscle '" + a.muscle + "'; the model's muscles are: " +
                                  JoinNames(MuscleNames(mesh)));
    if (!seen.insert(a.muscle).second)
      throw std::invalid_argument("muscle '" + a.muscle + "' is given twice");
    if (!(a.level >= 0 && a.level <= 1))
      throw std::invalid_argument("activation level " + std::to_string(a.level) + " of muscle '" + a.muscle +
                                  "' must lie in [0, 1]");
    if (mesh.muscles.at(a.muscle).cables.empty())
      throw std::invalid_argument("muscle '" + a.muscle + "' has no cable elements");
    anyActive = anyActive || a.level > 0;
  }
  if (!anyActive)
    throw std::invalid_argument("every activation level is 0: nothing to simulate");
}

std::vector<std::pair<double, double>> CableCurve(const CableModel& model, double maximumForce, double restLength,
                                                  double level)
{
  static const double stretches[] = {0, 0.3, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95, 1, 3};
  const double fmax = model.forceScale * maximumForce;
  std::vector<std::pair<double, double>> curve;
  for (double lambda : stretches)
  {
    const double active = lambda < 1 ? std::exp(-(lambda - 1) * (lambda - 1) / model.lengthWidth) : 1.0;
    curve.emplace_back((lambda - 1) * restLength, fmax * (level * active + model.stabilisingSlope * (lambda - 1)));
  }
  return curve;
}

double CableForce(const CableModel& model, double maximumForce, double restLength, double level, double elongation)
{
  const auto curve = CableCurve(model, maximumForce, restLength, level);
  std::size_t k = 1;
  while (k + 1 < curve.size() && elongation > curve[k].first)
    ++k;
  const auto& [e0, f0] = curve[k - 1];
  const auto& [e1, f1] = curve[k];
  return f0 + (f1 - f0) * (elongation - e0) / (e1 - e0);
}

std::vector<double> ShapeFunctions(ElementType type, const std::array<double, 3>& pcoords)
{
  std::vector<double> w(static_cast<std::size_t>(NodeCount(type)));
  switch (type)
  {
    case ElementType::Hexahedron:
      vtkHexahedron::InterpolationFunctions(pcoords.data(), w.data());
      break;
    case ElementType::Wedge:
      vtkWedge::InterpolationFunctions(pcoords.data(), w.data());
      break;
    case ElementType::Tetrahedron:
      vtkTetra::InterpolationFunctions(pcoords.data(), w.data());
      break;
    default:
      throw std::invalid_argument("shape functions are defined for solid elements only");
  }
  return w;
}

std::vector<SlidingNode> LipSupportNodes(const FEMesh& mesh, double margin)
{
  const auto inner = mesh.nodeSets.find("inner");
  const auto lips = mesh.nodeSets.find("lips");
  if (inner == mesh.nodeSets.end() || lips == mesh.nodeSets.end() || lips->second.empty())
    return {};
  double xmin = 1e300, xmax = -1e300, zmin = 1e300, zmax = -1e300;
  for (auto n : lips->second)
  {
    const Point3& p = mesh.nodes[static_cast<std::size_t>(n)];
    xmin = std::min(xmin, p.x());
    xmax = std::max(xmax, p.x());
    zmin = std::min(zmin, p.z());
    zmax = std::max(zmax, p.z());
  }
  std::vector<char> isInner(mesh.nodes.size(), 0);
  for (auto n : inner->second)
    isInner[static_cast<std::size_t>(n)] = 1;
  // Boundary quads of the hexahedra whose four nodes are inner nodes: the inner surface.
  static const int faces[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  std::map<std::array<std::int32_t, 4>, std::pair<int, std::array<std::int32_t, 4>>> quads;
  for (const auto& e : mesh.elements)
  {
    if (e.type != ElementType::Hexahedron)
      continue;
    for (const auto& f : faces)
    {
      std::array<std::int32_t, 4> ids{e.nodes[static_cast<std::size_t>(f[0])], e.nodes[static_cast<std::size_t>(f[1])],
                                      e.nodes[static_cast<std::size_t>(f[2])], e.nodes[static_cast<std::size_t>(f[3])]};
      auto key = ids;
      std::sort(key.begin(), key.end());
      auto& q = quads[key];
      ++q.first;
      q.second = ids;
    }
  }
  std::map<std::int32_t, Point3> normals;
  for (const auto& [key, q] : quads)
  {
    if (q.first != 1 || !std::all_of(key.begin(), key.end(), [&](std::int32_t n) { return isInner[static_cast<std::size_t>(n)] != 0; }))
      continue;
    const auto& id = q.second;
    const Point3 a = mesh.nodes[static_cast<std::size_t>(id[2])] - mesh.nodes[static_cast<std::size_t>(id[0])];
    const Point3 b = mesh.nodes[static_cast<std::size_t>(id[3])] - mesh.nodes[static_cast<std::size_t>(id[1])];
    const Point3 n = 0.5 * a.cross(b); // area-weighted
    for (auto v : id)
    {
      auto [it, fresh] = normals.emplace(v, Point3::Zero());
      // Orientation is irrelevant for n·u = 0; keep the accumulated normals consistent.
      it->second += (it->second.dot(n) < 0 ? -n : n);
    }
  }
  std::vector<SlidingNode> out;
  for (const auto& [node, n] : normals)
  {
    const Point3& p = mesh.nodes[static_cast<std::size_t>(node)];
    if (p.x() < xmin - margin || p.x() > xmax + margin || p.z() < zmin - margin || p.z() > zmax + margin || !(n.norm() > 0))
      continue;
    out.push_back({node, n.normalized()});
  }
  return out;
}

DeckSummary WriteCalculiXDeck(const FEMesh& mesh, const DeckOptions& options, std::ostream& out)
{
  if (!options.activations.empty() || options.loads.empty())
    CheckActivations(mesh, options.activations);
  const std::string& hexType = options.hexahedronType;
  if (hexType != "C3D8" && hexType != "C3D8I" && hexType != "C3D8R")
    throw std::invalid_argument("hexahedron type '" + hexType + "' must be C3D8, C3D8I or C3D8R");
  const StepControl& step = options.step;
  if (!(step.initialIncrement > 0 && step.minIncrement > 0 && step.minIncrement <= step.initialIncrement &&
        step.initialIncrement <= step.maxIncrement && step.maxIncrement <= 1 && step.maxIncrements > 0))
    throw std::invalid_argument("step control needs 0 < minimum <= initial <= maximum increment <= 1 and at least one increment");
  const CableModel& cm = options.cables;
  if (!(cm.forceScale > 0 && cm.lengthWidth > 0 && cm.stabilisingSlope > 0) || !std::isfinite(cm.forceScale))
    throw std::invalid_argument("the cable force scale, force-length width and stabilising slope must be positive");

  DeckSummary summary;
  std::vector<char> used(mesh.nodes.size(), 0);
  for (const auto& e : mesh.elements)
    if (e.type != ElementType::Cable)
      for (int k = 0; k < NodeCount(e.type); ++k)
        used[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])] = 1;

  // Fixed nodes: those of the set that carry a solid (a node without a solid has no stiffness).
  const auto fixedIt = mesh.nodeSets.find(options.fixedNodeSet);
  if (fixedIt == mesh.nodeSets.end())
    throw std::invalid_argument("the model has no node set '" + options.fixedNodeSet + "' to fix");
  std::vector<std::int32_t> fixed;
  for (auto n : fixedIt->second)
    if (used[static_cast<std::size_t>(n)])
      fixed.push_back(n);
  std::sort(fixed.begin(), fixed.end());
  fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
  if (fixed.empty())
    throw std::invalid_argument("node set '" + options.fixedNodeSet + "' holds no node of a solid element: nothing is fixed");
  summary.fixedNodes = fixed.size();

  std::vector<const MuscleActivation*> active;
  for (const auto& a : options.activations)
    if (a.level > 0)
    {
      active.push_back(&a);
      summary.activeMuscles.push_back(a.muscle);
    }
  std::vector<char> solidNode = used;
  for (const auto& load : options.loads)
    if (load.node < 0 || static_cast<std::size_t>(load.node) >= mesh.nodes.size() || !solidNode[static_cast<std::size_t>(load.node)] ||
        !load.force.allFinite())
      throw std::invalid_argument("load on node " + std::to_string(load.node) +
                                  ": not a node of a solid element, or a non-finite force");
  for (const auto* a : active)
  {
    const MuscleTrack& track = mesh.muscles.at(a->muscle);
    if (track.embedding.size() != track.nodes.size())
      throw std::invalid_argument("muscle '" + a->muscle + "' has no embedding for every track node");
    for (std::size_t i = 0; i < track.nodes.size(); ++i)
    {
      const auto& emb = track.embedding[i];
      if (emb.element < 0 || static_cast<std::size_t>(emb.element) >= mesh.elements.size() ||
          mesh.elements[static_cast<std::size_t>(emb.element)].type == ElementType::Cable)
        throw std::invalid_argument("muscle '" + a->muscle + "': track node " + std::to_string(i) +
                                    " is not embedded in a solid element");
      if (solidNode[static_cast<std::size_t>(track.nodes[i])])
        throw std::invalid_argument("muscle '" + a->muscle + "': track node " + std::to_string(i) +
                                    " is also a node of a solid element (muscle nodes must be separate)");
      used[static_cast<std::size_t>(track.nodes[i])] = 1;
    }
  }

  out << "** MMRep muscle activation deck (CalculiX). Units: mm, N, N/mm2 (MPa).\n";
  out << "** ids: node/element id = MMRep index + 1\n";
  out << "*NODE, NSET=NALL\n";
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    if (used[i])
    {
      const auto& p = mesh.nodes[i];
      out << i + 1 << ", " << FormatDouble(p.x()) << ", " << FormatDouble(p.y()) << ", " << FormatDouble(p.z()) << "\n";
    }

  // Solids grouped by (layer, type); one material and section per layer.
  const TissueLayer layers[] = {TissueLayer::None, TissueLayer::Epidermis, TissueLayer::Dermis, TissueLayer::Hypodermis};
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
      out << "*ELEMENT, TYPE=" << SolidType(type, hexType) << ", ELSET=" << name << "\n";
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
    const std::string tag = LayerTag(layer);
    out << "*ELSET, ELSET=L_" << tag << "\n" << JoinNames(blocks) << "\n";
    const HyperelasticMaterial& m = options.materials[static_cast<std::size_t>(layer)];
    if (!(m.d1 > 0) || !(m.ShearModulus() > 0))
      throw std::invalid_argument(std::string("material of layer ") + TissueLayerName(layer) +
                                  " needs a positive shear modulus and D1 > 0");
    out << "*MATERIAL, NAME=M_" << tag << "\n*HYPERELASTIC, POLYNOMIAL, N=2\n"
        << FormatDouble(m.c10) << ", " << FormatDouble(m.c01) << ", " << FormatDouble(m.c20) << ", " << FormatDouble(m.c11)
        << ", " << FormatDouble(m.c02) << ", " << FormatDouble(m.d1) << ", " << FormatDouble(m.d2) << "\n";
    out << "*SOLID SECTION, ELSET=L_" << tag << ", MATERIAL=M_" << tag << "\n";
  }

  // Cables: one SPRINGA element set per cable (each has its own rest length, hence its own curve).
  for (const auto* a : active)
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
      const double L0 = (mesh.nodes[static_cast<std::size_t>(e.nodes[1])] - mesh.nodes[static_cast<std::size_t>(e.nodes[0])]).norm();
      if (!(L0 > 0))
        throw std::invalid_argument("muscle '" + a->muscle + "': cable " + std::to_string(c) + " has zero length");
      const std::string set = "C" + std::to_string(id + 1);
      out << "*ELEMENT, TYPE=SPRINGA, ELSET=" << set << "\n" << id + 1 << ", " << e.nodes[0] + 1 << ", " << e.nodes[1] + 1 << "\n";
      out << "*SPRING, ELSET=" << set << ", NONLINEAR\n";
      // Two curves: load parameter 0 (relaxed) and 1 (the muscle's level); the law is linear in the
      // level, so ccx's interpolation between them is the law at the ramped level.
      for (int t = 0; t <= 1; ++t)
        for (const auto& [elong, force] : CableCurve(cm, track.maximumForce, L0, t * a->level))
          out << FormatDouble(force) << ", " << FormatDouble(elong) << ", " << t << ".\n";
      ++summary.springs;
    }
  }

  // Embedding: u_m - sum N_i u_i = 0 for each direction (4 terms per line at most). A node shared by
  // two tracks (the orbicularis rings meet on the mid-sagittal plane) gets its equations once.
  std::vector<char> tied(mesh.nodes.size(), 0);
  for (const auto* a : active)
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
        out << (dof == 1 ? "*EQUATION\n" : "") << terms.size() + 1 << "\n" << track.nodes[i] + 1 << ", " << dof << ", 1.";
        for (std::size_t k = 0; k < terms.size(); ++k)
          out << (((k + 1) % 4 == 0) ? "\n" : ", ") << terms[k].first + 1 << ", " << dof << ", " << FormatDouble(terms[k].second);
        out << "\n";
        ++summary.equations;
      }
    }
  }

  // Normal constraints n·u = 0: sliding nodes and, on a half model, the symmetry plane's nodes.
  std::vector<char> isFixed(mesh.nodes.size(), 0);
  for (auto n : fixed)
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
    if (s.node < 0 || static_cast<std::size_t>(s.node) >= mesh.nodes.size() || !solidNode[static_cast<std::size_t>(s.node)])
      throw std::invalid_argument("sliding node " + std::to_string(s.node) + " is not a node of a solid element");
    if (isFixed[static_cast<std::size_t>(s.node)])
      continue;
    addNormal(s.node, s.normal);
    ++summary.slidingNodes;
  }
  if (options.symmetry && IsHalfModel(mesh))
  {
    // Muscle nodes on the plane follow their (left) host element through the embedding.
    const Point3 normal = SymmetryPlaneOf(mesh).normal;
    for (auto n : mesh.nodeSets.at(kSymmetryBoundarySet))
      if (solidNode[static_cast<std::size_t>(n)] && !isFixed[static_cast<std::size_t>(n)])
      {
        addNormal(n, normal);
        ++summary.symmetryNodes;
      }
  }
  for (auto node : constrained)
  {
    // Reduced row echelon form of the node's constraints: each equation has its own dependent DOF
    // (its largest term), absent from the node's other equations; dependent constraints drop out.
    std::vector<Point3> rows;
    std::vector<int> leads;
    for (Point3 r : normals.at(node))
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
      out << "*EQUATION\n" << others.size() + 1 << "\n" << node + 1 << ", " << leads[i] + 1 << ", " << FormatDouble(n[leads[i]]);
      for (int d : others)
        out << ", " << node + 1 << ", " << d + 1 << ", " << FormatDouble(n[d]);
      out << "\n";
      ++summary.equations;
    }
  }

  out << "*NSET, NSET=FIXED\n";
  WriteIds(out, fixed);
  out << "*BOUNDARY\nFIXED, 1, 3\n";
  // The load parameter ("temperature") starts at 0 and is ramped to 1 during the static step.
  out << "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 0.\n";
  out << "*STEP, NLGEOM, INC=" << step.maxIncrements << "\n*STATIC\n"
      << FormatDouble(step.initialIncrement) << ", 1., " << FormatDouble(step.minIncrement) << ", "
      << FormatDouble(step.maxIncrement) << "\n";
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
  return summary;
}

} // namespace mmrep::simulation
