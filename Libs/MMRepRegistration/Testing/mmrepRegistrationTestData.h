// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Test surfaces for the registration tests: bundled CT skins through the image stage (computed
// once per test binary) and an analytic head-like shape with an exact mirror symmetry.
#pragma once

#include "mmrepCTThresholds.h"
#include "mmrepHeadSegmentation.h"
#include "mmrepImageIO.h"
#include "mmrepSurfaceExtraction.h"

#include <Eigen/Core>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace mmrep::testing
{

struct SampleSkin
{
  CTImage::Pointer ct;
  CTThresholds thresholds;
  vtkSmartPointer<vtkPolyData> skin;
};

inline vtkSmartPointer<vtkPolyData> SkinOf(const CTImage* ct, const CTThresholds& t, std::size_t vertices)
{
  HeadSegmentationOptions seg;
  seg.skinThreshold = t.skin;
  seg.boneThreshold = t.bone;
  const auto head = SegmentHead(ct, seg);
  SurfaceExtractionOptions surf;
  surf.targetVertexCount = vertices;
  return ExtractSurface(MaskedIntensities(ct, head.skin, t.skin), t.skin, surf);
}

// Skin of a bundled CT (cthead.nrrd, headsq.nrrd), decimated to about 30k vertices; cached.
inline const SampleSkin& BundledSkin(const std::string& name)
{
  static std::map<std::string, SampleSkin> cache;
  auto it = cache.find(name);
  if (it == cache.end())
  {
    SampleSkin s;
    s.ct = ReadCTImage(std::string(MMREP_SAMPLE_DATA) + "/" + name);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.thresholds = ChooseThresholds(s.ct, ThresholdMode::Automatic, nan, nan);
    s.skin = SkinOf(s.ct, s.thresholds, 30000);
    it = cache.emplace(name, s).first;
  }
  return it->second;
}

// Head-like closed surface, exactly mirror-symmetric about x = 0 (tessellation included: the
// sphere's even theta resolution maps x -> -x onto itself): an ellipsoid (LR 75, AP 95, SI 110 mm)
// with a nose (anterior = -y), two ears and a chin, all symmetric in x; then moved by `rotation`
// and `translation`, so its true plane has normal rotation·x and passes through `translation`.
inline vtkSmartPointer<vtkPolyData> SymmetricHead(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(160);
  sphere->SetPhiResolution(120);
  sphere->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(sphere->GetOutput());
  auto bump = [](const Eigen::Vector3d& d, const Eigen::Vector3d& at, double width) {
    return std::exp(-(d - at).squaredNorm() / (2 * width * width));
  };
  vtkPoints* pts = out->GetPoints();
  for (vtkIdType i = 0; i < pts->GetNumberOfPoints(); ++i)
  {
    double q[3];
    pts->GetPoint(i, q);
    const Eigen::Vector3d d = Eigen::Vector3d(q[0], q[1], q[2]).normalized();
    const Eigen::Vector3d flipped(-d.x(), d.y(), d.z());
    double r = 1.0 + 0.25 * bump(d, {0, -0.95, 0.1}, 0.12)                                         // nose
               + 0.12 * (bump(d, {0.98, 0.05, 0.0}, 0.1) + bump(flipped, {0.98, 0.05, 0.0}, 0.1))  // ears
               + 0.10 * bump(d, {0, -0.6, -0.75}, 0.2)                                             // chin
               + 0.05 * (bump(d, {0.5, -0.7, 0.4}, 0.15) + bump(flipped, {0.5, -0.7, 0.4}, 0.15)); // brows
    const Eigen::Vector3d p(75 * r * d.x(), 95 * r * d.y(), 110 * r * d.z());
    const Eigen::Vector3d moved = rotation * p + translation;
    pts->SetPoint(i, moved.data());
  }
  return out;
}

} // namespace mmrep::testing
