// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFaceLandmarks.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mmrep
{
namespace
{
constexpr double kDeg = M_PI / 180.0;
constexpr double kFar = 250.0; // mm: every ray from the centre leaves the head before this

std::string Describe(const std::string& name, const FacePoint& p)
{
  std::ostringstream s;
  s.precision(4);
  s << name << ": theta " << p.theta / kDeg << " deg, phi " << p.phi / kDeg << " deg, local (" << p.local.x() << ", "
    << p.local.y() << ", " << p.local.z() << ")";
  return s.str();
}

// Components (4-connected) of the open cells of a rows x cols grid, labelled in scan order:
// deterministic.
std::vector<std::vector<int>> OpenComponents(const std::vector<int>& open, int rows, int cols)
{
  std::vector<int> label(rows * cols, -1);
  std::vector<std::vector<int>> comps;
  for (int s = 0; s < rows * cols; ++s)
  {
    if (!open[s] || label[s] >= 0)
      continue;
    comps.emplace_back();
    std::vector<int> stack{s};
    label[s] = static_cast<int>(comps.size()) - 1;
    while (!stack.empty())
    {
      const int q = stack.back();
      stack.pop_back();
      comps.back().push_back(q);
      const int r = q / cols, c = q % cols;
      const int nb[4][2] = {{r - 1, c}, {r + 1, c}, {r, c - 1}, {r, c + 1}};
      for (const auto& n : nb)
        if (n[0] >= 0 && n[0] < rows && n[1] >= 0 && n[1] < cols && open[n[0] * cols + n[1]] &&
            label[n[0] * cols + n[1]] < 0)
        {
          label[n[0] * cols + n[1]] = label[s];
          stack.push_back(n[0] * cols + n[1]);
        }
    }
  }
  return comps;
}

// Left orbital opening (rays meeting no bone under the skin) and the eye corners.
void DetectOrbit(const SurfaceRays& skin, const SurfaceRays& bone, const Eigen::Vector3d& centre, FaceLandmarkSet& lm)
{
  // --- Left orbital opening: rays meeting no bone within 25 mm under the skin.
  const double orbitDepth = 25.0;
  const double da = 1.0 * kDeg;
  const double phi0 = lm.nasion.phi - 16 * kDeg, theta0 = 4 * kDeg;
  const int rows = 22, cols = 57; // phi: nasion -16 .. +5 deg; theta: 4 .. 60 deg
  std::vector<FacePoint> hits(rows * cols);
  std::vector<int> open(rows * cols, 0);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
    {
      const FacePoint p = SkinHit(skin, centre, theta0 + c * da, phi0 + r * da);
      const Eigen::Vector3d in = -RayDirection(p.theta, p.phi);
      hits[r * cols + c] = p;
      open[r * cols + c] = bone.First(p.local, p.local + orbitDepth * in) ? 0 : 1;
    }
  const std::vector<std::vector<int>> comps = OpenComponents(open, rows, cols);
  // Expected eye centre: 32 mm lateral of the midline, 4 mm below the nasion.
  const double eyeRadius = (lm.nasion.local - centre).norm();
  const double seedTheta = std::atan2(32.0, lm.nasion.local.y() - centre.y() - 10.0);
  const double seedPhi = lm.nasion.phi - 4.0 / eyeRadius;
  int bestComp = -1;
  double bestD = 1e300;
  for (int k = 0; k < static_cast<int>(comps.size()); ++k)
  {
    if (comps[k].size() < 5)
      continue;
    for (int q : comps[k])
    {
      const double d = std::hypot(hits[q].theta - seedTheta, hits[q].phi - seedPhi);
      if (d < bestD)
      {
        bestD = d;
        bestComp = k;
      }
    }
  }
  if (bestComp < 0)
    throw std::runtime_error("face landmarks: cannot find the left orbit (no bone-free region around the eye level)");
  int rMin = rows, rMax = -1;
  for (int q : comps[bestComp])
  {
    rMin = std::min(rMin, q / cols);
    rMax = std::max(rMax, q / cols);
  }
  const int rMid = (rMin + rMax) / 2;
  int cMin = cols, cMax = -1;
  for (int q : comps[bestComp])
    if (q / cols == rMid)
    {
      cMin = std::min(cMin, q % cols);
      cMax = std::max(cMax, q % cols);
    }
  lm.orbitMedialTheta = theta0 + cMin * da;
  lm.orbitLateralTheta = theta0 + cMax * da;
  lm.orbitBottomPhi = phi0 + rMin * da;
  lm.orbitTopPhi = phi0 + rMax * da;
  const FacePoint& mid = hits[rMid * cols + (cMin + cMax) / 2];
  lm.orbitCentre = mid;
  const double rho = std::hypot(mid.local.x(), mid.local.y() - centre.y()); // distance to the vertical axis
  const double phiMid = phi0 + rMid * da;
  lm.eyeInner = SkinHit(skin, centre, lm.orbitMedialTheta + 3.0 / rho, phiMid);
  lm.eyeOuter = SkinHit(skin, centre, lm.orbitLateralTheta - 6.0 / rho, phiMid + 1.0 / eyeRadius);
}

// Left mouth corner: follow the lip line laterally until the lips no longer bulge.
void DetectMouthCorner(const SurfaceRays& skin, const Eigen::Vector3d& centre, FaceLandmarkSet& lm)
{
  const double mouthRadius = (lm.stomion.local - centre).norm();
  const double dPhi = 0.5 * kDeg, dTheta = 0.5 * kDeg;
  const int halfRows = static_cast<int>(std::ceil(8.0 / mouthRadius / dPhi)); // +-8 mm around the line
  const int bulgeRows = static_cast<int>(std::ceil(6.0 / mouthRadius / dPhi));
  double linePhi = lm.stomion.phi;
  double cornerTheta = -1;
  std::ostringstream relief;
  relief.precision(3);
  for (int c = 0; c * dTheta <= 50 * kDeg; ++c)
  {
    const double theta = c * dTheta;
    std::vector<double> r;
    for (int k = -halfRows; k <= halfRows; ++k)
      r.push_back((SkinHit(skin, centre, theta, linePhi + k * dPhi).local - centre).norm());
    // The line moves at most 1 row per column, to the local radial minimum.
    int line = halfRows;
    for (int k = halfRows - 1; k <= halfRows + 1; ++k)
      if (r[k] < r[line])
        line = k;
    double above = -1e300, below = -1e300;
    for (int k = 1; k <= bulgeRows; ++k)
    {
      above = std::max(above, r[line + k]);
      below = std::max(below, r[line - k]);
    }
    const double bulge = std::min(above, below) - r[line];
    const double lateral = SkinHit(skin, centre, theta, linePhi).local.x();
    if (c % 4 == 0)
      relief << " " << lateral << ":" << bulge;
    linePhi += (line - halfRows) * dPhi;
    if (lateral >= 15.0 && bulge < 0.3)
    {
      cornerTheta = theta;
      break;
    }
    if (lateral > 35.0)
      break;
  }
  lm.log.push_back("lip-line relief (lateral mm: groove depth mm):" + relief.str());
  if (cornerTheta < 0)
    throw std::runtime_error(
      "face landmarks: cannot find the left mouth corner (the lip line does not end within 35 mm)");
  lm.lipCorner = SkinHit(skin, centre, cornerTheta, linePhi);
}

} // namespace

int NextExtremum(const std::vector<double>& v, int start, int step, bool wantMin, double delta)
{
  int best = start;
  for (int i = start; i >= 0 && i < static_cast<int>(v.size()); i += step)
  {
    if (wantMin ? v[i] < v[best] : v[i] > v[best])
      best = i;
    if (wantMin ? v[i] > v[best] + delta : v[i] < v[best] - delta)
      return best;
  }
  return -1;
}

FacePoint SkinHit(const SurfaceRays& skin, const Eigen::Vector3d& centre, double theta, double phi)
{
  const auto hit = skin.Last(centre, centre + kFar * RayDirection(theta, phi));
  if (!hit)
    throw std::runtime_error("face atlas: a ray from the face centre misses the skin (theta " +
                             std::to_string(theta / kDeg) + " deg, phi " + std::to_string(phi / kDeg) +
                             " deg); the centre is not inside the head");
  FacePoint p;
  p.theta = theta;
  p.phi = phi;
  p.local = *hit;
  if (theta == 0)
    p.local.x() = 0; // on the plane exactly
  return p;
}

void DetectOrbitAndMouthCorner(const SurfaceRays& skin, const SurfaceRays& bone, const Eigen::Vector3d& centre,
                               FaceLandmarkSet& lm)
{
  DetectOrbit(skin, bone, centre, lm);
  DetectMouthCorner(skin, centre, lm);
}

FaceLandmarkSet DetectFaceLandmarks(const SurfaceRays& skin, const SurfaceRays& bone, const Eigen::Vector3d& centre)
{
  FaceLandmarkSet lm;
  // --- Mid-sagittal profile.
  std::vector<FacePoint> profile;
  std::vector<double> v;
  for (double a = -75.0; a <= 65.0 + 1e-9; a += 0.25)
  {
    profile.push_back(SkinHit(skin, centre, 0, a * kDeg));
    v.push_back(profile.back().local.y());
  }
  // Nose tip: most anterior profile point within +-35 deg of the centre's level.
  int prn = -1;
  for (int i = 0; i < static_cast<int>(v.size()); ++i)
    if (std::abs(profile[i].phi) <= 35 * kDeg && (prn < 0 || v[i] > v[prn]))
      prn = i;
  const double delta = 0.5;
  auto need = [&](int i, const char* what) {
    if (i < 0)
      throw std::runtime_error(std::string("face atlas: cannot find the ") + what +
                               " on the mid-sagittal skin profile");
    return i;
  };
  // Lips and chin: extrema of the anterior coordinate walking down (smoothed over 1.25 deg).
  std::vector<double> vs(v.size());
  for (int i = 0; i < static_cast<int>(v.size()); ++i)
  {
    double sum = 0;
    int n = 0;
    for (int k = std::max(0, i - 2); k <= std::min(static_cast<int>(v.size()) - 1, i + 2); ++k, ++n)
      sum += v[k];
    vs[i] = sum / n;
  }
  const int sn = need(NextExtremum(vs, prn, -1, true, delta), "subnasale");
  const int ls = need(NextExtremum(vs, sn, -1, false, delta), "upper lip");
  const int st = need(NextExtremum(vs, ls, -1, true, delta), "stomion");
  const int li = need(NextExtremum(vs, st, -1, false, delta), "lower lip");
  // Concavities and convexities that depend on the head's pitch are measured from chords:
  // pogonion = farthest point in front of the chord from the labiomental fold to the profile
  // point 25 mm lower; nasion = farthest point behind the chord from the nose tip to the
  // profile point 50 mm higher.
  auto chordExtremum = [&](int from, int to, double sign) {
    const Eigen::Vector2d a(profile[from].local.y(), profile[from].local.z());
    const Eigen::Vector2d b(profile[to].local.y(), profile[to].local.z());
    const Eigen::Vector2d t = (b - a).normalized();
    int best = -1;
    double bestD = -1e300;
    for (int i = std::min(from, to) + 1; i < std::max(from, to); ++i)
    {
      const Eigen::Vector2d p(profile[i].local.y(), profile[i].local.z());
      const Eigen::Vector2d d = p - a - (p - a).dot(t) * t;
      const double side = sign * (d.x() >= 0 ? d.norm() : -d.norm()); // + in front (anterior)
      if (side > bestD)
      {
        bestD = side;
        best = i;
      }
    }
    return best;
  };
  auto firstBeyond = [&](int from, int step, double dz) {
    for (int i = from; i >= 0 && i < static_cast<int>(profile.size()); i += step)
      if (std::abs(profile[i].local.z() - profile[from].local.z()) >= dz)
        return i;
    return -1;
  };
  const int lmEnd = need(firstBeyond(li, -1, 30.0), "chin");
  const int lm_ = need(chordExtremum(li, lmEnd, -1.0), "labiomental fold");
  const int chinEnd = need(firstBeyond(lm_, -1, 25.0), "chin");
  const int pg = need(chordExtremum(lm_, chinEnd, +1.0), "pogonion");
  const int browEnd = need(firstBeyond(prn, +1, 50.0), "forehead");
  const int na = need(chordExtremum(prn, browEnd, -1.0), "nasion");
  lm.pronasale = profile[prn];
  lm.subnasale = profile[sn];
  lm.upperLip = profile[ls];
  lm.stomion = profile[st];
  lm.lowerLip = profile[li];
  lm.labiomental = profile[lm_];
  lm.pogonion = profile[pg];
  lm.nasion = profile[na];

  DetectOrbitAndMouthCorner(skin, bone, centre, lm);

  for (const auto& [name, p] : std::vector<std::pair<std::string, FacePoint>>{{"pronasale", lm.pronasale},
                                                                              {"subnasale", lm.subnasale},
                                                                              {"upper lip", lm.upperLip},
                                                                              {"stomion", lm.stomion},
                                                                              {"lower lip", lm.lowerLip},
                                                                              {"labiomental fold", lm.labiomental},
                                                                              {"pogonion", lm.pogonion},
                                                                              {"nasion", lm.nasion},
                                                                              {"eye inner corner", lm.eyeInner},
                                                                              {"eye outer corner", lm.eyeOuter},
                                                                              {"lip corner", lm.lipCorner}})
    lm.log.push_back(Describe(name, p));
  return lm;
}

} // namespace mmrep
