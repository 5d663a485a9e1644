// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The foldover-free energy of Garanzha, Kaporin, Kudryavtseva, Protais, Ray, Sokolov, "Foldover-free
// maps in 50 lines of code" (ACM TOG 40(4), 2021), on the Jacobian frames of a mesh's elements
// (mmrepJacobianFrames.h). Each frame adds weight x ((1 - theta) f + theta g) with
//   f = |J|_F^2 / chi(eps, det J)^(2/3)   (shape)   and   g = (1 + det J^2) / chi(eps, det J)   (volume),
// where chi(eps, d) = (d + sqrt(eps^2 + d^2)) / 2 is a positive regularisation of det J: for eps > 0 the
// energy is finite and smooth even for inverted frames, and as eps -> 0 it becomes a barrier that
// keeps every frame positive. Minimising it while decreasing eps untangles the mesh.
#pragma once

#include "mmrepJacobianFrames.h"

#include <vector>

namespace mmrep
{

// chi(eps, d) evaluated without cancellation for negative d, and its derivative in d.
double FoldoverChi(double eps, double d);
double FoldoverChiDerivative(double eps, double d);

class FoldoverFreeEnergy
{
public:
  FoldoverFreeEnergy(std::vector<JacobianFrame> frames, double theta = 0.5);

  // The energy at node positions `x`; adds dE/dx to `gradient` (indexed like x) when it is given.
  // Runs on WorkerThreads(); one Evaluate at a time per object (it reuses a scratch buffer).
  double Evaluate(const std::vector<Point3>& x, double eps, std::vector<Point3>* gradient = nullptr) const;
  // The smallest det J over the frames, and the elements with a frame det J <= 0 (ascending).
  double MinimumDeterminant(const std::vector<Point3>& x) const;
  std::vector<std::size_t> InvertedElements(const std::vector<Point3>& x) const;

  const std::vector<JacobianFrame>& Frames() const { return frames_; }

private:
  struct Term
  {
    double energy = 0;
    Eigen::Matrix3d gradient; // dE/dJ of the frame
  };
  Term FrameTerm(const JacobianFrame& frame, const std::vector<Point3>& x, double eps, bool withGradient) const;

  std::vector<JacobianFrame> frames_;
  double theta_;
  mutable std::vector<Term> terms_;
};

} // namespace mmrep
