// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Step 7 of the atlas: the reference surfaces the atlas keeps its nodes on, the repair of its
// elements with exact re-symmetrisation, and the surface nodes projected back onto the surfaces.
#include "mmrepFaceAtlasStages.h"

#include "mmrepCertifiedJacobian.h"
#include "mmrepMeshQuality.h"
#include "mmrepMeshRepair.h"

#include <vtkAppendPolyData.h>
#include <vtkBox.h>
#include <vtkCellData.h>
#include <vtkClipPolyData.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkReverseSense.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <cmath>

namespace mmrep
{
namespace
{
// The reference surfaces reach this far (mm) beyond the atlas's nodes, so that every node's
// closest surface point is on them.
constexpr double kSurfaceMargin = 15.0;
// Repair rounds: the exact re-symmetrisation can push an element slightly back under the threshold.
constexpr int kRepairRounds = 3;
// The repair aims this far above the threshold, as a margin for the re-symmetrisation.
constexpr double kRepairThresholdMargin = 0.05;
// A mid-sagittal inner node farther than this (mm) from the bone is not on the skull.
constexpr double kOnBoneTolerance = 0.1;

quality::QualitySummary Quality(const FEMesh& mesh, const FaceAtlasOptions& options)
{
  quality::QualityOptions qo;
  qo.threads = 1;
  return quality::SummarizeScaledJacobian(mesh, options.qualityThreshold, qo);
}

// grid.local from the mesh's left half (column 0 back onto the plane exactly).
void ReadLeftHalf(const FEMesh& mesh, const FaceFrame& frame, FaceGrid& grid)
{
  for (int i = 0; i < grid.Rows(); ++i)
    for (int j = 0; j < grid.Cols(); ++j)
      for (int k = 0; k < 4; ++k)
      {
        Eigen::Vector3d p = frame.ToLocal(mesh.nodes[grid.LeftNode(i, j, k)]);
        if (j == 0)
          p.x() = 0;
        grid.local[grid.LeftNode(i, j, k)] = p;
      }
}

vtkSmartPointer<vtkStaticCellLocator> Locator(vtkPolyData* surface)
{
  auto locator = vtkSmartPointer<vtkStaticCellLocator>::New();
  locator->SetDataSet(surface);
  locator->BuildLocator();
  return locator;
}

// Closest point of the locator's surface to a mesh node, and its distance.
Eigen::Vector3d Closest(vtkStaticCellLocator* locator, const Point3& node, double& distance)
{
  double x[3] = {node.x(), node.y(), node.z()}, closest[3], d2;
  vtkIdType cell;
  int sub;
  locator->FindClosestPoint(x, closest, cell, sub, d2);
  distance = std::sqrt(d2);
  return Eigen::Vector3d(closest[0], closest[1], closest[2]);
}
} // namespace

vtkSmartPointer<vtkPolyData> SymmetrisedSurface(vtkPolyData* local, const FaceFrame& frame, const FaceGrid& grid)
{
  double box[6] = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  for (const auto& p : grid.local)
    for (int a = 0; a < 3; ++a)
    {
      box[2 * a] = std::min(box[2 * a], p(a) - kSurfaceMargin);
      box[2 * a + 1] = std::max(box[2 * a + 1], p(a) + kSurfaceMargin);
    }
  box[0] = -box[1];
  auto boxFn = vtkSmartPointer<vtkBox>::New();
  boxFn->SetBounds(box);
  // Clipping keeps exact sub-triangles of the original ones (distances to them are unchanged).
  auto extract = vtkSmartPointer<vtkClipPolyData>::New();
  extract->SetInputData(local);
  extract->SetClipFunction(boxFn);
  extract->InsideOutOn();
  extract->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  auto plane = vtkSmartPointer<vtkPlane>::New();
  plane->SetOrigin(0, 0, 0);
  plane->SetNormal(1, 0, 0);
  auto clip = vtkSmartPointer<vtkClipPolyData>::New();
  clip->SetInputConnection(extract->GetOutputPort());
  clip->SetClipFunction(plane);
  clip->SetValue(0);
  clip->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  auto tri = vtkSmartPointer<vtkTriangleFilter>::New();
  tri->SetInputConnection(clip->GetOutputPort());
  tri->Update();
  vtkSmartPointer<vtkPolyData> left = tri->GetOutput();
  const double mirror[16] = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  auto right = TransformSurface(left, mirror);
  auto reverse = vtkSmartPointer<vtkReverseSense>::New();
  reverse->SetInputData(right);
  auto append = vtkSmartPointer<vtkAppendPolyData>::New();
  append->AddInputData(left);
  append->AddInputConnection(reverse->GetOutputPort());
  append->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  append->Update();
  double toWorld[16];
  frame.LocalToWorldMatrix(toWorld);
  auto world = TransformSurface(append->GetOutput(), toWorld);
  world->GetPointData()->Initialize();
  world->GetCellData()->Initialize();
  return world;
}

void RepairFaceAtlas(const FaceAtlasOptions& options, FaceAtlas& atlas)
{
  FEMesh& mesh = atlas.mesh;
  for (int round = 0; round < kRepairRounds; ++round)
  {
    const bool cornersGood = Quality(mesh, options).belowThreshold == 0;
    if (cornersGood && quality::CertifyMesh(mesh).NotValid() == 0)
      break;
    RepairOptions ro;
    ro.scaledJacobianThreshold = options.qualityThreshold + kRepairThresholdMargin;
    ro.skinSurface = atlas.skinSurface;
    ro.skullSurface = atlas.skullSurface;
    ro.hasSymmetryPlane = true;
    ro.symmetryPlane = atlas.plane;
    // Node by node, no global stage: first the corners, then the folds inside elements whose corners
    // are good (the thin columns beside the philtrum), so that the second round moves only their nodes.
    ro.globalUntangling = false;
    ro.keepPlaneSides = false;
    ro.certifyInside = cornersGood;
    const RepairReport rep = RepairMesh(mesh, ro);
    atlas.repairedNodes += rep.movedNodes;
    atlas.log.push_back(FaceAtlasLogLine("repair: %.0f nodes moved; scaled Jacobian min %.3f -> %.3f", rep.movedNodes,
                                         rep.minScaledJacobianBefore, rep.minScaledJacobianAfter));
    ReadLeftHalf(mesh, atlas.frame, atlas.grid);
    WriteNodesFromLeftHalf(atlas.grid, atlas.frame, mesh);
    const auto q = Quality(mesh, options);
    atlas.log.push_back(
      FaceAtlasLogLine("after repair and symmetrisation: scaled Jacobian min %.3f, mean %.3f; %.0f below the threshold",
                       q.min, q.mean, q.belowThreshold));
    atlas.log.push_back(FaceAtlasLogLine("%.0f elements not certified valid inside",
                                         static_cast<double>(quality::CertifyMesh(mesh).NotValid())));
  }
}

void ProjectFaceSurfaceNodes(const FaceAtlasOptions& options, std::vector<char>& onBone, FaceAtlas& atlas)
{
  FEMesh& mesh = atlas.mesh;
  FaceGrid& grid = atlas.grid;
  const int rows = grid.Rows(), cols = grid.Cols();
  // The repair's sliding leaves surface nodes within a fraction of a millimetre of their surfaces:
  // closest points on the triangles, left half, then mirrored.
  const auto skinLoc = Locator(atlas.skinSurface);
  const auto skullLoc = Locator(atlas.skullSurface);
  double worst = 0;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
      for (int k : {0, 3})
      {
        if (k == 3 && !onBone[i * cols + j])
          continue;
        const int n = grid.LeftNode(i, j, k);
        double d = 0;
        const Eigen::Vector3d closest = Closest(k == 0 ? skinLoc : skullLoc, mesh.nodes[n], d);
        worst = std::max(worst, d);
        Eigen::Vector3d p = atlas.frame.ToLocal(closest);
        if (j == 0)
          p.x() = 0;
        grid.local[n] = p;
      }
  WriteNodesFromLeftHalf(grid, atlas.frame, mesh);
  const auto q = Quality(mesh, options);
  atlas.log.push_back(FaceAtlasLogLine(
    "surface nodes projected (largest move %.3f mm): scaled Jacobian min %.3f, mean %.3f", worst, q.min, q.mean));
  // A mid-sagittal inner node is the closest bone point pushed back onto the plane: where the
  // bone meets the plane obliquely that leaves the bone. Such a node is not on the skull but
  // on the offset part of the inner surface (set `inner`), so `skull` means "on the bone".
  auto& skullSet = mesh.nodeSets["skull"];
  auto& innerSet = mesh.nodeSets["inner"];
  int demoted = 0;
  for (int i = 0; i < rows; ++i)
  {
    if (!onBone[i * cols])
      continue;
    const auto n = static_cast<std::int32_t>(grid.Node(i, 0, 3, 0));
    double d = 0;
    Closest(skullLoc, mesh.nodes[n], d);
    if (d <= kOnBoneTolerance)
      continue;
    onBone[i * cols] = 0;
    skullSet.erase(std::find(skullSet.begin(), skullSet.end(), n));
    innerSet.insert(std::upper_bound(innerSet.begin(), innerSet.end(), n), n);
    ++demoted;
  }
  atlas.log.push_back(FaceAtlasLogLine(
    "%.0f mid-sagittal inner nodes farther than 0.1 mm from the bone moved from set skull to inner", demoted));
}

} // namespace mmrep
