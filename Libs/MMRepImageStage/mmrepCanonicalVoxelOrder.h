// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The same physical CT in one voxel order: a volume whose axes are a signed permutation of L, P, S
// (any NRRD, NIfTI or DICOM series of an axis-aligned scan) is re-indexed so that i, j, k run along
// +L, +P, +S, and its origin and spacing are rounded to 1e-6 mm. Two files holding the same voxels
// in another order (flipped or swapped axes, RAS or LPS headers, a DICOM series) then give the same
// array, origin and spacing to the last bit, and every later stage gives the same bytes.
// Oblique volumes are returned as they are.
#pragma once

#include "mmrepImageIO.h"

namespace mmrep
{

CTImage::Pointer CanonicalVoxelOrder(const CTImage* ct);

} // namespace mmrep
