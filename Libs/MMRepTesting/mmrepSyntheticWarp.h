// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// A known, smooth, invertible map between a source head and a synthetic subject, for testing the
// registration against ground truth.
//
// Direction convention (read this before using the fields):
//   Forward  F : source point x  -> subject point y  (where a source structure ends up in the subject)
//   Inverse  G = F⁻¹ : subject y -> source x
// The synthetic image is I_subject(y) = I_source(G(y)), so the subject is resampled with G (ITK's
// resampling convention: output point -> input point). G is defined explicitly,
//   G(y) = W(Rigid⁻¹(y)),  Rigid(z) = R (z - c) + c + t,  W(z) = z + u(z),
// with R the head rotation (roll about the AP axis, pitch about LR, yaw about SI) about the centre
// c, t a translation and u a sum of Gaussian bumps u(z) = Σ a_k exp(-|z - c_k|² / 2σ²) with random
// centres c_k and vectors a_k (fixed seed). F = Rigid ∘ W⁻¹ is computed by the fixed-point
// iteration z ← x - u(z), a contraction because |∇u| < 1.
//
// Invertibility bound: each bump's gradient has Frobenius norm |a_k| (r/σ²) e^{-r²/2σ²} ≤
// |a_k| e^{-1/2}/σ, so ‖∇u‖₂ ≤ L = Σ|a_k| e^{-1/2}/σ everywhere. The constructor requires L ≤ 0.2,
// hence det ∇W = det(I + ∇u) ≥ (1 - L)³ ≥ 0.512 and det ∇F ≥ 1/(1 + L)³ ≥ 0.578: both > 0.5.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace mmrep
{

struct SyntheticWarpParameters
{
  double rollDegrees = 8.0;                         // about the anterior-posterior axis (LPS y)
  double pitchDegrees = 0.0;                        // about the left-right axis (LPS x)
  double yawDegrees = 5.0;                          // about the superior axis (LPS z)
  Eigen::Vector3d translation{4.0, -3.0, 2.0};      // mm
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(); // rotation centre (source space, mm)
  int bumps = 6;                                    // Gaussian bumps in u
  double amplitude = 2.5;                           // mm, |a_k| of each bump
  double width = 50.0;                              // mm, σ of the bumps
  std::uint32_t seed = 1;                           // random centres and directions
  // Box (source space, mm) where the bump centres are drawn.
  Eigen::Vector3d regionMin = Eigen::Vector3d::Constant(-100.0);
  Eigen::Vector3d regionMax = Eigen::Vector3d::Constant(100.0);
};

class SyntheticWarp
{
public:
  static constexpr double kMaximumGradient = 0.2; // bound L on ‖∇u‖ accepted by the constructor

  // Throws std::invalid_argument for |angle| > 15°, non-positive width, negative amplitude, fewer
  // than 0 or more than 1000 bumps, an empty region, or a gradient bound above kMaximumGradient.
  explicit SyntheticWarp(const SyntheticWarpParameters& parameters);

  Eigen::Vector3d Forward(const Eigen::Vector3d& source) const;  // F: source -> subject
  Eigen::Vector3d Inverse(const Eigen::Vector3d& subject) const; // G: subject -> source

  Eigen::Vector3d Displacement(const Eigen::Vector3d& z) const;          // u(z), source space
  Eigen::Matrix3d DisplacementGradient(const Eigen::Vector3d& z) const;  // ∂u/∂z
  Eigen::Matrix3d InverseJacobian(const Eigen::Vector3d& subject) const; // ∂G/∂y
  Eigen::Matrix3d ForwardJacobian(const Eigen::Vector3d& source) const;  // ∂F/∂x

  double GradientBound() const { return gradientBound_; } // L above
  const Eigen::Matrix3d& Rotation() const { return rotation_; }
  const SyntheticWarpParameters& Parameters() const { return parameters_; }

private:
  SyntheticWarpParameters parameters_;
  Eigen::Matrix3d rotation_;
  std::vector<Eigen::Vector3d> centres_, vectors_;
  double gradientBound_ = 0;
};

} // namespace mmrep
