// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFaceControlPoints.h"

#include "mmrepFaceAtlas.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mmrep
{
namespace
{
vtkSmartPointer<vtkPolyData> ToLocal(vtkPolyData* world, const FaceFrame& frame)
{
  double m[16];
  frame.WorldToLocalMatrix(m);
  return TransformSurface(world, m);
}

constexpr double kDeg = M_PI / 180.0;

// The atlas's landmark rules (mmrepFaceLandmarks.cxx) with the two changes that a flat, flexed
// face in a volume cut below the chin needs (headsq):
//  * nose tip = the profile point (within +-35 deg) farthest in front of the chord joining the
//    profile points 20 mm above and 20 mm below it, instead of the most anterior point (which is
//    the brow when the forehead is as far forward as the nose);
//  * no chin landmarks (labiomental fold, pogonion need 55 mm of profile below the lower lip);
//    the nasion chord reaches 50 mm above the nose tip, or the highest profile point when the
//    volume stops earlier (at least 25 mm).
// Orbits, eye corners and the mouth corner follow the atlas rules unchanged.
FaceLandmarkSet DetectWithoutChin(const SurfaceRays& skin, const SurfaceRays& bone, const Eigen::Vector3d& centre)
{
  FaceLandmarkSet lm;
  std::vector<FacePoint> profile;
  std::vector<double> v;
  for (double a = -75.0; a <= 65.0 + 1e-9; a += 0.25)
  {
    profile.push_back(SkinHit(skin, centre, 0, a * kDeg));
    v.push_back(profile.back().local.y());
  }
  const int n = static_cast<int>(v.size());
  auto need = [&](int i, const char* what) {
    if (i < 0)
      throw std::runtime_error(std::string("face control points: cannot find the ") + what +
                               " on the mid-sagittal skin profile");
    return i;
  };
  auto firstBeyond = [&](int from, int step, double dz) {
    for (int i = from; i >= 0 && i < n; i += step)
      if (std::abs(profile[i].local.z() - profile[from].local.z()) >= dz)
        return i;
    return -1;
  };
  // Signed distance of profile point i in front of the chord a-b (in the (v, w) plane).
  auto inFront = [&](int i, int a, int b) {
    const Eigen::Vector2d pa(profile[a].local.y(), profile[a].local.z()),
      pb(profile[b].local.y(), profile[b].local.z());
    const Eigen::Vector2d t = (pb - pa).normalized(), p(profile[i].local.y(), profile[i].local.z());
    const Eigen::Vector2d d = p - pa - (p - pa).dot(t) * t;
    return d.x() >= 0 ? d.norm() : -d.norm();
  };
  int prn = -1;
  double best = -1e300;
  for (int i = 0; i < n; ++i)
  {
    if (std::abs(profile[i].phi) > 35 * kDeg)
      continue;
    const int up = firstBeyond(i, +1, 20.0), down = firstBeyond(i, -1, 20.0);
    if (up < 0 || down < 0)
      continue;
    const double p = inFront(i, up, down);
    if (p > best)
    {
      best = p;
      prn = i;
    }
  }
  need(prn, "nose tip");
  std::vector<double> vs(v.size());
  for (int i = 0; i < n; ++i)
  {
    double sum = 0;
    int k0 = std::max(0, i - 2), k1 = std::min(n - 1, i + 2);
    for (int k = k0; k <= k1; ++k)
      sum += v[k];
    vs[i] = sum / (k1 - k0 + 1);
  }
  const double delta = 0.5;
  const int sn = need(NextExtremum(vs, prn, -1, true, delta), "subnasale");
  const int ls = need(NextExtremum(vs, sn, -1, false, delta), "upper lip");
  const int st = need(NextExtremum(vs, ls, -1, true, delta), "stomion");
  const int li = need(NextExtremum(vs, st, -1, false, delta), "lower lip");
  int browEnd = firstBeyond(prn, +1, 50.0);
  if (browEnd < 0)
  {
    browEnd = prn;
    for (int i = prn; i < n; ++i)
      if (profile[i].local.z() > profile[browEnd].local.z())
        browEnd = i;
    if (profile[browEnd].local.z() - profile[prn].local.z() < 25.0)
      throw std::runtime_error("face control points: the skin profile ends less than 25 mm above the nose tip");
  }
  int na = -1;
  best = -1e300;
  for (int i = prn + 1; i < browEnd; ++i)
    if (-inFront(i, prn, browEnd) > best)
    {
      best = -inFront(i, prn, browEnd);
      na = i;
    }
  need(na, "nasion");
  lm.pronasale = profile[prn];
  lm.subnasale = profile[sn];
  lm.upperLip = profile[ls];
  lm.stomion = profile[st];
  lm.lowerLip = profile[li];
  lm.nasion = profile[na];
  DetectOrbitAndMouthCorner(skin, bone, centre, lm);
  return lm;
}
} // namespace

Eigen::Vector3d FaceCentreOfLocalSkin(vtkPolyData* skinLocal, double* headDepth)
{
  if (!skinLocal || skinLocal->GetNumberOfPoints() == 0)
    throw std::runtime_error("face centre: the skin surface has no points");
  Eigen::Vector3d tip(0, -1e300, 0);
  for (vtkIdType p = 0; p < skinLocal->GetNumberOfPoints(); ++p)
  {
    double q[3];
    skinLocal->GetPoint(p, q);
    if (std::abs(q[0]) < 10 && q[1] > tip.y())
      tip = Eigen::Vector3d(q[0], q[1], q[2]);
  }
  if (tip.y() == -1e300)
    throw std::runtime_error("face centre: no skin within 10 mm of the symmetry plane");
  double back = tip.y();
  for (vtkIdType p = 0; p < skinLocal->GetNumberOfPoints(); ++p)
  {
    double q[3];
    skinLocal->GetPoint(p, q);
    if (std::abs(q[0]) < 10 && std::abs(q[2] - tip.z()) < 10)
      back = std::min(back, q[1]);
  }
  if (headDepth != nullptr)
    *headDepth = tip.y() - back;
  return {0, 0.5 * (tip.y() + back), tip.z() - 10};
}

FaceControlPoints DetectFaceControlPoints(vtkPolyData* skin, vtkPolyData* skull, const Plane& plane)
{
  if (!skin || skin->GetNumberOfPolys() == 0)
    throw std::runtime_error("face control points: the skin surface has no triangles");
  if (!skull || skull->GetNumberOfPolys() == 0)
    throw std::runtime_error("face control points: the skull surface has no triangles");
  FaceControlPoints out;
  // Same frame origin as the atlas builder (the skin's bounding-box centre, projected on the plane).
  double b[6];
  skin->GetBounds(b);
  out.frame =
    FaceFrame::FromPlane(plane, Eigen::Vector3d(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])));
  auto skinLocal = ToLocal(skin, out.frame);
  auto skullLocal = ToLocal(skull, out.frame);
  out.centre = FaceCentreOfLocalSkin(skinLocal);
  SurfaceRays skinRays(skinLocal), boneRays(skullLocal);
  try
  {
    out.landmarks = DetectFaceLandmarks(skinRays, boneRays, out.centre);
    out.log.push_back("atlas landmark rules");
  }
  catch (const std::runtime_error& e)
  {
    out.log.push_back(std::string("atlas landmark rules failed (") + e.what() +
                      "); nose tip by protrusion, no chin landmarks");
    out.landmarks = DetectWithoutChin(skinRays, boneRays, out.centre);
    out.usedFallback = true;
  }
  for (const auto& l : out.landmarks.log)
    out.log.push_back(l);
  const FaceLandmarkSet& all = out.landmarks;
  for (const auto& [name, p] : std::vector<std::pair<std::string, FacePoint>>{{"pronasale", all.pronasale},
                                                                              {"subnasale", all.subnasale},
                                                                              {"upper lip", all.upperLip},
                                                                              {"stomion", all.stomion},
                                                                              {"lower lip", all.lowerLip},
                                                                              {"nasion", all.nasion}})
  {
    std::ostringstream line;
    line.precision(4);
    line << name << ": theta " << p.theta / kDeg << " deg, phi " << p.phi / kDeg << " deg, local (" << p.local.x()
         << ", " << p.local.y() << ", " << p.local.z() << ")";
    out.log.push_back(line.str());
  }
  out.points = FaceAtlasLandmarks(out.landmarks, out.frame);
  return out;
}

} // namespace mmrep
