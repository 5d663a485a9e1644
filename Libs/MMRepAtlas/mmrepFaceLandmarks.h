// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Automatic facial landmarks of a head from its skin and bone surfaces (local face frame, see
// mmrepFaceFrame.h), found on ray maps cast from the face centre:
//   * mid-sagittal profile (theta = 0, phi every 0.25 deg): pronasale = most anterior point; walking
//     down, extrema of the anterior coordinate v (smoothed over 1.25 deg, confirmed by a 0.5 mm
//     change): subnasale (minimum), upper lip (labrale superius, maximum), stomion (minimum), lower
//     lip (labrale inferius, maximum). Features whose v-extremum depends on the head's pitch are
//     taken from chords instead: labiomental fold = deepest point behind the chord from the lower
//     lip to the profile point 30 mm lower; pogonion = farthest point in front of the chord from the
//     labiomental fold to the point 25 mm lower; nasion = deepest point behind the chord from the
//     nose tip to the profile point 50 mm higher.
//   * orbits: on a 1 deg map around eye level, rays that meet no bone within 25 mm under the skin;
//     the component nearest the expected eye position is the orbital opening. Inner eye corner:
//     at the opening's mid-height, 3 mm lateral to its medial rim; outer eye corner: 1 mm above
//     mid-height, 6 mm medial to its lateral rim (typical canthus-to-rim distances).
//   * mouth corner: along the lip line (the valley of the skin through the stomion, followed
//     laterally), the lips bulge out of the face; the corner is where that bulge ends: the first
//     column where the lip-line skin is no longer in front of the surrounding cheek (local relief
//     below 0.3 mm), searched 15 to 35 mm from the midline.
// Each landmark is an exact skin ray hit (a point of the skin triangles).
#pragma once

#include "mmrepFaceFrame.h"

#include <string>
#include <vector>

namespace mmrep
{

struct FacePoint
{
  double theta = 0, phi = 0;                       // ray angles (radians)
  Eigen::Vector3d local = Eigen::Vector3d::Zero(); // skin hit, local frame
};

struct FaceLandmarkSet
{
  FacePoint pronasale, subnasale, upperLip, stomion, lowerLip, labiomental, pogonion, nasion;
  FacePoint eyeInner, eyeOuter, lipCorner; // left side (theta > 0)
  FacePoint orbitCentre;                   // centre of the left orbital opening (on the skin)
  double orbitMedialTheta = 0, orbitLateralTheta = 0, orbitBottomPhi = 0, orbitTopPhi = 0;
  std::vector<std::string> log; // what was found, for the report
};

// Skin hit of the ray (theta, phi) from `centre` (the outermost crossing); throws when missed.
FacePoint SkinHit(const SurfaceRays& skin, const Eigen::Vector3d& centre, double theta, double phi);

// Index of the next minimum (wantMin) or maximum of `v` from `start` walking by `step`, confirmed by
// a change of at least `delta` after it (the profile landmarks' rule). -1 when the walk ends first.
int NextExtremum(const std::vector<double>& v, int start, int step, bool wantMin, double delta);

// Throws std::runtime_error naming the landmark when the face does not show the expected shape.
FaceLandmarkSet DetectFaceLandmarks(const SurfaceRays& skin, const SurfaceRays& bone, const Eigen::Vector3d& centre);

// The orbit, eye-corner and mouth-corner rules alone, given the nasion and the stomion in `lm`
// (DetectFaceLandmarks runs them after the profile; the control-point detector for other heads
// reuses them). Throws std::runtime_error when the orbit or the mouth corner is not found.
void DetectOrbitAndMouthCorner(const SurfaceRays& skin, const SurfaceRays& bone, const Eigen::Vector3d& centre,
                               FaceLandmarkSet& lm);

} // namespace mmrep
