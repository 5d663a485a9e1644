// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Foldover-free energy, see mmrepFoldoverFreeEnergy.h.
#include "mmrepFoldoverFreeEnergy.h"

#include "mmrepWorkerThreads.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

namespace mmrep
{

double FoldoverChi(double eps, double d)
{
  const double root = std::sqrt(eps * eps + d * d);
  return d > 0 ? (d + root) / 2 : 0.5 * eps * eps / (root - d);
}

double FoldoverChiDerivative(double eps, double d)
{
  return 0.5 + d / (2 * std::sqrt(eps * eps + d * d));
}

FoldoverFreeEnergy::FoldoverFreeEnergy(std::vector<JacobianFrame> frames, double theta)
    : frames_(std::move(frames)), theta_(theta)
{
}

FoldoverFreeEnergy::Term FoldoverFreeEnergy::FrameTerm(const JacobianFrame& frame, const std::vector<Point3>& x,
                                                       double eps, bool withGradient) const
{
  Term term;
  const Eigen::Matrix3d j = FrameJacobian(frame, x);
  const double d = j.determinant();
  const double c1 = FoldoverChi(eps, d), c2 = std::cbrt(c1 * c1), c3 = FoldoverChiDerivative(eps, d);
  const double f = j.squaredNorm() / c2, g = (1 + d * d) / c1;
  term.energy = frame.weight * ((1 - theta_) * f + theta_ * g);
  if (!withGradient)
    return term;
  Eigen::Matrix3d cofactor; // d(det J)/dJ
  cofactor.col(0) = j.col(1).cross(j.col(2));
  cofactor.col(1) = j.col(2).cross(j.col(0));
  cofactor.col(2) = j.col(0).cross(j.col(1));
  const Eigen::Matrix3d df = 2 * j / c2 - (2 * f * c3 / (3 * c1)) * cofactor;
  const Eigen::Matrix3d dg = ((2 * d - g * c3) / c1) * cofactor;
  term.gradient = frame.weight * ((1 - theta_) * df + theta_ * dg);
  return term;
}

double FoldoverFreeEnergy::Evaluate(const std::vector<Point3>& x, double eps, std::vector<Point3>* gradient) const
{
  // The frames' terms in parallel, then summed and scattered in frame order: the same bits on any
  // number of threads.
  constexpr std::size_t kChunk = 2048;
  const std::size_t n = frames_.size(), chunks = (n + kChunk - 1) / kChunk;
  terms_.resize(n);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t c = next++; c < chunks; c = next++)
      for (std::size_t k = c * kChunk, end = std::min(n, k + kChunk); k < end; ++k)
        terms_[k] = FrameTerm(frames_[k], x, eps, gradient != nullptr);
  };
  std::vector<std::thread> workers;
  for (unsigned t = 1; t < std::min<std::size_t>(WorkerThreads(), chunks); ++t)
    workers.emplace_back(work);
  work();
  for (std::thread& w : workers)
    w.join();
  double energy = 0;
  for (std::size_t k = 0; k < n; ++k)
  {
    energy += terms_[k].energy;
    if (gradient != nullptr)
      for (int i = 0; i < frames_[k].count; ++i)
        (*gradient)[frames_[k].nodes[i]] += terms_[k].gradient * frames_[k].w[i];
  }
  return energy;
}

double FoldoverFreeEnergy::MinimumDeterminant(const std::vector<Point3>& x) const
{
  double minimum = std::numeric_limits<double>::infinity();
  for (const JacobianFrame& frame : frames_)
    minimum = std::min(minimum, FrameJacobian(frame, x).determinant());
  return minimum;
}

std::vector<std::size_t> FoldoverFreeEnergy::InvertedElements(const std::vector<Point3>& x) const
{
  std::vector<std::size_t> inverted;
  for (const JacobianFrame& frame : frames_)
    if (!(FrameJacobian(frame, x).determinant() > 0))
      inverted.push_back(frame.element);
  std::sort(inverted.begin(), inverted.end());
  inverted.erase(std::unique(inverted.begin(), inverted.end()), inverted.end());
  return inverted;
}

} // namespace mmrep
