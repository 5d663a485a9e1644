// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Synthetic subject warp: rigid head motion and a smooth random Gaussian-bump displacement.
#include "mmrepSyntheticWarp.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace mmrep
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

// Uniform in [0, 1) from the raw 32-bit output: std::mt19937's sequence is fixed by the standard,
// the <random> distributions are not, so this keeps the warp identical across standard libraries.
double Uniform(std::mt19937& rng)
{
  return static_cast<double>(rng()) / 4294967296.0;
}
} // namespace

SyntheticWarp::SyntheticWarp(const SyntheticWarpParameters& p) : parameters_(p)
{
  for (double a : {p.rollDegrees, p.pitchDegrees, p.yawDegrees})
    if (!(std::abs(a) <= 15.0))
      throw std::invalid_argument("synthetic warp: rotation angle " + std::to_string(a) + " deg is outside [-15, 15]");
  if (!p.translation.allFinite() || !p.centre.allFinite())
    throw std::invalid_argument("synthetic warp: translation and centre must be finite");
  if (!(p.width > 0) || !std::isfinite(p.width))
    throw std::invalid_argument("synthetic warp: bump width must be > 0 mm");
  if (!(p.amplitude >= 0) || !std::isfinite(p.amplitude))
    throw std::invalid_argument("synthetic warp: bump amplitude must be >= 0 mm");
  if (p.bumps < 0 || p.bumps > 1000)
    throw std::invalid_argument("synthetic warp: bump count must be in [0, 1000]");
  if (!((p.regionMax - p.regionMin).minCoeff() >= 0) || !p.regionMin.allFinite() || !p.regionMax.allFinite())
    throw std::invalid_argument("synthetic warp: empty region for the bump centres");

  rotation_ = (Eigen::AngleAxisd(p.yawDegrees * kPi / 180, Eigen::Vector3d::UnitZ()) *
               Eigen::AngleAxisd(p.rollDegrees * kPi / 180, Eigen::Vector3d::UnitY()) *
               Eigen::AngleAxisd(p.pitchDegrees * kPi / 180, Eigen::Vector3d::UnitX()))
                .toRotationMatrix();

  std::mt19937 rng(p.seed);
  for (int k = 0; k < p.bumps; ++k)
  {
    Eigen::Vector3d c;
    for (int d = 0; d < 3; ++d)
      c(d) = p.regionMin(d) + Uniform(rng) * (p.regionMax(d) - p.regionMin(d));
    // Direction uniform on the sphere (z uniform in [-1, 1], azimuth uniform).
    const double z = 2.0 * Uniform(rng) - 1.0;
    const double phi = 2.0 * kPi * Uniform(rng);
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    centres_.push_back(c);
    vectors_.push_back(p.amplitude * Eigen::Vector3d(s * std::cos(phi), s * std::sin(phi), z));
  }
  gradientBound_ = p.bumps * p.amplitude * std::exp(-0.5) / p.width;
  if (gradientBound_ > kMaximumGradient)
    throw std::invalid_argument(
      "synthetic warp: bumps x amplitude too large for the width (gradient bound " + std::to_string(gradientBound_) +
      " > " + std::to_string(kMaximumGradient) +
      "; need bumps * amplitude <= " + std::to_string(kMaximumGradient * p.width / std::exp(-0.5)) + " mm)");
}

Eigen::Vector3d SyntheticWarp::Displacement(const Eigen::Vector3d& z) const
{
  const double inv2s2 = 0.5 / (parameters_.width * parameters_.width);
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < centres_.size(); ++k)
    u += vectors_[k] * std::exp(-(z - centres_[k]).squaredNorm() * inv2s2);
  return u;
}

Eigen::Matrix3d SyntheticWarp::DisplacementGradient(const Eigen::Vector3d& z) const
{
  const double s2 = parameters_.width * parameters_.width;
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < centres_.size(); ++k)
  {
    const Eigen::Vector3d r = z - centres_[k];
    g -= vectors_[k] * r.transpose() * (std::exp(-0.5 * r.squaredNorm() / s2) / s2);
  }
  return g;
}

Eigen::Vector3d SyntheticWarp::Inverse(const Eigen::Vector3d& y) const
{
  const Eigen::Vector3d& c = parameters_.centre;
  const Eigen::Vector3d z = rotation_.transpose() * (y - c - parameters_.translation) + c;
  return z + Displacement(z);
}

Eigen::Vector3d SyntheticWarp::Forward(const Eigen::Vector3d& x) const
{
  // W⁻¹(x): z = x - u(z); u is L-Lipschitz with L <= 0.2, so each step shrinks the error 5-fold.
  Eigen::Vector3d z = x;
  for (int i = 0; i < 100; ++i)
  {
    const Eigen::Vector3d next = x - Displacement(z);
    const double change = (next - z).norm();
    z = next;
    if (change < 1e-13 * (1.0 + x.norm()))
      break;
  }
  const Eigen::Vector3d& c = parameters_.centre;
  return rotation_ * (z - c) + c + parameters_.translation;
}

Eigen::Matrix3d SyntheticWarp::InverseJacobian(const Eigen::Vector3d& y) const
{
  const Eigen::Vector3d& c = parameters_.centre;
  const Eigen::Vector3d z = rotation_.transpose() * (y - c - parameters_.translation) + c;
  return (Eigen::Matrix3d::Identity() + DisplacementGradient(z)) * rotation_.transpose();
}

Eigen::Matrix3d SyntheticWarp::ForwardJacobian(const Eigen::Vector3d& x) const
{
  return InverseJacobian(Forward(x)).inverse();
}

} // namespace mmrep
