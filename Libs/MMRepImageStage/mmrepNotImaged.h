// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// What the scanner did not image. A CT reconstructs a circle of each slice; the voxels outside it
// hold one padding value (the volume's minimum exactly, e.g. -1024 HU), while the air the scanner
// did measure is noisy. Where the head reaches the circle, the skin is a flat cut, not the skin:
// the nose tip of a large face is the usual case. Found here as the tissue voxels that touch the
// padding, so that a model is never silently fitted to a cut.
#pragma once

#include "mmrepImageTypes.h"
#include "mmrepFEMesh.h"

#include <array>
#include <cstddef>
#include <vector>

namespace mmrep
{

struct NotImagedTissue
{
  bool padded = false;           // the CT marks a not-imaged region with a padding value
  short paddingValue = 0;        // the volume's minimum
  std::size_t paddingVoxels = 0; // voxels of that value connected to the volume's border
  std::vector<Point3> cut;       // centres of tissue voxels (>= the skin threshold) on the cut, sorted
};

// The padding is the set of voxels of exactly the volume's minimum value reached from the volume's
// border through voxels of that value. It counts as not imaged when it holds at least 2 % of the
// volume (a reconstruction circle; a few stray voxels of the minimum in noisy air do not) and when
// most of the face's skin within `box` (xmin, xmax, ymin, ymax, zmin, zmax, LPS mm; the whole
// volume when null) does not touch it (a CT whose air is clamped to the minimum everywhere has no
// circle to speak of). `cut` holds the tissue voxels of `box` that face the padding and no measured
// air (a flat cut; skin that also faces air met a thread of stray minimum-valued voxels), and is
// empty unless it holds at least 20 of them (a patch of skin, not noise). The result does not depend on the voxel
// order of the file.
NotImagedTissue FindNotImagedTissue(const CTImage* ct, double skinThreshold,
                                    const std::array<double, 6>* box = nullptr);

} // namespace mmrep
