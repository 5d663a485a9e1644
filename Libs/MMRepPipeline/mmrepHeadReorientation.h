// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// A CT whose orientation header is wrong (stored turned or upside down: the control points show the
// face looking sideways, up or down in LPS) put right: the quarter turns that make the face look to
// the front and stand upright, applied to the CT's header and to the control points, so the model is
// built, and written, in the patient's true LPS frame.
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepImageIO.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mmrep
{

struct HeadReorientation
{
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity(); // corrected = rotation · stored (LPS mm)
  bool applied = false;
  std::string before; // where the stored face looked, in words ("to the patient's left, top to the top")
};

// The quarter-turn rotation (a signed permutation) taking the face that `targets` (in the order of
// atlas.landmarks) describe to the atlas's orientation; `applied` only when the face is turned more
// than `maxTurn` degrees from it (what the plausibility check refuses).
HeadReorientation FaceUprightRotation(const FEMesh& atlas, const std::vector<Point3>& targets, double maxTurn);

// "the CT's orientation header was corrected: the face looked to …; the model is in the corrected frame
// (rotation [[…]])": for the warning line and the report.
std::string ReorientationInWords(const HeadReorientation& r);

// The CT with its header turned by `rotation` (direction and origin; the voxels are shared).
CTImage::Pointer ReorientedCT(const CTImage* ct, const Eigen::Matrix3d& rotation);

} // namespace mmrep
