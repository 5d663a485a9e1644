// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The atlas's mouth and jaw (rules in Resources/Atlas/README.md):
//  * mouth slit: the grid row nearest the stomion, from the plane to the column nearest the mouth
//    corner, through the whole thickness (skin to the inner surface facing the oral vestibule).
//    Its nodes are doubled: the upper lip keeps them, the lower lip's elements use new coincident
//    twins (mmrepLipContact.h); the corner column's nodes stay shared. Element sets upperLip /
//    lowerLip: the cells between the slit and the subnasale / the labiomental fold, inside the corner.
//  * condyles: the bone surface point nearest an anthropometric estimate from the outer eye corner
//    (`CondyleOffsets`), each side; stored as the two nodes of set `jawAxis` (mmrepJaw.h).
//  * mandible: the `skull` nodes below the plane through the two condyles and the stomion (the
//    occlusal plane, roughly), maxilla those above; the ones within `vestibule` mm of it are neither.
#pragma once

#include "mmrepFaceFrame.h"
#include "mmrepFaceGrid.h"
#include "mmrepFaceLandmarks.h"
#include "mmrepFEMesh.h"

#include <vtkPolyData.h>

#include <string>

namespace mmrep
{

struct MouthSlitCells
{
  int slitRow = 0;      // grid row of the slit (its nodes are doubled)
  int cornerColumn = 0; // grid column of the corner line (shared nodes); the slit runs over j < cornerColumn
  int lowRow = 0;       // first row of the lower lip's cells (labiomental fold)
  int highRow = 0;      // row of the subnasale: the upper lip's cells end below it
};
MouthSlitCells MouthSlitCellsOf(const FaceGrid& grid, const FaceLandmarkSet& landmarks);

// Doubles the slit's nodes (appended after the existing nodes, left half then right half), gives
// every twin the node sets of its partner, and adds the sets of mmrepLipContact.h.
// Returns the number of twins.
std::size_t CutMouthSlit(FEMesh& mesh, const FaceGrid& grid, const MouthSlitCells& cells);

// Anthropometric estimate of the left condylion from the left outer eye corner (exocanthion), in
// the face frame (mm): lateral to `lateral` from the plane, `posterior` behind and `inferior` below
// the eye corner. Bicondylar breadth ~ 100 mm, exocanthion–tragion ~ 75 mm with the condyle ~ 12 mm
// in front of the tragion, tragion ~ 12 mm below the eye corner (Farkas 1994, head and face tables).
struct CondyleOffsets
{
  double lateral = 50.0, posterior = 62.0, inferior = 12.0;
  // Half-height (mm) of the band around the occlusal plane where the cheek covers the teeth without
  // attaching to bone (the oral vestibule reaches ~10 mm above and below the occlusal plane): its
  // `skull` nodes belong to neither the maxilla nor the mandible, so the cheek stretches when the jaw opens.
  double vestibule = 10.0;
};

// Adds the jaw (mmrepJaw.h): the condyles found on `skullLocal` (the reference bone surface in the
// face frame), node set `jawAxis`, and the split of `skull` into `maxilla` and `mandible`.
// Returns a log line (condyle positions and how far the bone snap moved them).
std::string AddJaw(FEMesh& mesh, vtkPolyData* skullLocal, const FaceFrame& frame, const FaceLandmarkSet& landmarks,
                   const CondyleOffsets& offsets = {});

} // namespace mmrep
