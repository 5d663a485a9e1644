// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The node-by-node repair, see mmrepNodeByNodeRepair.h.
#include "mmrepNodeByNodeRepair.h"

#include "mmrepCertifiedJacobian.h"
#include "mmrepIdealPositions.h"
#include "mmrepMeshQuality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace mmrep
{
namespace
{
constexpr double kDegenerate = -2.0; // quality of a Verdict-flagged (collapsed) element
constexpr double kMargin = 0.05;     // elements are improved up to threshold + margin
constexpr double kRingMargin = 0.4;  // elements around a stuck one are improved up to threshold + this
constexpr double kEqual = 1e-12;     // qualities closer than this compare equal

bool IsSolid(ElementType t)
{
  return t != ElementType::Cable;
}
} // namespace

NodeByNodeRepair::NodeByNodeRepair(FEMesh& mesh, const RepairOptions& options, const NodeElements& adjacency,
                                   const RepairConstraints& constraints, bool certifyInside)
    : mesh_(mesh), options_(options), adjacency_(adjacency), constraints_(constraints), certifyInside_(certifyInside)
{
  threshold_ = options.scaledJacobianThreshold;
  cap_ = std::min(1.0, threshold_ + kMargin);
  Reset();
}

void NodeByNodeRepair::Reset()
{
  quality_.assign(mesh_.elements.size(), std::numeric_limits<double>::infinity());
  for (std::size_t e = 0; e < mesh_.elements.size(); ++e)
    if (IsSolid(mesh_.elements[e].type))
      quality_[e] = Quality(e);
  clock_ = 1;
  changedAt_.assign(mesh_.elements.size(), 0);
  failedAt_.assign(mesh_.nodes.size(), 0);
  ringFailedAt_.assign(mesh_.nodes.size(), 0);
}

void NodeByNodeRepair::Run(double from, double to)
{
  auto report = [&](double f) {
    if (options_.progress)
      options_.progress(from + (to - from) * std::min(1.0, f));
  };
  // Phase 1: regularity (inverted first), phase 2: threshold. In each phase inner nodes move
  // first, then surface nodes too, then also the nodes around the bad elements (to make room).
  struct Stage
  {
    bool regularity, surfaceAllowed, ring;
  };
  const Stage plan[] = {{true, false, false},  {true, true, false},  {true, true, true},
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
        report((pass * stages + stage + double(sweep + 1) / options_.maximumSweeps) / stages);
        const bool progressed = now.bad < last.bad || now.score > last.score + 1e-3 * double(last.bad);
        last = now;
        if (!changed || !progressed)
          break;
      }
      report(double(pass * stages + stage + 1) / stages);
    }
  }
  report(1);
}

std::vector<std::size_t> NodeByNodeRepair::BadElements(bool regularity) const
{
  std::vector<std::size_t> bad;
  for (std::size_t e = 0; e < mesh_.elements.size(); ++e)
    if (IsSolid(mesh_.elements[e].type) && Bad(e, regularity))
      bad.push_back(e);
  return bad;
}

bool NodeByNodeRepair::State::BetterThan(const State& other) const
{
  if (inverted != other.inverted)
    return inverted < other.inverted;
  if (below != other.below)
    return below < other.below;
  return minimum > other.minimum;
}

NodeByNodeRepair::State NodeByNodeRepair::Current() const
{
  State state;
  state.minimum = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < quality_.size(); ++e)
    if (IsSolid(mesh_.elements[e].type))
    {
      state.inverted += Bad(e, true) ? 1 : 0;
      state.below += Bad(e, false) ? 1 : 0;
      state.minimum = std::min(state.minimum, quality_[e]);
    }
  return state;
}

double NodeByNodeRepair::Quality(std::size_t e) const
{
  const double v = quality::ElementQuality(mesh_, e, quality::Measure::ScaledJacobian);
  if (std::isnan(v) || quality::IsVerdictFlag(v))
    return kDegenerate;
  return v > 0 && certifyInside_ ? quality::CertifiedQuality(mesh_, e, v) : v;
}

NodeByNodeRepair::Progress NodeByNodeRepair::Measure(bool regularity) const
{
  Progress p;
  for (std::size_t e = 0; e < quality_.size(); ++e)
    if (IsSolid(mesh_.elements[e].type) && Bad(e, regularity))
      ++p.bad, p.score += std::max(quality_[e], -1.0) - cap_;
  return p;
}

bool NodeByNodeRepair::Bad(std::size_t e, bool regularity) const
{
  return regularity ? quality_[e] <= 0 : quality_[e] < threshold_;
}

// ---- one sweep over the bad elements, worst first ------------------------------------------
bool NodeByNodeRepair::Sweep(bool regularity, bool surfaceAllowed)
{
  std::vector<std::size_t> bad = BadElements(regularity);
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
      const bool constrained = constraints_.Constrained(node);
      if ((constrained && !surfaceAllowed) || constraints_.IsFixed(node))
        return;
      if (OptimizeNode(std::min<std::size_t>(node, constraints_.Partner(node)), cap))
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
      for (std::size_t k = adjacency_.offsets[node]; k < adjacency_.offsets[node + 1]; ++k)
      {
        const Element& neighbour = mesh_.elements[adjacency_.adjacent[k]];
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
std::vector<std::size_t> NodeByNodeRepair::Patch(std::size_t node) const
{
  std::vector<std::size_t> patch(adjacency_.adjacent.begin() + adjacency_.offsets[node],
                                 adjacency_.adjacent.begin() + adjacency_.offsets[node + 1]);
  const auto mirror = static_cast<std::size_t>(constraints_.Partner(node));
  if (mirror != node)
  {
    patch.insert(patch.end(), adjacency_.adjacent.begin() + adjacency_.offsets[mirror],
                 adjacency_.adjacent.begin() + adjacency_.offsets[mirror + 1]);
    std::sort(patch.begin(), patch.end());
    patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
  }
  return patch;
}

void NodeByNodeRepair::Place(std::size_t node, const Point3& p)
{
  mesh_.nodes[node] = p;
  const auto mirror = static_cast<std::size_t>(constraints_.Partner(node));
  if (mirror != node)
    mesh_.nodes[mirror] = constraints_.SymmetryPlane().Mirror(p);
}

// Qualities of the patch with the node (and its partner) at p; the mesh is restored.
void NodeByNodeRepair::Evaluate(std::size_t node, const Point3& p, const std::vector<std::size_t>& patch,
                                std::vector<double>& out)
{
  const auto mirror = static_cast<std::size_t>(constraints_.Partner(node));
  const Point3 keep = mesh_.nodes[node], keepMirror = mesh_.nodes[mirror];
  Place(node, p);
  out.resize(patch.size());
  for (std::size_t k = 0; k < patch.size(); ++k)
    out[k] = Quality(patch[k]);
  mesh_.nodes[mirror] = keepMirror;
  mesh_.nodes[node] = keep;
}

// Leximin improvement of the capped qualities, without pushing a good element below threshold.
bool NodeByNodeRepair::Better(const std::vector<double>& before, const std::vector<double>& after, double cap) const
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

bool NodeByNodeRepair::OptimizeNode(std::size_t node, double cap)
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
  auto capped = [&](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()) >= cap; };
  if (capped(current))
    return false;

  const Point3 start = mesh_.nodes[node];
  double reach = 0;
  int others = 0;
  for (std::size_t k = adjacency_.offsets[node]; k < adjacency_.offsets[node + 1]; ++k)
  {
    const Element& e = mesh_.elements[adjacency_.adjacent[k]];
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
    const Point3 q = constraints_.Constrain(node, raw);
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
      const auto [ideal, centroid] = IdealPositions(mesh_, adjacency_, node, each);
      if (attempt(ideal) || attempt(centroid) || attempt(0.5 * (p + ideal)) || attempt(0.5 * (p + centroid)))
        continue;
      if (std::any_of(each.begin(), each.end(), [&](const Point3& x) { return attempt(x); }))
        continue;
    }
    // 2. Line search along the gradient of the worst element around the node.
    const std::size_t worst =
      static_cast<std::size_t>(std::min_element(current.begin(), current.end()) - current.begin());
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
      if (constraints_.OnPlane(node))
        gradient -= constraints_.SymmetryPlane().normal.dot(gradient) * constraints_.SymmetryPlane().normal;
      const double norm = gradient.norm();
      if (norm > 0 && std::isfinite(norm))
        stepped = attempt(p + (2 * h / norm) * gradient) || attempt(p + (h / norm) * gradient);
    }
    // 3. Compass steps in the directions the node may move (its surface / plane tangents).
    if (!stepped)
    {
      const std::vector<Point3> directions = constraints_.Directions(node, p);
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

} // namespace mmrep
