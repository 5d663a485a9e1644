// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Skin and bone masks of a head CT.
//
// Skin: threshold, a small opening to detach the table, head holder and cushions, the largest
// connected component (the head), then interior air (airways, sinuses, ear canals) filled so the
// skin is one closed outer surface: background not reachable from the volume border in 3-D, then
// background enclosed within each axial slice (airways leave the volume through the neck).
// Bone: threshold inside the filled head, largest connected component, enclosed cavities filled.
#pragma once

#include "mmrepImageIO.h"

#include <functional>

namespace mmrep
{

struct HeadSegmentationOptions
{
  double skinThreshold = 0;       // intensities >= this are tissue
  double boneThreshold = 0;       // intensities >= this are bone
  unsigned int openingRadius = 1; // voxels; 0 disables the opening
  bool fillInteriorAir = true;    // fill airways and sinuses in the skin mask
  // mm³; 0: from the CT's size, 5 % of the imaged volume, at most 500 ml (an adult head is 3–5 l)
  // and at least 150 ml (a newborn's is about 400 ml), so that a small head in a small volume is found.
  double minimumHeadVolume = 0;
  double minimumBoneVolume = 2.0e4; // mm³ (20 ml)
};

struct HeadSegmentation
{
  MaskImage::Pointer skin;
  MaskImage::Pointer bone;
  double skinVolume = 0; // mm³
  double boneVolume = 0; // mm³
};

// Throws std::runtime_error with a one-line reason: empty segmentation at the threshold, no head
// (largest component too small), no bone.
HeadSegmentation SegmentHead(const CTImage* ct, const HeadSegmentationOptions& options,
                             const std::function<void(double)>& progress = {});

// Index axis closest to the patient's superior-inferior direction (LPS z).
unsigned int AxialAxis(const itk::ImageBase<3>* image);

// Sets to 1 every background voxel not 6-connected to the volume border; with `axialSlices`,
// then also every background pixel not 4-connected to the border of its slice along `axis`.
void FillEnclosedBackground(MaskImage* mask, bool axialSlices, unsigned int axis);

// Closes thin horizontal slits of a head mask: background runs of at most `maxRun` voxels along
// the axial axis with tissue at both ends (the lip slit of a closed mouth, the eyelid slit), so
// that the skin passes over the slit instead of diving into it (the mouth closed at rest, as the
// face atlas has it). Returns the number of voxels set.
std::size_t CloseAxialSlits(MaskImage* mask, int maxRun);

// Binary opening by a Euclidean ball of `radius` voxels (index units), exact: erosion and dilation
// are thresholds of Saito–Toriwaki distance maps. An opening that would remove everything leaves
// the mask empty.
void OpenWithBall(MaskImage* mask, unsigned int radius);

// Keeps only the largest 6-connected foreground component; returns its voxel count (0 if none).
std::size_t KeepLargestComponent(MaskImage::Pointer& mask);

// CT copy whose iso-surface at `threshold` is the boundary of `mask`: voxels inside are raised to
// at least threshold+1, voxels outside lowered to at most threshold-1, others keep their values so
// Marching Cubes still interpolates the real intensities where the mask follows the threshold.
CTImage::Pointer MaskedIntensities(const CTImage* ct, const MaskImage* mask, double threshold);

} // namespace mmrep
