// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Synthetic atlas and subject with a known truth for the elastic registration tests.
//
// Atlas: a face-like patch of an ellipsoid head (front, θ ∈ [−60°, 60°], φ ∈ [−40°, 40°]), one
// layer of hexahedra between the skin (outer ellipsoid) and the skull (inner ellipsoid), exactly
// symmetric about x = 0 (the right half is the negated left half), node sets skin, skull, lips,
// midsagittal, and the five control points of the face atlas.
// Subject: the ellipsoids mapped by T = s Rot W + t, W a symmetric sum of Gaussian bumps, Rot a
// ~10° rotation, as triangle surfaces; control points T(ā_i); plane = T(x = 0 plane).
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepSymmetryPlane.h"

#include <Eigen/Geometry>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <string>
#include <vector>

namespace mmrep::elastictest
{

constexpr double kPi = 3.14159265358979323846;
inline double Rad(double d)
{
  return d * kPi / 180.0;
}

inline Eigen::Vector3d EllipsoidPoint(double thetaDeg, double phiDeg, const Eigen::Vector3d& radii)
{
  const double t = Rad(thetaDeg), p = Rad(phiDeg);
  const Eigen::Vector3d d(std::sin(t) * std::cos(p), -std::cos(t) * std::cos(p), std::sin(p)); // anterior = −y
  return d /
         std::sqrt(std::pow(d.x() / radii.x(), 2) + std::pow(d.y() / radii.y(), 2) + std::pow(d.z() / radii.z(), 2));
}

inline const Eigen::Vector3d& SkinRadii()
{
  static const Eigen::Vector3d r(70, 90, 100);
  return r;
}
inline const Eigen::Vector3d& SkullRadii()
{
  static const Eigen::Vector3d r(58, 78, 88);
  return r;
}

struct SyntheticAtlas
{
  FEMesh mesh;
  Plane plane;                                  // x = 0
  std::vector<std::pair<int, int>> mirrorPairs; // (node, mirror node), i > 0 columns
};

inline SyntheticAtlas MakeAtlas(int halfColumns = 20, int rows = 31)
{
  SyntheticAtlas a;
  const int cols = 2 * halfColumns + 1;
  auto id = [&](int layer, int i, int j) { return (layer * rows + j) * cols + (i + halfColumns); };
  a.mesh.nodes.resize(static_cast<std::size_t>(2 * rows * cols));
  std::vector<std::int32_t> skin, skull, lips, mid;
  for (int layer = 0; layer < 2; ++layer)
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i <= halfColumns; ++i)
      {
        const double theta = 60.0 * i / halfColumns, phi = -40.0 + 80.0 * j / (rows - 1);
        Eigen::Vector3d p = EllipsoidPoint(theta, phi, layer == 0 ? SkinRadii() : SkullRadii());
        if (i == 0)
          p.x() = 0.0;
        a.mesh.nodes[static_cast<std::size_t>(id(layer, i, j))] = p;
        a.mesh.nodes[static_cast<std::size_t>(id(layer, -i, j))] = Eigen::Vector3d(-p.x(), p.y(), p.z());
        if (i > 0)
          a.mirrorPairs.emplace_back(id(layer, i, j), id(layer, -i, j));
      }
  for (int layer = 0; layer < 2; ++layer)
    for (int j = 0; j < rows; ++j)
      for (int i = -halfColumns; i <= halfColumns; ++i)
      {
        const int n = id(layer, i, j);
        (layer == 0 ? skin : skull).push_back(n);
        const double theta = 60.0 * i / halfColumns, phi = -40.0 + 80.0 * j / (rows - 1);
        if (layer == 0 && std::abs(theta) <= 25.0 && phi >= -33.0 && phi <= -15.0)
          lips.push_back(n);
        if (i == 0)
          mid.push_back(n);
      }
  for (int j = 0; j + 1 < rows; ++j)
    for (int i = -halfColumns; i < halfColumns; ++i)
    {
      Element e;
      e.type = ElementType::Hexahedron;
      e.layer = TissueLayer::Dermis;
      e.nodes = {id(1, i, j), id(1, i + 1, j), id(1, i + 1, j + 1), id(1, i, j + 1),
                 id(0, i, j), id(0, i + 1, j), id(0, i + 1, j + 1), id(0, i, j + 1)};
      a.mesh.elements.push_back(e);
    }
  a.mesh.nodeSets["skin"] = skin;
  a.mesh.nodeSets["skull"] = skull;
  a.mesh.nodeSets["lips"] = lips;
  a.mesh.nodeSets["midsagittal"] = mid;
  const std::vector<std::pair<std::string, Eigen::Vector2d>> cps = {{"LeftEyeInnerCorner", {10, 20}},
                                                                    {"LeftEyeOuterCorner", {30, 18}},
                                                                    {"LeftLipCorner", {20, -24}},
                                                                    {"UpperLipCenter", {0, -20}},
                                                                    {"LowerLipCenter", {0, -29}}};
  for (const auto& [name, tp] : cps)
  {
    Eigen::Vector3d p = EllipsoidPoint(tp.x(), tp.y(), SkinRadii());
    if (tp.x() == 0)
      p.x() = 0;
    a.mesh.landmarks.push_back({name, p});
  }
  a.mesh.UpdateLayerSets();
  a.plane.point = Eigen::Vector3d::Zero();
  a.plane.normal = Eigen::Vector3d::UnitX();
  return a;
}

// The known truth T = s Rot W + t.
struct Truth
{
  double scale = 1.04;
  Eigen::Matrix3d rotation =
    (Eigen::AngleAxisd(Rad(8), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(Rad(6), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
  Eigen::Vector3d translation{5, -3, 8};
  double sigma = 35;
  // Bumps (centre, vector): a mirrored pair and one on the plane, so that W(Mx) = M W(x).
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> bumps = {
    {{30, -70, 20}, {3, -4, 2}}, {{-30, -70, 20}, {-3, -4, 2}}, {{0, -85, -25}, {0, -5, -3}}};

  Eigen::Vector3d Warp(const Eigen::Vector3d& x) const
  {
    Eigen::Vector3d u = Eigen::Vector3d::Zero();
    for (const auto& [c, a] : bumps)
      u += a * std::exp(-(x - c).squaredNorm() / (2 * sigma * sigma));
    return x + u;
  }
  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const { return scale * (rotation * Warp(x)) + translation; }
  Plane SubjectPlane() const
  {
    Plane p;
    p.point = (*this)(Eigen::Vector3d::Zero());
    p.normal = rotation * Eigen::Vector3d::UnitX();
    return p;
  }
};

// Triangulated patch of the ellipsoid (θ ∈ ±100°, φ ∈ ±65°, 1° steps) mapped by `truth`.
inline vtkSmartPointer<vtkPolyData> MakeSurface(const Eigen::Vector3d& radii, const Truth& truth, double stepDeg = 1.0)
{
  const int nt = static_cast<int>(std::lround(200 / stepDeg)) + 1,
            np = static_cast<int>(std::lround(130 / stepDeg)) + 1;
  vtkNew<vtkPoints> pts;
  for (int j = 0; j < np; ++j)
    for (int i = 0; i < nt; ++i)
    {
      const Eigen::Vector3d p = truth(EllipsoidPoint(-100 + i * stepDeg, -65 + j * stepDeg, radii));
      pts->InsertNextPoint(p.x(), p.y(), p.z());
    }
  vtkNew<vtkCellArray> tris;
  for (int j = 0; j + 1 < np; ++j)
    for (int i = 0; i + 1 < nt; ++i)
    {
      const vtkIdType a = j * nt + i, b = a + 1, c = a + nt + 1, d = a + nt;
      const vtkIdType t1[3] = {a, b, c}, t2[3] = {a, c, d};
      tris->InsertNextCell(3, t1);
      tris->InsertNextCell(3, t2);
    }
  auto s = vtkSmartPointer<vtkPolyData>::New();
  s->SetPoints(pts);
  s->SetPolys(tris);
  return s;
}

inline std::vector<Landmark> SubjectControlPoints(const FEMesh& atlas, const Truth& truth)
{
  std::vector<Landmark> out;
  for (const auto& l : atlas.landmarks)
    out.push_back({l.name, truth(l.position)});
  return out;
}

} // namespace mmrep::elastictest
