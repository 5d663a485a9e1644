// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Synthetic subject CT from a source CT and a SyntheticWarp, and the warp's dense displacement
// fields (see mmrepSyntheticWarp.h for the direction convention).
#pragma once

#include "mmrepImageIO.h"
#include "mmrepSyntheticWarp.h"

#include <functional>
#include <string>

namespace mmrep
{

// Rotation centre = the volume's physical centre; bump centres drawn in the central 60% of its
// physical bounding box (where the head is).
void FitWarpToImage(SyntheticWarpParameters& parameters, const itk::ImageBase<3>* image);

// I_subject(y) = I_source(G(y)) on the source's grid (trilinear; points mapped outside the source
// get its minimum intensity, i.e. air).
CTImage::Pointer ResampleSyntheticSubject(const CTImage* source, const SyntheticWarp& warp,
                                          const std::function<void(double)>& progress = {});

// On the grid of `grid`: forward field D(x) = F(x) - x at source points (so F(x) = x + D(x)), and
// inverse field E(y) = G(y) - y at subject points (ITK's displacement-field-transform convention for
// resampling the source into the subject).
DisplacementField::Pointer ForwardDisplacementField(const itk::ImageBase<3>* grid, const SyntheticWarp& warp);
DisplacementField::Pointer InverseDisplacementField(const itk::ImageBase<3>* grid, const SyntheticWarp& warp);

} // namespace mmrep
