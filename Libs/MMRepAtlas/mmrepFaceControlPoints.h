// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The atlas's five control points (FaceAtlasLandmarkNames) on any head, by the same automatic
// rules the atlas builder uses on its reference head (mmrepFaceLandmarks.h): face frame on the
// symmetry plane, face centre on the plane halfway through the head at the nose tip's level and
// 10 mm lower, rays from it. Used to give a subject CT the control points the registration needs.
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepFaceFrame.h"
#include "mmrepFaceLandmarks.h"
#include "mmrepPlane.h"

#include <vtkPolyData.h>

#include <string>
#include <vector>

namespace mmrep
{

struct FaceControlPoints
{
  std::vector<Landmark> points; // world (LPS), names and order of FaceAtlasLandmarkNames()
  FaceFrame frame;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(); // face centre (local)
  FaceLandmarkSet landmarks;                        // all detected landmarks (local)
  bool usedFallback = false;                        // the atlas rules failed; see DetectFaceControlPoints
  std::vector<std::string> log;
};

// The atlas builder's face-centre rule on a skin surface given in the local face frame: on the
// plane, at the level of the nose tip (most anterior skin point within 10 mm of the plane) 10 mm
// lower, halfway between the tip and the back of the head (their distance in *headDepth when
// given). Throws for a surface without points or without skin within 10 mm of the plane.
Eigen::Vector3d FaceCentreOfLocalSkin(vtkPolyData* skinLocal, double* headDepth = nullptr);

// The atlas rules first (DetectFaceLandmarks: same points as the atlas's on its reference CT).
// When they fail (a flat face whose brow is as far forward as the nose, or a volume cut less than
// 55 mm below the lower lip, as headsq), the same rules with two changes: nose tip = the profile
// point farthest in front of the chord between the profile points 20 mm above and below it, and
// no chin landmarks (the nasion chord stops at the top of the profile when it is shorter than
// 50 mm, at least 25 mm). Throws std::runtime_error (empty surfaces, or the rule that fails).
FaceControlPoints DetectFaceControlPoints(vtkPolyData* skin, vtkPolyData* skull, const Plane& plane);

} // namespace mmrep
