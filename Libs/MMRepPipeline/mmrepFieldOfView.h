// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Field of view: does the CT cover the face the model is built for? A CT of the cranium only
// (no mouth, no chin) would otherwise give a "speaker model" whose lower face is the atlas's.
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepImageIO.h"

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

// Maps the atlas's face region (the nodes of `faceSet`: brow to chin, both cheeks) into the CT by
// the similarity taking the atlas landmarks to `targets` (the control points, in the atlas
// landmarks' order) and throws std::runtime_error unless the CT's extent holds all of them with
// `margin` mm to spare, naming each side that is missing and by how many mm.
void CheckFieldOfView(const CTImage* ct, const FEMesh& atlas, const std::string& faceSet,
                      const std::vector<Point3>& targets, double margin);

} // namespace mmrep
