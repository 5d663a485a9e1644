// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The elastic registration function R = r_N ∘ … ∘ r_1 ∘ A of MMRep (paper §3.1–3.3).
//
// A is a similarity (the initial alignment, identity for a local refinement Q). Each elementary
// step moves one node n of a virtual grid level by δ:
//   r(x) = x + δ φ((x − n)/h),  φ(u) = b(u_x) b(u_y) b(u_z),  b(t) = (1−|t|)²(1+2|t|) for |t| ≤ 1, else 0,
// h = the level's cell size per axis. b(0) = 1, b(±1) = b'(±1) = 0 and b' is continuous, so φ is
// C1 on R³ and vanishes with its gradient on the boundary of the node's 8 cells.
// Non-folding: ∇r = I + δ ∇φᵀ has det = 1 + δ·∇φ ≥ 1 − |δ| L with L = max|∇φ| (computed by
// MaximumBumpGradient), so |δ| < 1/L makes r a C1 diffeomorphism (injective: |δ·(φ(x)−φ(y))| ≤
// |δ|L|x−y| < |x−y|), and R, a composition of such maps, is one too with det ∇R = Π det ∇r_n > 0.
// The optimiser keeps |δ| ≤ safety/L (safety 0.4 by default, so det ∇r_n ≥ 0.6).
//
// Symmetry: steps live in a "frame" (a rigid copy of LPS whose x = 0 plane is the subject's
// symmetry plane). A mirrored step moves node n by δ and its mirror Mn by Mδ (M flips frame x);
// a node on the plane moves within it. Every step then commutes with M, bit for bit in frame
// coordinates (the arithmetic is written so that negating x negates every intermediate).
//
// Direction: Apply maps ATLAS points to SUBJECT points. ToDisplacementField samples
// u(x) = R(x) − x on a grid placed in atlas space: Slicer/ITK treat such a grid transform as a
// "from parent" (resampling) transform, i.e. it pulls an image defined in subject space back
// onto the atlas grid (output point x takes the subject value at x + u(x)). To move models or
// markups from atlas to subject in Slicer, load the field as a transform and invert it (or
// harden the inverse); to resample a subject volume into atlas space, use it as is.
#pragma once

#include <functional>

#include "mmrepImageIO.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace mmrep
{

// b(t) and b'(t) of the C1 bump.
double ElasticBump(double t);
double ElasticBumpDerivative(double t);
// max over u of |∇φ| for cell sizes h (exact maximiser found by grid + pattern search; the
// maximum over the cube is reached inside it, so the search is over [0,1]³ by symmetry).
double MaximumBumpGradient(const Eigen::Vector3d& h);

// One elementary step, in frame coordinates.
struct ElasticStep
{
  Eigen::Vector3d node = Eigen::Vector3d::Zero();
  Eigen::Vector3d delta = Eigen::Vector3d::Zero();
  bool mirrored = false; // also moves the mirror node (−n_x, n_y, n_z) by (−δ_x, δ_y, δ_z)
};

// One level of the virtual grid, in frame coordinates: `cells` cells per axis over
// [boxMin, boxMin + cells ∘ h]. Steps are applied in order within a level, levels in order.
struct ElasticLevel
{
  int level = 1;
  Eigen::Vector3d boxMin = Eigen::Vector3d::Zero();
  Eigen::Vector3d h = Eigen::Vector3d::Ones();
  int cells = 2;
  std::vector<ElasticStep> steps;
};

class ElasticTransform
{
public:
  // Initial alignment (world → world), applied first.
  Eigen::Matrix3d preLinear = Eigen::Matrix3d::Identity();
  Eigen::Vector3d preTranslation = Eigen::Vector3d::Zero();
  // Frame: f = frameRotation (x − frameOrigin); rows of frameRotation are the frame axes.
  Eigen::Matrix3d frameRotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d frameOrigin = Eigen::Vector3d::Zero();
  std::vector<ElasticLevel> levels;

  Eigen::Vector3d ToFrame(const Eigen::Vector3d& world) const { return frameRotation * (world - frameOrigin); }
  Eigen::Vector3d ToWorld(const Eigen::Vector3d& frame) const
  {
    return frameRotation.transpose() * frame + frameOrigin;
  }
  bool HasPreTransform() const;
  Eigen::Vector3d PreApply(const Eigen::Vector3d& x) const
  {
    return HasPreTransform() ? Eigen::Vector3d(preLinear * x + preTranslation) : x;
  }

  // R(x). A point that no step touches and with an identity pre-transform is returned bit for bit.
  Eigen::Vector3d Apply(const Eigen::Vector3d& x) const;
  // ∂R/∂x (chain rule through every step).
  Eigen::Matrix3d Jacobian(const Eigen::Vector3d& x) const;
  // The elastic part only, frame → frame (no pre-transform, no frame change).
  Eigen::Vector3d ApplyInFrame(const Eigen::Vector3d& f, Eigen::Matrix3d* jacobian = nullptr) const;

  std::size_t StepCount() const;
  std::vector<std::size_t> StepsPerLevel() const;
  // Call after adding steps, before Apply: buckets every level's steps by grid cell.
  void BuildIndex();

  // u(x) = R(x) − x at every voxel of `grid` (its geometry only: origin, spacing, direction, size).
  DisplacementField::Pointer ToDisplacementField(const itk::ImageBase<3>* grid) const;

  // Pieces used by the optimiser (same arithmetic as Apply, so tracked points stay bit-identical).
  static double Bump(const Eigen::Vector3d& p, const Eigen::Vector3d& node, const Eigen::Vector3d& h,
                     Eigen::Vector3d* gradient = nullptr);
  static Eigen::Vector3d ApplyStep(const ElasticStep& step, const Eigen::Vector3d& h, const Eigen::Vector3d& p,
                                   Eigen::Matrix3d* jacobian = nullptr);

private:
  // Per level: for each (padded) cell, the indices of the steps whose support may reach it.
  struct LevelIndex
  {
    int pad = 2;
    int dim = 0;                      // cells + 2 pad per axis
    std::vector<std::uint32_t> start; // CSR offsets, dim³ + 1
    std::vector<std::uint32_t> steps;
  };
  std::vector<LevelIndex> index_;
  bool indexed_ = false;
};

// u(x) = map(x) − x at every voxel of the allocated `field` (float storage). Voxels are independent:
// slabs of z run on up to 8 threads, and the bytes do not depend on the split.
void FillDisplacementField(DisplacementField* field, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& map);

} // namespace mmrep
