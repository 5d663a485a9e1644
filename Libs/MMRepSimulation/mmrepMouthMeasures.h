// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// What a speech scientist reads off a lip gesture: the mouth width (corner to corner), the lip
// aperture at the centre (height of the opening between the lips' outer edges on the mid-sagittal
// plane) and its width (extent of the parted part of the slit), the protrusion of each lip (forward
// motion of the upper/lower lip-centre landmarks) and the smallest gap between the lips' facing
// surfaces (negative = interpenetration). "Forward" is the face's anterior direction, the plane
// normal (oriented to the patient's left) crossed with the superior axis: −y in LPS for an upright head.
#pragma once

#include "mmrepMuscleActivation.h"

namespace mmrep::simulation
{

struct MouthMeasures
{
  bool hasCorners = false;         // LeftLipCorner landmark present
  double restWidth = 0, width = 0; // mm, corner to corner (right corner = mirror of the left)
  Point3 leftCorner = Point3::Zero(), rightCorner = Point3::Zero(); // corner displacements (mm, LPS)
  double upperProtrusion = 0, lowerProtrusion = 0;                  // mm forward (NaN without the landmark)
  bool hasSlit = false;                                             // a model with a mouth slit
  double apertureHeight = 0, apertureWidth = 0;                     // mm
  double minimumLipGap = 0, meanLipGap = 0;                         // mm over the lower lip's facing nodes
};

// The plane is fitted to node set "midsagittal" (or "symmetryBoundary" on a half model, whose right
// corner is the left one's mirror image, as is its motion).
MouthMeasures MeasureMouth(const FEMesh& mesh, const ActivationResult& result);

} // namespace mmrep::simulation
