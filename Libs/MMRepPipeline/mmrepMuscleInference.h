// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Muscle inference (paper §3.4): the atlas's muscle tracks carried into the subject through the
// registration transform (Q∘R, atlas -> subject). Each track keeps its structure (points in order,
// insertion first, its cable elements); only positions and the embedding change: every track
// point is located again in the subject mesh's solid elements, so a solver can tie it to the
// element that now contains it.
#pragma once

#include "mmrepFEMesh.h"

#include <functional>
#include <string>
#include <vector>

namespace mmrep
{

using PointMap = std::function<Point3(const Point3&)>;

struct MuscleInsertion
{
  std::string muscle;
  Point3 atlas = Point3::Zero(), subject = Point3::Zero(); // first track point (bone insertion or meeting point)
};

struct MuscleInferenceReport
{
  std::size_t muscles = 0, points = 0;
  // Track points that no subject element contains (a repair moved the boundary under them): they
  // keep their transformed position and are embedded in the nearest element, whose parametric
  // coordinates then lie slightly outside [0, 1]; the largest such distance is reported.
  std::size_t outside = 0;
  double maxOutsideDistance = 0;           // mm
  std::size_t changedElement = 0;          // points now in another element than in the atlas
  std::vector<MuscleInsertion> insertions; // one per muscle, in name order
};

// `subject` must have the atlas's topology (same node count, elements and muscles), e.g. the
// atlas after registration and repair. Moves every muscle node of `subject` to
// atlasToSubject(atlas position) and recomputes the embeddings. Deterministic: among elements
// containing a point (shared faces) the atlas's element wins, then the lowest index.
// Throws std::invalid_argument when the topologies differ or the atlas has no muscles.
MuscleInferenceReport InferMuscles(const FEMesh& atlas, const PointMap& atlasToSubject, FEMesh& subject);

// Insertion points of every muscle of a mesh (first node of each track), in name order.
std::vector<std::pair<std::string, Point3>> MuscleInsertions(const FEMesh& mesh);

} // namespace mmrep
