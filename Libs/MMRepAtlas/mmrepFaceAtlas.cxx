// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The atlas builder: the phases of mmrepFaceAtlas.h in order (each in its own file, see
// mmrepFaceAtlasStages.h), with the construction log and the progress.
#include "mmrepFaceAtlas.h"

#include "mmrepFaceAtlasStages.h"
#include "mmrepFaceControlPoints.h"
#include "mmrepFaceMouth.h"
#include "mmrepFaceMuscles.h"
#include "mmrepMeshQuality.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>

namespace mmrep
{
namespace
{
void CheckInputs(vtkPolyData* skinWorld, vtkPolyData* skullWorld, const FaceAtlasOptions& options)
{
  if (!skinWorld || skinWorld->GetNumberOfPolys() == 0)
    throw std::runtime_error("face atlas: the skin surface has no triangles");
  if (!skullWorld || skullWorld->GetNumberOfPolys() == 0)
    throw std::runtime_error("face atlas: the skull surface has no triangles");
  const auto& r = options.layerRatios;
  if (r[0] <= 0 || r[1] <= 0 || r[2] <= 0)
    throw std::invalid_argument("face atlas: layer ratios must be positive");
  if (options.meshSize <= 0 || options.lipsMeshSize <= 0 || options.lipsMeshSize > options.meshSize)
    throw std::invalid_argument("face atlas: mesh sizes must be positive and the lips size at most the mesh size");
}
} // namespace

std::string FaceAtlasLogLine(const char* format, double a, double b, double c)
{
  char buf[256];
  std::snprintf(buf, sizeof(buf), format, a, b, c);
  return buf;
}

const std::vector<std::string>& FaceAtlasLandmarkNames()
{
  static const std::vector<std::string> names{"LeftEyeInnerCorner", "LeftEyeOuterCorner", "LeftLipCorner",
                                              "UpperLipCenter", "LowerLipCenter"};
  return names;
}

std::vector<Landmark> FaceAtlasLandmarks(const FaceLandmarkSet& lm, const FaceFrame& frame)
{
  const FacePoint* points[] = {&lm.eyeInner, &lm.eyeOuter, &lm.lipCorner, &lm.upperLip, &lm.lowerLip};
  std::vector<Landmark> landmarks;
  for (std::size_t n = 0; n < 5; ++n)
    landmarks.push_back({FaceAtlasLandmarkNames()[n], frame.ToWorld(points[n]->local)});
  return landmarks;
}

FaceAtlas BuildFaceAtlas(vtkPolyData* skinWorld, vtkPolyData* skullWorld, const Plane& plane,
                         const FaceAtlasOptions& options, const std::function<void(double)>& progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::string> timings;
  auto report = [&](double f) {
    if (progress)
      progress(f);
    timings.push_back(
      FaceAtlasLogLine("%.2f s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()));
  };
  CheckInputs(skinWorld, skullWorld, options);

  // 1. Face frame, face centre, landmarks.
  FaceAtlas atlas;
  atlas.plane = plane;
  double b[6];
  skinWorld->GetBounds(b);
  atlas.frame =
    FaceFrame::FromPlane(plane, Eigen::Vector3d(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])));
  const FaceFrame& frame = atlas.frame;
  double toLocal[16];
  frame.WorldToLocalMatrix(toLocal);
  auto skinLocal = TransformSurface(skinWorld, toLocal);
  auto skullLocal = TransformSurface(skullWorld, toLocal);
  SurfaceRays skin(skinLocal), bone(skullLocal);
  report(0.1);
  double headDepth = 0;
  atlas.centre = FaceCentreOfLocalSkin(skinLocal, &headDepth);
  const Eigen::Vector3d& c = atlas.centre;
  atlas.log.push_back(FaceAtlasLogLine(
    "face centre (local): anterior %.2f, superior %.2f mm; head depth at the nose %.1f mm", c.y(), c.z(), headDepth));
  atlas.landmarks = DetectFaceLandmarks(skin, bone, c);
  const FaceLandmarkSet& lm = atlas.landmarks;
  for (const auto& l : lm.log)
    atlas.log.push_back(l);
  report(0.3);

  // 2-4. Grid of rays, skin nodes, through-thickness columns.
  FaceGrid& grid = atlas.grid;
  const FaceMouthRegion mouth = LayOutFaceGrid(skin, c, lm, options, grid);
  atlas.log.push_back(
    FaceAtlasLogLine("grid: %.0f rows (phi) x %.0f columns (theta), left half", grid.Rows(), grid.Cols()));
  auto outer = FaceSkinNodes(skin, c, grid);
  report(0.4);
  FaceColumns columns = FaceThroughThickness(std::move(outer), bone, grid, mouth, options, atlas.log);
  report(0.5);

  // 5-6. Left-half nodes, the mirrored mesh.
  PlaceLeftHalfNodes(columns, grid);
  FEMesh& mesh = atlas.mesh;
  mesh = MirroredFaceMesh(grid, frame);
  {
    quality::QualityOptions qo;
    qo.threads = 1;
    const auto s = quality::SummarizeScaledJacobian(mesh, options.qualityThreshold, qo);
    atlas.log.push_back(
      FaceAtlasLogLine("before repair: scaled Jacobian min %.3f, mean %.3f; %.0f elements below the threshold", s.min,
                       s.mean, s.belowThreshold));
  }
  report(0.7);
  AddFaceNodeSets(grid, columns, mouth, lm, mesh);

  // 7. Reference surfaces, repair, surface nodes back onto their surfaces.
  atlas.skinSurface = SymmetrisedSurface(skinLocal, frame, grid);
  atlas.skullSurface = SymmetrisedSurface(skullLocal, frame, grid);
  RepairFaceAtlas(options, atlas);
  ProjectFaceSurfaceNodes(options, columns.onBone, atlas);

  // Mouth slit and jaw (mmrepFaceMouth.h).
  const MouthSlitCells slit = MouthSlitCellsOf(grid, lm);
  const std::size_t twins = CutMouthSlit(mesh, grid, slit);
  atlas.log.push_back(FaceAtlasLogLine("mouth slit: row %.0f, corner column %.0f, %.0f nodes doubled", slit.slitRow,
                                       slit.cornerColumn, static_cast<double>(twins)));
  atlas.log.push_back(AddJaw(mesh, skullLocal, frame, lm));

  // 8. Landmarks (world), muscles.
  mesh.landmarks = FaceAtlasLandmarks(lm, frame);
  AddFaceMuscles(mesh, grid, frame, FaceMuscleRules(lm, c), options.muscleSpacing);
  auto& midSet = mesh.nodeSets["midsagittal"];
  std::sort(midSet.begin(), midSet.end());
  mesh.UpdateLayerSets();
  mesh.Validate();
  report(0.9);

  report(1.0);
  std::string t = "timings at 0.1 0.3 0.4 0.5 0.7 0.9 1.0:";
  for (const auto& x : timings)
    t += " " + x;
  atlas.log.push_back(t);
  return atlas;
}

} // namespace mmrep
