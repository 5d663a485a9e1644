// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The engine behind OptimizeElastic (internal): energy terms and the sweeps moving one grid node at a time.
#pragma once

#include "mmrepElasticOptimizer.h"
#include "mmrepHexQuality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

namespace mmrep::elastic
{

constexpr int kPad = 2;   // padded cells beyond the box (boundary supports reach one cell out)
constexpr int kHeld = -2; // pointMap of a held point

class Engine
{
public:
  Engine(ElasticTransform& t, ElasticProblem& p, const ElasticOptimizerOptions& o)
      : transform_(t), problem_(p), options_(o)
  {
    // Hexahedra of each point (CSR) and their current quality, for the mesh guard.
    const std::size_t n = problem_.points.size();
    hexStart_.assign(n + 1, 0);
    for (const auto& h : problem_.hexahedra)
      for (int v : h)
        ++hexStart_[static_cast<std::size_t>(v) + 1];
    for (std::size_t i = 0; i < n; ++i)
      hexStart_[i + 1] += hexStart_[i];
    hexOfPoint_.resize(hexStart_[n]);
    std::vector<std::size_t> fill(hexStart_.begin(), hexStart_.end() - 1);
    for (std::size_t h = 0; h < problem_.hexahedra.size(); ++h)
      for (int v : problem_.hexahedra[h])
        hexOfPoint_[fill[static_cast<std::size_t>(v)]++] = static_cast<int>(h);
    hexQuality_.resize(problem_.hexahedra.size());
    for (std::size_t h = 0; h < problem_.hexahedra.size(); ++h)
      hexQuality_[h] = HexQuality(h, nullptr);
    hexStamp_.assign(problem_.hexahedra.size(), 0);
    start_ = problem_.points;
    trialSlot_.assign(n, -1);
  }

  ElasticOptimizerStats stats_;

  // Scaled Jacobian of hexahedron h; `moved` (slot per point, -1 = unmoved) gives trial positions.
  double HexQuality(std::size_t h, const std::vector<Eigen::Vector3d>* moved) const
  {
    quality::HexNodes nodes;
    for (int c = 0; c < 8; ++c)
    {
      const auto v = static_cast<std::size_t>(problem_.hexahedra[h][static_cast<std::size_t>(c)]);
      nodes[static_cast<std::size_t>(c)] =
        moved && trialSlot_[v] >= 0 ? (*moved)[static_cast<std::size_t>(trialSlot_[v])] : problem_.points[v];
    }
    return quality::HexScaledJacobian(nodes);
  }

  // Mesh guard for a step moving the points `ids` to `moved`: every hexahedron touched keeps
  // min(floor, its quality before). On success the touched hexahedra's qualities are updated.
  bool GuardAccepts(const std::vector<int>& ids, const std::vector<Eigen::Vector3d>& moved)
  {
    if (problem_.hexahedra.empty())
      return true;
    ++stamp_;
    touched_.clear();
    for (std::size_t j = 0; j < ids.size(); ++j)
      if (static_cast<std::size_t>(ids[j]) < problem_.points.size())
        trialSlot_[static_cast<std::size_t>(ids[j])] = static_cast<int>(j);
    bool ok = true;
    for (std::size_t j = 0; j < ids.size() && ok; ++j)
    {
      const auto k = static_cast<std::size_t>(ids[j]);
      if (k >= problem_.points.size())
        continue;
      for (std::size_t a = hexStart_[k]; a < hexStart_[k + 1] && ok; ++a)
      {
        const auto h = static_cast<std::size_t>(hexOfPoint_[a]);
        if (hexStamp_[h] == stamp_)
          continue;
        hexStamp_[h] = stamp_;
        const double q = HexQuality(h, &moved);
        ok = q >= std::min(options_.elementQualityFloor, hexQuality_[h]);
        touched_.emplace_back(h, q);
      }
    }
    for (int k : ids)
      if (static_cast<std::size_t>(k) < problem_.points.size())
        trialSlot_[static_cast<std::size_t>(k)] = -1;
    if (ok)
      for (const auto& [h, q] : touched_)
        hexQuality_[h] = q;
    return ok;
  }

  std::size_t Count() const { return problem_.points.size() + problem_.controlSources.size(); }
  Eigen::Vector3d& Position(std::size_t k)
  {
    return k < problem_.points.size() ? problem_.points[k] : problem_.controlSources[k - problem_.points.size()];
  }

  // Energy term of tracked point k at position p, and its gradient (frame coordinates).
  double Term(std::size_t k, const Eigen::Vector3d& p, Eigen::Vector3d* g) const
  {
    if (k < problem_.points.size())
    {
      if (problem_.pointMap[k] < 0)
      {
        if (problem_.pointMap[k] == kHeld && holdingWeight_ > 0)
        {
          const Eigen::Vector3d w = p - levelStart_[k];
          if (g)
            *g = 2.0 * holdingWeight_ * w;
          return holdingWeight_ * w.squaredNorm();
        }
        if (g)
          g->setZero();
        return 0.0;
      }
      Eigen::Vector3d gw;
      const double v =
        problem_.maps[static_cast<std::size_t>(problem_.pointMap[k])].Value(transform_.ToWorld(p), g ? &gw : nullptr);
      // |d|: a signed map (negative inside) gives the same energy as an unsigned one, but its
      // trilinear interpolation crosses zero at the surface instead of rounding off the V of |d|.
      const double sign = v < 0 ? -1.0 : 1.0;
      const Eigen::Vector3d u = p - start_[k];
      double e = sign * v + options_.tieWeight * u.squaredNorm();
      if (g)
        *g = sign * (transform_.frameRotation * gw) + 2.0 * options_.tieWeight * u;
      if (slidingWeight_ > 0)
      {
        const Eigen::Vector3d& n = levelNormal_[k];
        const Eigen::Vector3d w = p - levelStart_[k];
        const Eigen::Vector3d t = w - n.dot(w) * n;
        e += slidingWeight_ * t.squaredNorm();
        if (g)
          *g += 2.0 * slidingWeight_ * t;
      }
      return e;
    }
    const std::size_t i = k - problem_.points.size();
    const Eigen::Vector3d d = p - problem_.controlTargets[i];
    const double n = d.norm();
    if (g)
      *g = n > 0 ? Eigen::Vector3d(problem_.controlWeights[i] * d / n) : Eigen::Vector3d::Zero();
    return problem_.controlWeights[i] * n;
  }

  double TotalEnergy()
  {
    double e = 0;
    for (std::size_t k = 0; k < Count(); ++k)
      e += Term(k, Position(k), nullptr);
    return e;
  }

  void UpdateWeights()
  {
    for (std::size_t i = 0; i < problem_.controlSources.size(); ++i)
      if ((problem_.controlSources[i] - problem_.controlTargets[i]).norm() > options_.controlPointTolerance)
        problem_.controlWeights[i] = std::min(2.0 * problem_.controlWeights[i], options_.controlPointWeightCap);
  }

  long long CellKey(const Eigen::Vector3d& p) const
  {
    long long key = 0;
    for (int a = 2; a >= 0; --a)
    {
      const double c = std::floor((p[a] - level_->boxMin[a]) / level_->h[a]);
      if (!(c >= -kPad && c <= level_->cells - 1 + kPad))
        return -1;
      key = key * dim_ + (static_cast<long long>(c) + kPad);
    }
    return key;
  }

  void Bucket()
  {
    cells_.clear();
    cellOf_.assign(Count(), -1);
    for (std::size_t k = 0; k < Count(); ++k)
    {
      cellOf_[k] = CellKey(Position(k));
      if (cellOf_[k] >= 0)
        cells_[cellOf_[k]].push_back(static_cast<int>(k));
    }
  }

  void Move(std::size_t k, const Eigen::Vector3d& p)
  {
    Position(k) = p;
    const long long key = CellKey(p);
    if (key == cellOf_[k])
      return;
    if (cellOf_[k] >= 0)
    {
      auto& v = cells_[cellOf_[k]];
      v.erase(std::find(v.begin(), v.end(), static_cast<int>(k)));
    }
    cellOf_[k] = key;
    if (key >= 0)
      cells_[key].push_back(static_cast<int>(k));
  }

  double NodeCoordinate(int axis, int i) const
  {
    // Symmetric grids: x nodes at (i − cells/2) h so that mirror nodes are exact negatives.
    if (options_.symmetric && axis == 0)
      return (i - level_->cells / 2) * level_->h.x();
    return level_->boxMin[axis] + i * level_->h[axis];
  }

  // Points possibly in the support of node (ix, iy, iz): its 2×2×2 cells plus one cell of slack.
  void Gather(int ix, int iy, int iz, std::vector<int>& out) const
  {
    for (int z = iz - 2; z <= iz + 1; ++z)
      for (int y = iy - 2; y <= iy + 1; ++y)
        for (int x = ix - 2; x <= ix + 1; ++x)
        {
          if (x + kPad < 0 || y + kPad < 0 || z + kPad < 0 || x + kPad >= dim_ || y + kPad >= dim_ || z + kPad >= dim_)
            continue;
          const long long key = ((static_cast<long long>(z + kPad) * dim_) + (y + kPad)) * dim_ + (x + kPad);
          const auto it = cells_.find(key);
          if (it != cells_.end())
            out.insert(out.end(), it->second.begin(), it->second.end());
        }
  }

  // Sorted node ids (z, y, x order) whose support holds at least one point; symmetric grids keep
  // the node of each mirror pair with x index ≤ cells/2.
  std::vector<long long> CandidateNodes() const
  {
    const int n = level_->cells;
    const int lo = options_.fixBoundary ? 1 : 0, hi = options_.fixBoundary ? n - 1 : n;
    std::vector<long long> nodes;
    for (const auto& [key, ids] : cells_)
    {
      if (ids.empty())
        continue;
      long long r = key;
      const int cx = static_cast<int>(r % dim_) - kPad;
      r /= dim_;
      const int cy = static_cast<int>(r % dim_) - kPad;
      const int cz = static_cast<int>(r / dim_) - kPad;
      for (int z = cz; z <= cz + 1; ++z)
        for (int y = cy; y <= cy + 1; ++y)
          for (int x = cx; x <= cx + 1; ++x)
          {
            if (x < lo || x > hi || y < lo || y > hi || z < lo || z > hi)
              continue;
            const int mx = options_.symmetric ? std::min(x, n - x) : x;
            nodes.push_back((static_cast<long long>(z) * (n + 1) + y) * (n + 1) + mx);
          }
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
  }

  // One node: gradient, line search, step. Returns true when a step was taken.
  bool VisitNode(long long id, double maxStep)
  {
    const int n = level_->cells;
    const int ix = static_cast<int>(id % (n + 1));
    const int iy = static_cast<int>((id / (n + 1)) % (n + 1));
    const int iz = static_cast<int>(id / ((n + 1) * (n + 1)));
    ElasticStep step;
    step.node = Eigen::Vector3d(NodeCoordinate(0, ix), NodeCoordinate(1, iy), NodeCoordinate(2, iz));
    const bool onPlane = options_.symmetric && 2 * ix == n;
    step.mirrored = options_.symmetric && !onPlane;
    gathered_.clear();
    Gather(ix, iy, iz, gathered_);
    if (step.mirrored)
      Gather(n - ix, iy, iz, gathered_);
    std::sort(gathered_.begin(), gathered_.end());
    gathered_.erase(std::unique(gathered_.begin(), gathered_.end()), gathered_.end());
    if (gathered_.empty())
      return false;

    const Eigen::Vector3d mirrorNode(-step.node.x(), step.node.y(), step.node.z());
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    double e0 = 0;
    active_.clear();
    passive_.clear();
    for (int k : gathered_)
    {
      const Eigen::Vector3d& p = Position(static_cast<std::size_t>(k));
      const double f1 = ElasticTransform::Bump(p, step.node, level_->h);
      const double f2 = step.mirrored ? ElasticTransform::Bump(p, mirrorNode, level_->h) : 0.0;
      if (f1 == 0.0 && f2 == 0.0)
        continue;
      if (IsPassive(static_cast<std::size_t>(k)))
      {
        passive_.push_back(k); // no energy: moved only for the mesh guard
        continue;
      }
      Eigen::Vector3d ge;
      e0 += Term(static_cast<std::size_t>(k), p, &ge);
      g += f1 * ge;
      if (step.mirrored)
        g += f2 * Eigen::Vector3d(-ge.x(), ge.y(), ge.z()); // d/dδ of the mirrored displacement Mδ
      active_.push_back(k);
    }
    if (onPlane)
      g.x() = 0; // plane nodes move within the plane
    const double gn = g.norm();
    if (active_.empty() || !(gn > 0))
      return false;
    const Eigen::Vector3d direction = -g / gn;
    // Mirror supports overlapping (node within one cell of the plane): two bumps add up, halve.
    double alpha = maxStep;
    if (step.mirrored && std::abs(step.node.x()) < level_->h.x())
      alpha *= 0.5;

    auto trial = [&](double a, std::vector<Eigen::Vector3d>& moved) {
      ElasticStep s = step;
      s.delta = a * direction;
      if (onPlane)
        s.delta.x() = 0;
      double e = 0;
      moved.resize(active_.size());
      for (std::size_t j = 0; j < active_.size(); ++j)
      {
        const auto k = static_cast<std::size_t>(active_[j]);
        moved[j] = ElasticTransform::ApplyStep(s, level_->h, Position(k));
        e += Term(k, moved[j], nullptr);
      }
      return std::make_pair(e, s);
    };
    for (int halving = 0; halving < 12; ++halving, alpha *= 0.5)
    {
      auto [e, s] = trial(alpha, movedA_);
      if (!(e < e0))
        continue;
      // Keep halving while the energy keeps dropping: the best of the halving sequence, which
      // avoids overshooting steps that later steps would have to undo.
      for (int more = halving + 1; more < 16; ++more)
      {
        alpha *= 0.5;
        auto [eHalf, sHalf] = trial(alpha, movedB_);
        if (!(eHalf < e))
          break;
        e = eHalf;
        s = sHalf;
        movedA_.swap(movedB_);
      }
      // Mesh guard: shorten the step while it would spoil an element, as long as it still helps.
      for (int shorten = 0;; ++shorten)
      {
        AppendPassive(s, movedA_);
        if (GuardAccepts(allIds_, movedA_))
          break;
        if (shorten == 4)
        {
          ++stats_.droppedSteps;
          return false;
        }
        ++stats_.guardedSteps;
        const double a = 0.5 * s.delta.norm();
        auto [eShort, sShort] = trial(a, movedA_);
        if (!(eShort < e0))
        {
          ++stats_.droppedSteps;
          return false;
        }
        s = sShort;
      }
      for (std::size_t j = 0; j < allIds_.size(); ++j)
        Move(static_cast<std::size_t>(allIds_[j]), movedA_[j]);
      level_->steps.push_back(s);
      return true;
    }
    return false;
  }

  // Reference positions and unit surface normals (frame coordinates) of the attracted points at
  // the start of level l, for the sliding term.
  void StartSliding(int l)
  {
    slidingWeight_ = l >= options_.regularizationFirstLevel ? options_.slidingWeight : 0.0;
    holdingWeight_ = l >= options_.regularizationFirstLevel ? options_.holdingWeight : 0.0;
    if (!(slidingWeight_ > 0) && !(holdingWeight_ > 0))
      return;
    levelStart_ = problem_.points;
    if (!(slidingWeight_ > 0))
      return; // the holding term needs no normals
    levelNormal_.assign(problem_.points.size(), Eigen::Vector3d::Zero());
    for (std::size_t k = 0; k < problem_.points.size(); ++k)
    {
      if (problem_.pointMap[k] < 0)
        continue;
      Eigen::Vector3d gw;
      problem_.maps[static_cast<std::size_t>(problem_.pointMap[k])].Value(transform_.ToWorld(problem_.points[k]), &gw);
      const Eigen::Vector3d g = transform_.frameRotation * gw;
      // Where the map has no clear direction (far outside, flat), no direction is preferred: the
      // whole displacement counts as sliding.
      levelNormal_[k] = g.norm() > 0.5 ? Eigen::Vector3d(g.normalized()) : Eigen::Vector3d::Zero();
    }
  }

  bool IsPassive(std::size_t k) const
  {
    return k < problem_.points.size() && problem_.pointMap[k] < 0 &&
           !(problem_.pointMap[k] == kHeld && holdingWeight_ > 0);
  }

  // movedA_ holds the active points' trial positions; append the passive points' (same step) and
  // list every moved point in allIds_, same order.
  void AppendPassive(const ElasticStep& s, std::vector<Eigen::Vector3d>& moved)
  {
    moved.resize(active_.size());
    allIds_ = active_;
    for (int k : passive_)
    {
      moved.push_back(ElasticTransform::ApplyStep(s, level_->h, Position(static_cast<std::size_t>(k))));
      allIds_.push_back(k);
    }
  }

  ElasticOptimizerStats Run()
  {
    ElasticOptimizerStats& stats = stats_;
    if (options_.firstLevel < 1 || options_.finestLevel < options_.firstLevel || options_.finestLevel > 10)
      throw std::invalid_argument("elastic registration: levels must satisfy 1 <= first <= finest <= 10");
    if (!(options_.stepSafety > 0 && options_.stepSafety < 1))
      throw std::invalid_argument("elastic registration: the step safety factor must be in (0, 1)");
    const Eigen::Vector3d extent = problem_.boxMax - problem_.boxMin;
    if (!(extent.minCoeff() > 0))
      throw std::invalid_argument("elastic registration: the grid box is empty");
    stats.initialEnergy = TotalEnergy();
    const int levelCount = options_.finestLevel - options_.firstLevel + 1;
    for (int l = options_.firstLevel; l <= options_.finestLevel; ++l)
    {
      ElasticLevel level;
      level.level = l;
      level.cells = 1 << l;
      level.boxMin = problem_.boxMin;
      level.h = extent / level.cells;
      transform_.levels.push_back(level);
      level_ = &transform_.levels.back();
      dim_ = level_->cells + 2 * kPad;
      const double maxStep = options_.stepSafety / MaximumBumpGradient(level_->h);
      StartSliding(l);
      Bucket();
      int sweeps = 0;
      double energy = TotalEnergy();
      while (sweeps < options_.maximumSweeps)
      {
        ++sweeps;
        const auto nodes = CandidateNodes();
        for (long long id : nodes)
          VisitNode(id, maxStep);
        const double after = TotalEnergy();
        const bool converged = !(energy - after > options_.tolerance * std::max(energy, 1e-12));
        UpdateWeights();
        energy = TotalEnergy(); // with the new weights
        if (options_.progress)
          options_.progress((l - options_.firstLevel + std::min(1.0, double(sweeps) / options_.maximumSweeps)) /
                            levelCount);
        if (converged)
          break;
      }
      stats.sweepsPerLevel.push_back(sweeps);
      stats.energyAfterLevel.push_back(energy);
      if (options_.progress)
        options_.progress(double(l - options_.firstLevel + 1) / levelCount);
    }
    transform_.BuildIndex();
    return stats;
  }

private:
  ElasticTransform& transform_;
  ElasticProblem& problem_;
  const ElasticOptimizerOptions& options_;
  ElasticLevel* level_ = nullptr;
  long long dim_ = 0;
  std::unordered_map<long long, std::vector<int>> cells_;
  std::vector<long long> cellOf_;
  std::vector<int> gathered_, active_, passive_, allIds_;
  // Mesh guard.
  std::vector<std::size_t> hexStart_;
  std::vector<int> hexOfPoint_;
  std::vector<double> hexQuality_;
  std::vector<unsigned> hexStamp_;
  unsigned stamp_ = 0;
  std::vector<int> trialSlot_;
  std::vector<Eigen::Vector3d> start_;                    // points at the start (the tie's reference)
  double slidingWeight_ = 0, holdingWeight_ = 0;          // μ_s and μ_h of the current level
  std::vector<Eigen::Vector3d> levelStart_, levelNormal_; // sliding term's reference and normals
  std::vector<std::pair<std::size_t, double>> touched_;
  std::vector<Eigen::Vector3d> movedA_, movedB_;
};

} // namespace mmrep::elastic
