// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Field of view: does the CT cover the face the model is built for? A CT of the cranium only
// (no mouth, no chin) would otherwise give a "speaker model" whose lower face is the atlas's.
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepImageIO.h"
#include "mmrepNotImaged.h"

#include <array>
#include <string>
#include <vector>

namespace mmrep
{

// What of the face region the CT misses: "chin by 23 mm, right cheek by 4 mm" (each short side, by
// how many mm including the margin); empty when the CT holds it all, or when the control points
// place nothing (coincident, collinear: the pipeline reports those itself).
std::string MissingFieldOfView(const CTImage* ct, const FEMesh& atlas, const std::string& faceSet,
                               const std::vector<Point3>& targets, double margin);

// The box (xmin, xmax, ymin, ymax, zmin, zmax) of the face region placed in the CT by the control
// points: the least the subject's skin (and its distance map) covers. False when they place nothing.
bool FaceRegionBounds(const FEMesh& atlas, const std::string& faceSet, const std::vector<Point3>& targets,
                      std::array<double, 6>& box);

// The face regions the not-imaged cut lies in, in words ("the nose tip", "the nose tip and the
// left cheek": each region holding at least a fifth of the cut), from where the control points
// place the atlas's face: eye, nose, lips and chin levels, the midline and the mouth corners.
// Empty when there is no cut or the control points place nothing.
std::string NotImagedRegions(const FEMesh& atlas, const std::vector<Point3>& targets, const NotImagedTissue& notImaged);

// The sentence a user reads: "the nose tip is outside the scanner's field of view (the skin there
// is a flat cut: 412 voxels touch the padding value -1024): the model's nose tip there is the
// atlas's". Empty when `regions` is.
std::string NotImagedMessage(const std::string& regions, const NotImagedTissue& notImaged);

// The nodes of `mesh`'s `skinSet` within `radius` mm of the cut, in ascending order.
std::vector<std::int32_t> NodesOnNotImagedSkin(const FEMesh& mesh, const std::string& skinSet,
                                               const NotImagedTissue& notImaged, double radius);

} // namespace mmrep
