// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Step 2 of the atlas: the (theta, phi) grid of rays over the left half of the face, graded from
// the mesh size to the lips' size over the mouth.
#include "mmrepFaceAtlasStages.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace mmrep
{
namespace
{
constexpr double kDeg = M_PI / 180.0;
// The face region must close within this angle of the face centre (beyond it rays graze the head).
constexpr double kMaximumProfileAngle = 85 * kDeg;
// Step (deg) of the search along the mid-sagittal profile for the top and bottom rows.
constexpr double kProfileStepDeg = 0.25;
// The fine (lips) size extends this far past the lip corner (mm), so the corner is inside it.
constexpr double kMouthPastCorner = 6.0;

// Sizes along an axis: positions from a to b with spacing h(x) (angles), rescaled to end at b.
std::vector<double> Graded(double a, double b, const std::function<double(double)>& h)
{
  std::vector<double> x{a};
  while (x.back() < b)
    x.push_back(x.back() + h(x.back()));
  // Drop the last step when it overshoots by more than half a step, then stretch to end at b.
  if (x.size() > 2 && x.back() - b > 0.5 * (x.back() - x[x.size() - 2]))
    x.pop_back();
  const double scale = (b - a) / (x.back() - a);
  for (auto& v : x)
    v = a + (v - a) * scale;
  x.back() = b;
  return x;
}

// Size h at position x: `fine` inside [lo, hi], `coarse` beyond `ramp` outside, linear in between.
double Size(double x, double lo, double hi, double ramp, double fine, double coarse)
{
  const double d = x < lo ? lo - x : x > hi ? x - hi : 0;
  return fine + (coarse - fine) * std::min(1.0, d / ramp);
}

// The first profile angle from `from` (stepping by stepDeg) whose skin point satisfies `stop`.
double ProfileAngle(const SurfaceRays& skin, const Eigen::Vector3d& c, double from, double stepDeg,
                    const std::function<bool(const FacePoint&)>& stop)
{
  for (double a = from;; a += stepDeg * kDeg)
  {
    if (std::abs(a) > kMaximumProfileAngle)
      throw std::runtime_error("face atlas: the face region does not close within +-85 deg of the face centre");
    const FacePoint p = SkinHit(skin, c, 0, a);
    if (stop(p))
      return a;
  }
}
} // namespace

FaceMouthRegion LayOutFaceGrid(const SurfaceRays& skin, const Eigen::Vector3d& c, const FaceLandmarkSet& lm,
                               const FaceAtlasOptions& options, FaceGrid& grid)
{
  const double phiTop = ProfileAngle(skin, c, lm.nasion.phi, kProfileStepDeg, [&](const FacePoint& p) {
    return p.local.z() >= lm.nasion.local.z() + options.browMargin;
  });
  const double phiBottom = ProfileAngle(skin, c, lm.pogonion.phi, -kProfileStepDeg, [&](const FacePoint& p) {
    return p.local.z() <= lm.pogonion.local.z() - options.chinMargin;
  });
  const double radius = (lm.stomion.local - c).norm(); // nominal radius: mm -> radians
  FaceMouthRegion mouth;
  mouth.rho = std::hypot(lm.lipCorner.local.x(), lm.lipCorner.local.y() - c.y());
  const double rho = mouth.rho;
  const double thetaMax = options.lateralAngle * kDeg;
  mouth.mouthLo = lm.labiomental.phi;
  mouth.mouthHi = lm.subnasale.phi;
  mouth.lateral = lm.lipCorner.theta + kMouthPastCorner / rho;
  grid.phi = Graded(phiBottom, phiTop, [&](double x) {
    return Size(x * radius, mouth.mouthLo * radius, mouth.mouthHi * radius, options.gradingLength, options.lipsMeshSize,
                options.meshSize) /
           radius;
  });
  grid.theta = Graded(0, thetaMax, [&](double x) {
    return Size(x * rho, -1e9, mouth.lateral * rho, options.gradingLength, options.lipsMeshSize, options.meshSize) /
           rho;
  });
  const auto& r = options.layerRatios;
  grid.levels = {0, r[0] / (r[0] + r[1] + r[2]), (r[0] + r[1]) / (r[0] + r[1] + r[2]), 1.0};
  return mouth;
}

} // namespace mmrep
