// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Facial muscle tracks of the atlas, one rule per muscle (left side; the right side is the mirror).
//
// A rule gives a few control points in the atlas's face parameterisation: ray angles (theta, phi)
// placed relative to the detected landmarks by offsets in millimetres, and a thickness fraction
// (0 skin, 1 inner surface; bone insertions use 0.95, i.e. in the hypodermis 0.05 of the
// thickness above the bone). The track is the polyline through the control points interpolated
// in that parameterisation (so it follows the face's curvature) and resampled every ~4 mm; each
// point lies inside a hexahedron by construction and its embedding (element + VTK parametric
// coordinates) is exact. Rules (lateral = towards the patient's left, mm along the face):
//   OrbicularisOrisPeripheralisUpper: midline halfway between subnasale and upper lip -> 8 mm
//       lateral of the mouth corner (modiolus), depth 0.75, arched 2 mm upwards at mid-course.
//   OrbicularisOrisPeripheralisLower: midline halfway between lower lip and labiomental fold ->
//       modiolus, depth 0.75, arched 2 mm downwards.
//   OrbicularisOrisMarginalisUpper: midline 1.5 mm above the stomion -> mouth corner, depth 0.55.
//   OrbicularisOrisMarginalisLower: midline 1.5 mm below the stomion -> mouth corner, depth 0.55.
//   ZygomaticusMajor: zygomatic bone, 10 mm lateral and 22 mm below the outer eye corner
//       (near the zygomaticotemporal suture), depth 0.95 -> the skin above the mouth corner, 4 mm
//       lateral and 2 mm above it, depth 0.3 (inserts into the dermis).
//   Risorius: parotid fascia 40 mm lateral of the corner at its level, depth 0.6 -> modiolus, 0.55.
//   LevatorLabiiSuperioris: infraorbital margin below the middle of the orbit, 6 mm under its rim,
//       depth 0.95 -> upper lip, 45% of the way to the corner, 3 mm above the upper-lip centre, 0.6.
//   LevatorLabiiSuperiorisAlaequeNasi: frontal process of the maxilla, 3 mm medial and 4 mm below the
//       inner eye corner, depth 0.95 -> 10 mm lateral, at the subnasale level, 0.6.
//   LevatorAnguliOris: canine fossa, 80% of the corner's lateral offset, 8 mm above the subnasale,
//       depth 0.95 -> modiolus 3 mm above the corner, 0.6.
//   DepressorAnguliOris: mandible (oblique line), 12 mm lateral of the corner at the level 6 mm
//       below the pogonion, depth 0.95 -> modiolus 2 mm below the corner, 0.6.
//   DepressorLabiiInferioris: mandible, 60% of the corner's offset, 4 mm below the pogonion level,
//       depth 0.95 -> lower lip, 35% of the corner's offset, 2 mm below the lower-lip centre, 0.6.
//   Mentalis: incisive fossa, 5 mm lateral, 3 mm below the labiomental fold, depth 0.95 -> chin
//       skin, 7 mm lateral, 4 mm below the pogonion, depth 0.35 (inserts into the dermis).
//   Buccinator: alveolar processes behind the molars, 35 mm lateral of the corner at its level,
//       depth 0.95 -> modiolus, 0.7 (deep in the cheek).
// Maximum force of each fibre (N; FaceMuscleMaximumForce, sources in Resources/Atlas/README.md):
//   ZygomaticusMajor 3.25: the smile force at the mouth corner measured with a direct probe,
//       0.730 lb (Neely & Pomerantz 2002).
//   OrbicularisOris* 0.43: the pucker force at the corner, 0.387 lb = 1.72 N (same study, surface
//       adhesion), shared by the four tracks of a side that pull on the corner.
//   every other muscle 1.0: ArtiSynth's face model's generic fibre force (no cited value found).
#pragma once

#include "mmrepFaceFrame.h"
#include "mmrepFaceGrid.h"
#include "mmrepFaceLandmarks.h"
#include "mmrepFEMesh.h"

#include <string>
#include <vector>

namespace mmrep
{

struct MuscleControlPoint
{
  double theta = 0, phi = 0, depth = 0.5; // ray angles (left side) and thickness fraction
};

struct MuscleRule
{
  std::string name;                                        // without side suffix
  std::vector<MuscleControlPoint> points;                  // first = insertion (bone or meeting point)
  bool startsOnMidline = false;                            // first point on the plane: shared by _L and _R
  double maximumForce = MuscleTrack::kDefaultMaximumForce; // N, per track
};

// The maximum force (N) of a muscle's fibre by rule name (without side suffix), see above.
double FaceMuscleMaximumForce(const std::string& name);

// The rules above, evaluated on the landmarks (centre = face centre, local frame).
std::vector<MuscleRule> FaceMuscleRules(const FaceLandmarkSet& landmarks, const Eigen::Vector3d& centre);

// Adds, for each rule, muscles <name>_L and <name>_R to `mesh` (world coordinates): new nodes,
// cable elements, embeddings, an element set <name>_L/_R with the cables. Nodes on the plane are
// added once and shared by both sides; the `midsagittal` node set receives them.
void AddFaceMuscles(FEMesh& mesh, const FaceGrid& grid, const FaceFrame& frame, const std::vector<MuscleRule>& rules,
                    double spacing = 4.0);

} // namespace mmrep
