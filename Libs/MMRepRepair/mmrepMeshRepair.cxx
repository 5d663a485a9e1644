// Jacobian-based mesh repair, see mmrepMeshRepair.h.
//
// Each element's quality is its Verdict scaled Jacobian (as vtkMeshQuality computes it), with
// degenerate elements (Verdict's 1e30 flag) counted as -2, below any real value. Elements below
// the target are visited worst first; for each, its nodes are moved one at a time (worst corner
// first) by a derivative-free local search: geometric "ideal" positions of the node in its
// elements, a line search along the finite-difference gradient of the worst element around the
// node, and compass steps. A move is kept only when it raises the sorted (leximin) qualities of
// the elements around the node, capped just above the threshold, and never pushes an element that
// met the threshold below it. Phase 1 visits inverted elements only, phase 2 every element below
// the threshold; each phase first moves inner nodes only, then also surface nodes.
#include "mmrepMeshRepair.h"

#include "mmrepLipContact.h"

#include "mmrepMeshQuality.h"
#include "mmrepSurfaceProjector.h"

#include <vtkHexahedron.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkIdList.h>
#include <vtkStaticPointLocator.h>
#include <vtkTetra.h>
#include <vtkWedge.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace mmrep
{
namespace
{
constexpr double kDegenerate = -2.0; // quality of a Verdict-flagged (collapsed) element
constexpr double kMargin = 0.05;     // elements are improved up to threshold + margin
constexpr double kRingMargin = 0.4; // elements around a stuck one are improved up to threshold + this
constexpr double kEqual = 1e-12;     // qualities closer than this compare equal

enum class SurfaceKind : std::uint8_t
{
  None,
  Skin,
  Skull
};

bool IsSolid(ElementType t)
{
  return t != ElementType::Cable;
}

// Hex corner (r,s,t) bits of VTK's node order, for the trilinear "ideal corner" position.
constexpr int kHexBits[8] = {0b000, 0b001, 0b011, 0b010, 0b100, 0b101, 0b111, 0b110}; // bit0=r, bit1=s, bit2=t
int HexNodeOfBits(int bits)
{
  for (int i = 0; i < 8; ++i)
    if (kHexBits[i] == bits)
      return i;
  return -1;
}

class Repairer
{
public:
  Repairer(FEMesh& mesh, const RepairOptions& options) : mesh_(mesh), options_(options)
  {
    threshold_ = options.scaledJacobianThreshold;
    cap_ = std::min(1.0, threshold_ + kMargin);
    BuildAdjacency();
    BuildConstraints();
    changedAt_.assign(mesh_.elements.size(), 0);
    failedAt_.assign(mesh_.nodes.size(), 0);
    ringFailedAt_.assign(mesh_.nodes.size(), 0);
  }

  void Run(RepairReport& report)
  {
    const std::vector<Point3> original = mesh_.nodes;
    quality_.assign(mesh_.elements.size(), std::numeric_limits<double>::infinity());
    for (std::size_t e = 0; e < mesh_.elements.size(); ++e)
      if (IsSolid(mesh_.elements[e].type))
        quality_[e] = Quality(e);

    // Phase 1: regularity (inverted first), phase 2: threshold. In each phase inner nodes move
    // first, then surface nodes too, then also the nodes around the bad elements (to make room).
    struct Stage
    {
      bool regularity, surfaceAllowed, ring;
    };
    const Stage plan[] = {{true, false, false}, {true, true, false}, {true, true, true},
                          {false, false, false}, {false, true, false}, {false, true, true}};
    const int stages = 6;
    // The plan is repeated while a full pass still fixes elements.
    std::size_t badBefore = std::numeric_limits<std::size_t>::max();
    for (int pass = 0; pass < 4; ++pass)
    {
      const std::size_t bad = Measure(false).bad;
      if (bad == 0 || bad >= badBefore)
        break;
      badBefore = bad;
    for (int stage = 0; stage < stages; ++stage)
    {
      const bool regularity = plan[stage].regularity, surfaceAllowed = plan[stage].surfaceAllowed;
      ring_ = plan[stage].ring;
      // A stage ends when a sweep neither fixes an element nor raises the bad elements noticeably.
      Progress last = Measure(regularity);
      for (int sweep = 0; sweep < options_.maximumSweeps && last.bad > 0; ++sweep)
      {
        const bool changed = Sweep(regularity, surfaceAllowed);
        const Progress now = Measure(regularity);
        if (options_.progress)
          options_.progress(std::min(1.0, (pass * stages + stage + double(sweep + 1) / options_.maximumSweeps) / stages));
        const bool progressed = now.bad < last.bad || now.score > last.score + 1e-3 * double(last.bad);
        last = now;
        if (!changed || !progressed)
          break;
      }
      if (options_.progress)
        options_.progress(std::min(1.0, double(pass * stages + stage + 1) / stages));
    }
    }
    MoveMuscleNodes(original);

    for (std::size_t i = 0; i < mesh_.nodes.size(); ++i)
      if (mesh_.nodes[i] != original[i])
      {
        ++report.movedNodes;
        if (surface_[i] != SurfaceKind::None)
          ++report.movedSurfaceNodes;
      }
    report.symmetricPairs = pairs_;
  }

private:
  // ---- setup --------------------------------------------------------------------------------
  void BuildAdjacency()
  {
    const std::size_t n = mesh_.nodes.size();
    offsets_.assign(n + 1, 0);
    for (const Element& e : mesh_.elements)
      if (IsSolid(e.type))
        for (int k = 0; k < NodeCount(e.type); ++k)
          ++offsets_[e.nodes[k] + 1];
    std::partial_sum(offsets_.begin(), offsets_.end(), offsets_.begin());
    adjacent_.assign(offsets_.back(), 0);
    std::vector<std::size_t> fill(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t e = 0; e < mesh_.elements.size(); ++e) // ascending element ids per node
      if (IsSolid(mesh_.elements[e].type))
        for (int k = 0; k < NodeCount(mesh_.elements[e].type); ++k)
        {
          const auto node = static_cast<std::size_t>(mesh_.elements[e].nodes[k]);
          if (fill[node] == offsets_[node] || adjacent_[fill[node] - 1] != e) // a node listed twice in one element
            adjacent_[fill[node]++] = e;
        }
    // Nodes listed twice in an element leave unused slots: compact.
    std::vector<std::size_t> compact;
    std::vector<std::size_t> newOffsets(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (std::size_t k = offsets_[i]; k < fill[i]; ++k)
        compact.push_back(adjacent_[k]);
      newOffsets[i + 1] = compact.size();
    }
    adjacent_ = std::move(compact);
    offsets_ = std::move(newOffsets);
  }

  const std::vector<std::int32_t>* Set(const char* name) const
  {
    const auto it = mesh_.nodeSets.find(name);
    return it == mesh_.nodeSets.end() ? nullptr : &it->second;
  }

  void BuildConstraints()
  {
    const std::size_t n = mesh_.nodes.size();
    surface_.assign(n, SurfaceKind::None);
    onPlane_.assign(n, 0);
    partner_.resize(n);
    std::iota(partner_.begin(), partner_.end(), 0);

    // Skull first, then skin: a node in both sets follows the skin.
    for (const auto& [name, kind] : {std::pair{"skull", SurfaceKind::Skull}, std::pair{"skin", SurfaceKind::Skin}})
      if (const auto* set = Set(name))
        for (const std::int32_t id : *set)
          surface_[id] = kind;
    auto projector = [&](vtkPolyData* given, SurfaceKind kind) -> std::unique_ptr<SurfaceProjector> {
      if (std::none_of(surface_.begin(), surface_.end(), [&](SurfaceKind k) { return k == kind; }))
        return nullptr;
      if (given != nullptr)
        return std::make_unique<SurfaceProjector>(given);
      // No surface given: the input mesh's own boundary faces made of the set's nodes (or all of them).
      std::vector<char> mask(n, 0);
      for (std::size_t i = 0; i < n; ++i)
        mask[i] = surface_[i] == kind;
      vtkSmartPointer<vtkPolyData> boundary = BoundarySurface(mesh_, &mask);
      if (boundary->GetNumberOfCells() == 0)
        boundary = BoundarySurface(mesh_);
      ownSurfaces_.push_back(boundary);
      return boundary->GetNumberOfCells() > 0 ? std::make_unique<SurfaceProjector>(boundary) : nullptr;
    };
    skin_ = projector(options_.skinSurface, SurfaceKind::Skin);
    skull_ = projector(options_.skullSurface, SurfaceKind::Skull);
    for (std::size_t i = 0; i < n; ++i) // a surface set without any surface face: keep its nodes fixed
      if ((surface_[i] == SurfaceKind::Skin && !skin_) || (surface_[i] == SurfaceKind::Skull && !skull_))
        fixed_.push_back(i);

    const auto* midsagittal = Set("midsagittal");
    if (options_.hasSymmetryPlane)
    {
      plane_ = options_.symmetryPlane;
      if (!(plane_.normal.norm() > 0) || !plane_.normal.allFinite() || !plane_.point.allFinite())
        throw std::invalid_argument("symmetry plane has no valid normal");
      plane_.normal.normalize();
      hasPlane_ = true;
      FindMirrorPairs();
    }
    else if (midsagittal != nullptr && midsagittal->size() >= 3)
      FitPlane(*midsagittal);
    if (hasPlane_ && midsagittal != nullptr)
      for (const std::int32_t id : *midsagittal)
        onPlane_[id] = 1;
    std::sort(fixed_.begin(), fixed_.end());
  }

  double Diagonal() const
  {
    Eigen::AlignedBox3d box;
    for (const Point3& p : mesh_.nodes)
      box.extend(p);
    return box.diagonal().norm();
  }

  // Symmetric input: every node of a solid element has a mirror node of a solid element (same
  // surface kind) within 1e-7 of the mesh size. Nodes of no solid element (embedded muscle points,
  // which may coincide pairwise) never move in the search and are left out. Coincident nodes (a
  // tangle can project two skin nodes onto one surface point) make the position ambiguous: the
  // candidate whose neighbourhood (centroid of its elements' nodes) is the mirror of the node's wins.
  void FindMirrorPairs()
  {
    const std::size_t n = mesh_.nodes.size();
    const double tolerance = 1e-7 * std::max(Diagonal(), 1e-300);
    auto solid = [&](std::size_t i) { return offsets_[i] != offsets_[i + 1]; };
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    std::vector<std::size_t> ids;
    for (std::size_t i = 0; i < n; ++i)
      if (solid(i))
      {
        points->InsertNextPoint(mesh_.nodes[i].data());
        ids.push_back(i);
      }
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(points);
    vtkNew<vtkStaticPointLocator> locator;
    locator->SetDataSet(cloud);
    locator->BuildLocator();
    std::vector<std::int32_t> partner(n);
    std::iota(partner.begin(), partner.end(), 0);
    auto neighbourhood = [&](std::size_t i) {
      Point3 sum = Point3::Zero();
      int count = 0;
      for (std::size_t a = offsets_[i]; a < offsets_[i + 1]; ++a)
      {
        const Element& e = mesh_.elements[adjacent_[a]];
        for (int k = 0; k < NodeCount(e.type); ++k, ++count)
          sum += mesh_.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])];
      }
      return Point3(sum / std::max(count, 1));
    };
    vtkNew<vtkIdList> candidates;
    for (const std::size_t i : ids)
    {
      const Point3 mirror = plane_.Mirror(mesh_.nodes[i]);
      locator->FindPointsWithinRadius(tolerance, mirror.data(), candidates);
      std::size_t best = n;
      double bestMismatch = std::numeric_limits<double>::infinity();
      for (vtkIdType c = 0; c < candidates->GetNumberOfIds(); ++c)
      {
        const std::size_t j = ids[static_cast<std::size_t>(candidates->GetId(c))];
        if (surface_[j] != surface_[i])
          continue;
        const double mismatch =
          candidates->GetNumberOfIds() == 1 ? 0.0 : (plane_.Mirror(neighbourhood(i)) - neighbourhood(j)).norm();
        if (mismatch < bestMismatch || (mismatch == bestMismatch && j < best))
        {
          best = j;
          bestMismatch = mismatch;
        }
      }
      if (best == n)
        return; // not symmetric: nodes move one by one
      partner[i] = static_cast<std::int32_t>(best);
    }
    for (std::size_t i = 0; i < n; ++i)
      if (partner[partner[i]] != static_cast<std::int32_t>(i))
        return;
    partner_ = std::move(partner);
    pairs_ = true;
    for (const std::size_t i : ids)
      if (partner_[i] == static_cast<std::int32_t>(i))
        onPlane_[i] = 1; // its own mirror: must stay on the plane to stay symmetric
  }

  // Mid-sagittal nodes that are coplanar (to 1e-6 of the mesh size) stay on their plane.
  void FitPlane(const std::vector<std::int32_t>& ids)
  {
    Point3 centre = Point3::Zero();
    for (const auto id : ids)
      centre += mesh_.nodes[id];
    centre /= static_cast<double>(ids.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const auto id : ids)
    {
      const Point3 d = mesh_.nodes[id] - centre;
      covariance += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    if (solver.info() != Eigen::Success || !(solver.eigenvalues()(1) > 0))
      return; // collinear or coincident: no plane
    Plane plane;
    plane.point = centre;
    plane.normal = solver.eigenvectors().col(0).normalized();
    double worst = 0;
    for (const auto id : ids)
      worst = std::max(worst, std::abs(plane.SignedDistance(mesh_.nodes[id])));
    if (worst <= 1e-6 * Diagonal())
    {
      plane_ = plane;
      hasPlane_ = true;
    }
  }

  // ---- quality ------------------------------------------------------------------------------
  double Quality(std::size_t e) const
  {
    const double v = quality::ElementQuality(mesh_, e, quality::Measure::ScaledJacobian);
    return (std::isnan(v) || quality::IsVerdictFlag(v)) ? kDegenerate : v;
  }

  struct Progress
  {
    std::size_t bad = 0;
    double score = 0; // sum of the bad elements' qualities, capped below at -1
  };
  Progress Measure(bool regularity) const
  {
    Progress p;
    for (std::size_t e = 0; e < quality_.size(); ++e)
      if (IsSolid(mesh_.elements[e].type) && Bad(e, regularity))
        ++p.bad, p.score += std::max(quality_[e], -1.0) - cap_;
    return p;
  }

  bool Bad(std::size_t e, bool regularity) const
  {
    return regularity ? quality_[e] <= 0 : quality_[e] < threshold_;
  }

  bool IsFixed(std::size_t node) const
  {
    return std::binary_search(fixed_.begin(), fixed_.end(), node);
  }

  // ---- one sweep over the bad elements, worst first ------------------------------------------
  bool Sweep(bool regularity, bool surfaceAllowed)
  {
    std::vector<std::size_t> bad;
    for (std::size_t e = 0; e < mesh_.elements.size(); ++e)
      if (IsSolid(mesh_.elements[e].type) && Bad(e, regularity))
        bad.push_back(e);
    if (bad.empty())
      return false;
    std::stable_sort(bad.begin(), bad.end(), [&](std::size_t a, std::size_t b) { return quality_[a] < quality_[b]; });
    bool changed = false;
    for (const std::size_t e : bad)
    {
      if (!Bad(e, regularity))
        continue; // fixed by an earlier move
      const Element& element = mesh_.elements[e];
      const int count = NodeCount(element.type);
      // Worst corner first (corner Jacobians), ties by local index.
      std::vector<double> corners = quality::CornerJacobians(mesh_, e);
      std::vector<int> order(count);
      std::iota(order.begin(), order.end(), 0);
      if (static_cast<int>(corners.size()) == count)
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return corners[a] < corners[b]; });
      auto optimize = [&](std::size_t node, double cap) {
        const bool constrained = surface_[node] != SurfaceKind::None || onPlane_[node];
        if ((constrained && !surfaceAllowed) || IsFixed(node))
          return;
        if (OptimizeNode(std::min<std::size_t>(node, partner_[node]), cap))
          changed = true;
      };
      for (const int local : order)
      {
        optimize(static_cast<std::size_t>(element.nodes[local]), cap_);
        if (!Bad(e, regularity))
          break;
      }
      if (!ring_ || !Bad(e, regularity))
        continue;
      // Make room: improve the elements around this one well above the threshold, then retry.
      std::vector<std::size_t> around;
      for (int local = 0; local < count; ++local)
      {
        const auto node = static_cast<std::size_t>(element.nodes[local]);
        for (std::size_t k = offsets_[node]; k < offsets_[node + 1]; ++k)
        {
          const Element& neighbour = mesh_.elements[adjacent_[k]];
          for (int i = 0; i < NodeCount(neighbour.type); ++i)
            around.push_back(static_cast<std::size_t>(neighbour.nodes[i]));
        }
      }
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
      for (const std::size_t node : around)
        if (std::find(element.nodes.begin(), element.nodes.begin() + count, static_cast<std::int32_t>(node)) ==
            element.nodes.begin() + count)
          optimize(node, std::min(1.0, threshold_ + kRingMargin));
      for (const int local : order)
      {
        optimize(static_cast<std::size_t>(element.nodes[local]), cap_);
        if (!Bad(e, regularity))
          break;
      }
    }
    return changed;
  }

  // Elements around a node and its mirror partner, ascending.
  std::vector<std::size_t> Patch(std::size_t node) const
  {
    std::vector<std::size_t> patch(adjacent_.begin() + offsets_[node], adjacent_.begin() + offsets_[node + 1]);
    const auto mirror = static_cast<std::size_t>(partner_[node]);
    if (mirror != node)
    {
      patch.insert(patch.end(), adjacent_.begin() + offsets_[mirror], adjacent_.begin() + offsets_[mirror + 1]);
      std::sort(patch.begin(), patch.end());
      patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
    }
    return patch;
  }

  // A proposed position made admissible: on the node's surface, then on the plane.
  Point3 Constrain(std::size_t node, Point3 p) const
  {
    const SurfaceProjector* surface = surface_[node] == SurfaceKind::Skin    ? skin_.get()
                                      : surface_[node] == SurfaceKind::Skull ? skull_.get()
                                                                             : nullptr;
    if (surface != nullptr)
      p = surface->Project(p);
    if (!onPlane_[node])
      return p;
    p = plane_.Project(p);
    // On a surface and the plane: alternate projections onto their intersection curve (they
    // cross nearly at right angles, so this converges in a few steps), ending on the plane.
    for (int i = 0; i < 20 && surface != nullptr; ++i)
    {
      const Point3 q = plane_.Project(surface->Project(p));
      const double step = (q - p).norm();
      p = q;
      if (step <= 1e-13 * (1 + p.norm()))
        break;
    }
    return p;
  }

  void Place(std::size_t node, const Point3& p)
  {
    mesh_.nodes[node] = p;
    const auto mirror = static_cast<std::size_t>(partner_[node]);
    if (mirror != node)
      mesh_.nodes[mirror] = plane_.Mirror(p);
  }

  // Qualities of the patch with the node (and its partner) at p; the mesh is restored.
  void Evaluate(std::size_t node, const Point3& p, const std::vector<std::size_t>& patch, std::vector<double>& out)
  {
    const auto mirror = static_cast<std::size_t>(partner_[node]);
    const Point3 keep = mesh_.nodes[node], keepMirror = mesh_.nodes[mirror];
    Place(node, p);
    out.resize(patch.size());
    for (std::size_t k = 0; k < patch.size(); ++k)
      out[k] = Quality(patch[k]);
    mesh_.nodes[mirror] = keepMirror;
    mesh_.nodes[node] = keep;
  }

  // Leximin improvement of the capped qualities, without pushing a good element below threshold.
  bool Better(const std::vector<double>& before, const std::vector<double>& after, double cap) const
  {
    for (std::size_t k = 0; k < before.size(); ++k)
      if (before[k] >= threshold_ && after[k] < threshold_)
        return false;
    std::vector<double> a(before.size()), b(after.size());
    for (std::size_t k = 0; k < before.size(); ++k)
    {
      a[k] = std::min(before[k], cap);
      b[k] = std::min(after[k], cap);
    }
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    for (std::size_t k = 0; k < a.size(); ++k)
    {
      if (b[k] > a[k] + kEqual)
        return true;
      if (b[k] < a[k] - kEqual)
        return false;
    }
    return false;
  }

  // Where the node would make each of its elements an affine (parallelepiped / straight prism)
  // cell, averaged over its elements; the mean of the element centroids as a smoothing target.
  // Per-element ideal positions are appended to `each` (tried one by one when the means fail:
  // a neighbour that is itself misplaced spoils the mean but not every element's ideal).
  std::pair<Point3, Point3> Targets(std::size_t node, std::vector<Point3>& each) const
  {
    each.clear();
    Point3 ideal = Point3::Zero(), centroids = Point3::Zero();
    int idealCount = 0, count = 0;
    const auto P = [&](const Element& e, int k) -> const Point3& { return mesh_.nodes[e.nodes[k]]; };
    for (std::size_t k = offsets_[node]; k < offsets_[node + 1]; ++k)
    {
      const Element& e = mesh_.elements[adjacent_[k]];
      const int n = NodeCount(e.type);
      Point3 centroid = Point3::Zero();
      int local = -1;
      for (int i = 0; i < n; ++i)
      {
        centroid += P(e, i);
        if (static_cast<std::size_t>(e.nodes[i]) == node)
          local = i;
      }
      centroids += centroid / n;
      ++count;
      if (e.type == ElementType::Hexahedron)
      {
        // Trilinear map without twist: x_c = sum over the 7 other corners of (-1)^(flips+1) x.
        Point3 x = Point3::Zero();
        for (int flip = 1; flip < 8; ++flip)
        {
          const int flips = __builtin_popcount(flip);
          x += (flips % 2 == 1 ? 1.0 : -1.0) * P(e, HexNodeOfBits(kHexBits[local] ^ flip));
        }
        ideal += x;
        each.push_back(x);
        ++idealCount;
      }
      else if (e.type == ElementType::Wedge)
      {
        // Straight prism: same offset to the other triangle as the mean of the two other edges.
        const int other = local < 3 ? local + 3 : local - 3;
        const int base = local < 3 ? 0 : 3, otherBase = 3 - base;
        Point3 offset = Point3::Zero();
        for (int i = 0; i < 3; ++i)
          if (base + i != local)
            offset += P(e, base + i) - P(e, otherBase + i);
        ideal += P(e, other) + offset / 2;
        each.push_back(P(e, other) + offset / 2);
        ++idealCount;
      }
      else if (e.type == ElementType::Tetrahedron)
      {
        // Regular-tet apex over the opposite face, on the side that gives a positive volume.
        int face[3], f = 0;
        for (int i = 0; i < 4; ++i)
          if (i != local)
            face[f++] = i;
        const Point3 a = P(e, face[0]), b = P(e, face[1]), c = P(e, face[2]);
        Point3 normal = (b - a).cross(c - a);
        const double area2 = normal.norm();
        if (area2 > 0)
        {
          const double edge = ((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3;
          normal /= area2;
          // In a valid VTK tet the faces (0,2,3) and (0,1,2) opposite nodes 1 and 3 face their node,
          // while (1,2,3) and (0,1,3) opposite nodes 0 and 2 face away.
          const double sign = (local == 1 || local == 3) ? 1.0 : -1.0;
          each.push_back((a + b + c) / 3 + sign * std::sqrt(2.0 / 3.0) * edge * normal);
          ideal += each.back();
          ++idealCount;
        }
      }
    }
    const Point3 p = mesh_.nodes[node];
    return {idealCount > 0 ? Point3(ideal / idealCount) : p, count > 0 ? Point3(centroids / count) : p};
  }

  // Unit directions spanning the node's admissible moves: 3D (axes and cube diagonals), a surface's
  // tangent plane or the symmetry plane (axes and diagonals of a basis), or their intersection line.
  std::vector<Point3> Directions(std::size_t node, const Point3& p) const
  {
    std::vector<Point3> normals;
    if (surface_[node] == SurfaceKind::Skin)
      normals.push_back(skin_->Normal(p));
    else if (surface_[node] == SurfaceKind::Skull)
      normals.push_back(skull_->Normal(p));
    if (onPlane_[node])
      normals.push_back(plane_.normal);
    normals.erase(std::remove_if(normals.begin(), normals.end(), [](const Point3& n) { return !(n.norm() > 0.5); }),
                  normals.end());
    std::vector<Point3> d;
    if (normals.empty())
    {
      for (int axis = 0; axis < 3; ++axis)
        for (const double s : {1.0, -1.0})
          d.push_back(s * Point3::Unit(axis));
      for (int corner = 0; corner < 8; ++corner)
        d.push_back(Point3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1) / std::sqrt(3.0));
      return d;
    }
    if (normals.size() == 2)
    {
      const Point3 line = normals[0].cross(normals[1]);
      if (line.norm() > 1e-6)
        return {line.normalized(), -line.normalized()};
    }
    const Point3& n = normals[0];
    const Point3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    for (const Point3& t : {t1, t2, Point3((t1 + t2) / std::sqrt(2.0)), Point3((t1 - t2) / std::sqrt(2.0))})
    {
      d.push_back(t);
      d.push_back(-t);
    }
    return d;
  }

  // Local search on one node (and its mirror partner). Returns true when it moved.
  bool OptimizeNode(std::size_t node, double cap)
  {
    const std::vector<std::size_t> patch = Patch(node);
    if (patch.empty())
      return false;
    // Skip a node whose last search with this cap failed and whose elements did not change since.
    auto& failedAt = cap > cap_ ? ringFailedAt_[node] : failedAt_[node];
    std::uint64_t lastChange = 0;
    for (const std::size_t e : patch)
      lastChange = std::max(lastChange, changedAt_[e]);
    if (failedAt > lastChange)
      return false;
    std::vector<double> current(patch.size()), trial;
    for (std::size_t k = 0; k < patch.size(); ++k)
      current[k] = quality_[patch[k]];
    auto capped = [&](const std::vector<double>& v) {
      return *std::min_element(v.begin(), v.end()) >= cap;
    };
    if (capped(current))
      return false;

    const Point3 start = mesh_.nodes[node];
    double reach = 0;
    int others = 0;
    for (std::size_t k = offsets_[node]; k < offsets_[node + 1]; ++k)
    {
      const Element& e = mesh_.elements[adjacent_[k]];
      for (int i = 0; i < NodeCount(e.type); ++i)
        if (static_cast<std::size_t>(e.nodes[i]) != node)
        {
          reach += (mesh_.nodes[e.nodes[i]] - start).norm();
          ++others;
        }
    }
    const double h0 = others > 0 ? 0.25 * reach / others : 0;
    if (!(h0 > 0))
      return false;

    bool moved = false;
    Point3 p = start;
    // Tries a position: keeps it when it improves the patch.
    auto attempt = [&](const Point3& raw) {
      const Point3 q = Constrain(node, raw);
      if (!q.allFinite() || q == p)
        return false;
      Evaluate(node, q, patch, trial);
      if (!Better(current, trial, cap))
        return false;
      p = q;
      current.swap(trial);
      Place(node, p);
      moved = true;
      return true;
    };

    double h = h0;
    bool retryTargets = true;
    std::vector<Point3> each;
    for (int iteration = 0; iteration < 60 && !capped(current); ++iteration)
    {
      // 1. Geometric targets, full and half way (unchanged while the node has not moved).
      if (retryTargets)
      {
        const auto [ideal, centroid] = Targets(node, each);
        if (attempt(ideal) || attempt(centroid) || attempt(0.5 * (p + ideal)) || attempt(0.5 * (p + centroid)))
          continue;
        if (std::any_of(each.begin(), each.end(), [&](const Point3& x) { return attempt(x); }))
          continue;
      }
      // 2. Line search along the gradient of the worst element around the node.
      const std::size_t worst = static_cast<std::size_t>(std::min_element(current.begin(), current.end()) - current.begin());
      bool stepped = false;
      if (current[worst] > kDegenerate)
      {
        const std::vector<std::size_t> one{patch[worst]};
        std::vector<double> value;
        Point3 gradient;
        const double delta = 1e-6 * h0;
        for (int axis = 0; axis < 3; ++axis)
        {
          Point3 q = p;
          q[axis] += delta;
          Evaluate(node, q, one, value);
          gradient[axis] = (value[0] - current[worst]) / delta;
        }
        if (onPlane_[node])
          gradient -= plane_.normal.dot(gradient) * plane_.normal;
        const double norm = gradient.norm();
        if (norm > 0 && std::isfinite(norm))
          stepped = attempt(p + (2 * h / norm) * gradient) || attempt(p + (h / norm) * gradient);
      }
      // 3. Compass steps in the directions the node may move (its surface / plane tangents).
      if (!stepped)
      {
        const std::vector<Point3> directions = Directions(node, p);
        for (std::size_t d = 0; d < directions.size() && !stepped; ++d)
          stepped = attempt(p + h * directions[d]);
      }
      retryTargets = stepped;
      if (stepped)
        continue;
      h /= 2;
      if (h < h0 / 128)
        break;
    }
    ++clock_;
    if (moved)
      for (std::size_t k = 0; k < patch.size(); ++k)
      {
        quality_[patch[k]] = current[k];
        changedAt_[patch[k]] = clock_;
      }
    else
      failedAt = clock_;
    return moved;
  }

  // Muscle nodes that belong to no solid element follow their embedding element.
  void MoveMuscleNodes(const std::vector<Point3>& original)
  {
    for (auto& [name, muscle] : mesh_.muscles)
      for (std::size_t k = 0; k < muscle.nodes.size() && k < muscle.embedding.size(); ++k)
      {
        const auto node = static_cast<std::size_t>(muscle.nodes[k]);
        const Embedding& embedding = muscle.embedding[k];
        if (offsets_[node] != offsets_[node + 1] || embedding.element < 0 ||
            static_cast<std::size_t>(embedding.element) >= mesh_.elements.size())
          continue;
        const Element& e = mesh_.elements[embedding.element];
        const int n = NodeCount(e.type);
        bool changed = false;
        for (int i = 0; i < n; ++i)
          changed = changed || mesh_.nodes[e.nodes[i]] != original[e.nodes[i]];
        if (!changed)
          continue;
        double weights[8] = {};
        switch (e.type)
        {
          case ElementType::Hexahedron: vtkHexahedron::InterpolationFunctions(embedding.pcoords.data(), weights); break;
          case ElementType::Wedge: vtkWedge::InterpolationFunctions(embedding.pcoords.data(), weights); break;
          case ElementType::Tetrahedron: vtkTetra::InterpolationFunctions(embedding.pcoords.data(), weights); break;
          default: continue;
        }
        Point3 x = Point3::Zero();
        for (int i = 0; i < n; ++i)
          x += weights[i] * mesh_.nodes[e.nodes[i]];
        mesh_.nodes[node] = x;
      }
  }

  FEMesh& mesh_;
  const RepairOptions& options_;
  double threshold_ = 0.3, cap_ = 0.35;
  std::vector<std::size_t> offsets_, adjacent_; // node -> solid elements (CSR)
  std::vector<double> quality_;
  std::vector<SurfaceKind> surface_;
  std::vector<char> onPlane_;
  std::vector<std::int32_t> partner_;
  std::vector<std::size_t> fixed_;
  bool pairs_ = false, hasPlane_ = false, ring_ = false;
  // Logical clock of searches: when each element last changed, when each node's search last failed.
  std::uint64_t clock_ = 1;
  std::vector<std::uint64_t> changedAt_, failedAt_, ringFailedAt_;
  Plane plane_;
  std::vector<vtkSmartPointer<vtkPolyData>> ownSurfaces_;
  std::unique_ptr<SurfaceProjector> skin_, skull_;
};

double Value(double v)
{
  return quality::IsVerdictFlag(v) ? -std::numeric_limits<double>::infinity() : v;
}

void CheckSurface(vtkPolyData* surface, const char* name)
{
  if (surface != nullptr && surface->GetNumberOfCells() == 0)
    throw std::invalid_argument(std::string(name) + " surface has no cells");
}
} // namespace

RepairReport RepairMesh(FEMesh& mesh, const RepairOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  mesh.Validate();
  if (mesh.SolidElementCount() == 0)
    throw std::invalid_argument("mesh has no solid element to repair");
  const double threshold = options.scaledJacobianThreshold;
  if (!(threshold >= -1 && threshold <= 1))
    throw std::invalid_argument("scaled Jacobian threshold " + std::to_string(threshold) + " is outside [-1, 1]");
  CheckSurface(options.skinSurface, "skin");
  CheckSurface(options.skullSurface, "skull");

  RepairReport report;
  const quality::QualityOptions sequential{1, {}};
  const quality::QualitySummary before = quality::SummarizeScaledJacobian(mesh, threshold, sequential);
  report.minScaledJacobianBefore = before.min;
  report.meanScaledJacobianBefore = before.mean;
  report.invertedBefore = before.inverted;
  report.belowThresholdBefore = before.belowThreshold;

  quality::QualitySummary after = before;
  if (before.belowThreshold > 0 || before.inverted > 0) // a valid mesh is left untouched
  {
    // The lips move node by node here: close the mouth slit so that they stay together.
    const ClosedMouth closed = CloseMouth(mesh);
    Repairer(mesh, options).Run(report);
    ReopenMouth(mesh, closed);
    after = quality::SummarizeScaledJacobian(mesh, threshold, sequential);
  }
  report.minScaledJacobianAfter = after.min;
  report.meanScaledJacobianAfter = after.mean;
  report.invertedAfter = after.inverted;
  report.belowThresholdAfter = after.belowThreshold;
  report.success = after.belowThreshold == 0 && after.inverted == 0;

  std::vector<std::pair<double, std::size_t>> failed;
  const std::vector<double> values = quality::ComputeQuality(mesh, quality::Measure::ScaledJacobian, sequential);
  for (std::size_t e = 0; e < values.size(); ++e)
    if (!std::isnan(values[e]) && (quality::IsVerdictFlag(values[e]) || values[e] < threshold))
      failed.emplace_back(Value(values[e]), e);
  std::sort(failed.begin(), failed.end());
  for (const auto& [value, e] : failed)
  {
    report.failedElements.push_back(e);
    report.failedValues.push_back(value);
  }
  if (options.progress)
    options.progress(1.0);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

} // namespace mmrep
