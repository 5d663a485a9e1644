// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Steps shared by the atlas registration R and the local refinement Q (internal to the library).
#pragma once

#include "mmrepElasticOptimizer.h"
#include "mmrepElasticTransform.h"
#include "mmrepFEMesh.h"
#include "mmrepImageTypes.h"
#include "mmrepPlane.h"
#include "mmrepSurfaceDistanceMap.h"

#include <vtkPolyData.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace mmrep::registration
{

// Nodes within this distance (mm) of the plane count as plane nodes (a symmetric atlas has them on it
// to rounding).
constexpr double kPlaneTolerance = 1e-3;

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t0);

// Mesh guard: every node of a hexahedron not yet tracked becomes a passive point, and the
// hexahedra are given over point indices (mmrepElasticOptimizer.h says why).
// `innerMap(node)` gives the pointMap of a node that is not tracked yet (−1 passive, −2 held).
void AddMeshGuard(
  const FEMesh& mesh, const std::vector<std::int32_t>& trackedNodes,
  const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& toFrame, ElasticProblem& problem,
  const std::function<int(std::size_t)>& innerMap = [](std::size_t) { return -1; });

// Rigid frame whose x axis is the plane normal and whose origin lies on the plane.
void SetPlaneFrame(ElasticTransform& t, const Plane& plane);
void CheckPlane(const Plane& p, const std::string& what);
const std::vector<std::int32_t>& NodeSet(const FEMesh& mesh, const std::string& name, const std::string& what);
void CheckSurface(vtkPolyData* s, const std::string& what);
std::vector<std::int32_t> Intersection(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b);
// The finest level whose smallest cell is at least `cellsPerSpacing` map voxels.
int AutomaticLevel(double smallestExtent, double spacing, double cellsPerSpacing);
// Signed map when asked and possible (closed surface), unsigned otherwise: any failure of the
// signed computation (open or non-manifold surface) retries unsigned, whose own errors propagate.
FloatImage::Pointer DistanceMap(vtkPolyData* surface, SurfaceDistanceMapOptions o, bool trySigned,
                                const std::function<void(double)>& progress);
// With `symmetric`, [lo, hi] widened to be symmetric in frame x (about the plane).
void SymmetricInX(bool symmetric, Eigen::Vector3d& lo, Eigen::Vector3d& hi);

} // namespace mmrep::registration
