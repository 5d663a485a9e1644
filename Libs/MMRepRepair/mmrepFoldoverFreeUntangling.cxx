// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Foldover-free untangling, see mmrepFoldoverFreeUntangling.h.
#include "mmrepFoldoverFreeUntangling.h"

#include "mmrepFoldoverFreeEnergy.h"

#include <LBFGS.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mmrep
{
namespace
{
void AddElementNodes(const FEMesh& mesh, std::size_t e, std::vector<std::size_t>& nodes)
{
  const Element& element = mesh.elements[e];
  for (int k = 0; k < NodeCount(element.type); ++k)
    nodes.push_back(static_cast<std::size_t>(element.nodes[k]));
}

void Unique(std::vector<std::size_t>& v)
{
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// The nodes that move (those of the seeds and of their neighbours, with their mirror partners,
// without fixed nodes or pairs with a fixed partner) and the elements around them.
struct Region
{
  std::vector<std::size_t> nodes, elements;
};

Region FindRegion(const FEMesh& mesh, const NodeElements& adjacency, const RepairConstraints& constraints,
                  const std::vector<std::size_t>& seeds)
{
  std::vector<std::size_t> seedNodes, ring;
  for (const std::size_t e : seeds)
    AddElementNodes(mesh, e, seedNodes);
  Unique(seedNodes);
  for (const std::size_t n : seedNodes)
    ring.insert(ring.end(), adjacency.adjacent.begin() + adjacency.offsets[n],
                adjacency.adjacent.begin() + adjacency.offsets[n + 1]);
  Unique(ring);
  Region region;
  for (const std::size_t e : ring)
    AddElementNodes(mesh, e, region.nodes);
  for (std::size_t k = 0, n = region.nodes.size(); k < n; ++k)
    region.nodes.push_back(constraints.Partner(region.nodes[k]));
  Unique(region.nodes);
  region.nodes.erase(std::remove_if(region.nodes.begin(), region.nodes.end(),
                                    [&](std::size_t n) {
                                      return constraints.IsFixed(n) || constraints.IsFixed(constraints.Partner(n));
                                    }),
                     region.nodes.end());
  for (const std::size_t n : region.nodes)
    region.elements.insert(region.elements.end(), adjacency.adjacent.begin() + adjacency.offsets[n],
                           adjacency.adjacent.begin() + adjacency.offsets[n + 1]);
  Unique(region.elements);
  return region;
}

// The unknowns: one free node per mirror pair (the smaller id), moving from a base point along the
// directions its constraints allow (3 inside, 2 on a surface or the plane, 1 on both).
class Unknowns
{
public:
  Unknowns(const RepairConstraints& constraints, const std::vector<std::size_t>& nodes) : constraints_(constraints)
  {
    for (const std::size_t n : nodes)
      if (n <= constraints.Partner(n))
        nodes_.push_back(n);
  }

  // Takes the mesh's positions as the base, with the directions allowed there.
  void Rebase(const std::vector<Point3>& x)
  {
    base_.clear();
    basis_.clear();
    offsets_.assign(1, 0);
    for (const std::size_t n : nodes_)
    {
      base_.push_back(x[n]);
      const std::vector<Point3> d = constraints_.Directions(n, x[n]);
      Eigen::Matrix3Xd basis = Eigen::Matrix3d::Identity();
      if (d.size() == 2)
        basis = d[0];
      else if (d.size() == 8)
      {
        basis.resize(3, 2);
        basis << d[0], d[2];
      }
      basis_.push_back(basis);
      offsets_.push_back(offsets_.back() + basis.cols());
    }
  }

  Eigen::Index Size() const { return offsets_.back(); }

  // Moves the nodes to z; with `onSurfaces`, constrained nodes go onto their surfaces and the plane
  // (what the energy then sees is where they will be; the gradient stays the tangent one).
  void Apply(const Eigen::VectorXd& z, std::vector<Point3>& x, bool onSurfaces = false) const
  {
    for (std::size_t k = 0; k < nodes_.size(); ++k)
    {
      const Point3 p = base_[k] + basis_[k] * z.segment(offsets_[k], basis_[k].cols());
      Place(nodes_[k], onSurfaces && basis_[k].cols() < 3 ? constraints_.Constrain(nodes_[k], p) : p, x);
    }
  }

  // Projects the nodes onto their surfaces and the plane (the end of a minimisation).
  void Constrain(std::vector<Point3>& x) const
  {
    for (const std::size_t n : nodes_)
      Place(n, constraints_.Constrain(n, x[n]), x);
  }

  // dE/dz from dE/dx (a partner's gradient reflected through the plane).
  void Pull(const std::vector<Point3>& gradient, Eigen::VectorXd& dz) const
  {
    const Plane& plane = constraints_.SymmetryPlane();
    for (std::size_t k = 0; k < nodes_.size(); ++k)
    {
      Point3 g = gradient[nodes_[k]];
      const std::size_t partner = constraints_.Partner(nodes_[k]);
      if (partner != nodes_[k])
      {
        const Point3& m = gradient[partner];
        g += m - 2 * plane.normal.dot(m) * plane.normal;
      }
      dz.segment(offsets_[k], basis_[k].cols()) = basis_[k].transpose() * g;
    }
  }

  void ClearGradient(std::vector<Point3>& gradient) const
  {
    for (const std::size_t n : nodes_)
      gradient[n].setZero(), gradient[constraints_.Partner(n)].setZero();
  }

private:
  void Place(std::size_t n, const Point3& p, std::vector<Point3>& x) const
  {
    x[n] = p;
    const std::size_t partner = constraints_.Partner(n);
    if (partner != n)
      x[partner] = constraints_.SymmetryPlane().Mirror(p);
  }

  const RepairConstraints& constraints_;
  std::vector<std::size_t> nodes_;
  std::vector<Point3> base_;
  std::vector<Eigen::Matrix3Xd> basis_;
  std::vector<Eigen::Index> offsets_;
};

// E(z) for LBFGSpp; remembers the best point it saw (a failed line search leaves the solver elsewhere).
struct Objective
{
  const FoldoverFreeEnergy& energy;
  const Unknowns& unknowns;
  std::vector<Point3>& x;
  std::vector<Point3>& gradient;
  double eps;
  bool projected;
  double best = std::numeric_limits<double>::infinity();
  Eigen::VectorXd bestZ;

  double operator()(const Eigen::VectorXd& z, Eigen::VectorXd& dz)
  {
    unknowns.Apply(z, x, projected);
    unknowns.ClearGradient(gradient);
    const double e = energy.Evaluate(x, eps, &gradient);
    unknowns.Pull(gradient, dz);
    if (!std::isfinite(e) || !dz.allFinite())
      return std::numeric_limits<double>::infinity();
    if (e < best)
      best = e, bestZ = z;
    return e;
  }
};

// One minimisation at fixed eps from the base point; leaves x at the best point found.
void Minimize(const FoldoverFreeEnergy& energy, const Unknowns& unknowns, double eps, int iterations, bool projected,
              std::vector<Point3>& x)
{
  std::vector<Point3> gradient(x.size(), Point3::Zero());
  Objective objective{energy, unknowns, x, gradient, eps, projected};
  LBFGSpp::LBFGSParam<double> parameters;
  parameters.m = 7;
  parameters.epsilon = 1e-9;
  parameters.max_iterations = iterations;
  parameters.max_linesearch = 40;
  parameters.min_step = 1e-20;
  parameters.linesearch = LBFGSpp::LBFGS_LINESEARCH_BACKTRACKING_ARMIJO;
  LBFGSpp::LBFGSSolver<double> solver(parameters);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(unknowns.Size());
  double value = 0;
  try
  {
    solver.minimize(objective, z, value);
  }
  catch (const std::exception&)
  {
    // A line search that cannot go further: the best point seen so far is the result.
  }
  if (objective.bestZ.size() == z.size())
    unknowns.Apply(objective.bestZ, x, projected);
}

// A valid region: a few minimisations with a small eps (the energy is then a barrier keeping every
// frame positive), each kept only when it leaves nothing inverted.
void Relax(const FoldoverFreeEnergy& energy, Unknowns& unknowns, const UntanglingOptions& options,
           std::vector<Point3>& x, UntanglingResult& result)
{
  constexpr double kEps = 1e-3; // det J is about 1 for a well-shaped frame
  constexpr int kSteps = 5;
  for (int step = 0; step < kSteps; ++step)
  {
    ++result.steps;
    const std::vector<Point3> previous = x;
    unknowns.Rebase(x);
    const double before = energy.Evaluate(x, kEps);
    Minimize(energy, unknowns, kEps, options.iterationsPerStep, true, x);
    unknowns.Constrain(x);
    const double after = energy.Evaluate(x, kEps);
    if (!(after < before) || !energy.InvertedElements(x).empty())
    {
      x = previous;
      break;
    }
    result.kept = true;
    if (options.progress)
      options.progress(double(step + 1) / kSteps);
    if (before - after <= 1e-3 * after)
      break;
  }
}
} // namespace

UntanglingResult UntangleFoldovers(FEMesh& mesh, const NodeElements& adjacency, const RepairConstraints& constraints,
                                   const std::vector<std::size_t>& seeds, const UntanglingOptions& options)
{
  UntanglingResult result;
  const Region region = FindRegion(mesh, adjacency, constraints, seeds);
  result.freeNodes = region.nodes.size();
  std::vector<JacobianFrame> frames;
  for (const std::size_t e : region.elements)
    AppendJacobianFrames(mesh, e, frames);
  const FoldoverFreeEnergy energy(std::move(frames), options.theta);
  std::vector<Point3> x = mesh.nodes;
  result.invertedBefore = result.invertedAfter = energy.InvertedElements(x).size();
  if (region.nodes.empty() || (result.invertedBefore == 0 && !options.relaxValid))
    return result;

  Unknowns unknowns(constraints, region.nodes);
  if (result.invertedBefore == 0)
  {
    Relax(energy, unknowns, options, x, result);
    if (result.kept)
      mesh.nodes = x;
    return result;
  }
  std::vector<Point3> best = x;
  std::size_t fewest = result.invertedBefore;
  double detmin = energy.MinimumDeterminant(x);
  double eps = std::max(options.initialEps, 0.2 * std::abs(std::min(detmin, 0.0)));
  for (int stale = 0, valid = 0; result.steps < options.maximumSteps && stale < options.patience;)
  {
    ++result.steps;
    unknowns.Rebase(x);
    const double before = energy.Evaluate(x, eps);
    Minimize(energy, unknowns, eps, options.iterationsPerStep, false, x);
    unknowns.Constrain(x);
    const double after = energy.Evaluate(x, eps);
    detmin = energy.MinimumDeterminant(x);
    const std::size_t inverted = energy.InvertedElements(x).size();
    if (inverted < fewest || inverted == 0)
      fewest = inverted, best = x, stale = 0;
    else
      ++stale;
    if (options.progress)
      options.progress(1 - double(fewest) / double(result.invertedBefore));
    // Once valid, a few more steps with the barrier improve the shapes for the threshold phase.
    if (inverted == 0 && (++valid >= 5 || std::abs(before - after) <= 1e-3 * after))
      break;
    // eps follows the smallest determinant (Garanzha et al. 2021, section 3).
    const double sigma = std::max(1 - after / before, 0.1);
    const double mu = (1 - sigma) * FoldoverChi(eps, detmin);
    eps = detmin < mu ? 2 * std::sqrt(mu * (mu - detmin)) : 1e-10;
  }
  result.invertedAfter = fewest;
  result.kept = fewest < result.invertedBefore;
  if (result.kept)
    mesh.nodes = best;
  return result;
}

} // namespace mmrep
