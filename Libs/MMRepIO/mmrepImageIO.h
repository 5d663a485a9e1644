// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Volume input/output in physical LPS space: NRRD, MetaImage (.mha/.mhd), NIfTI (.nii, .nii.gz)
// and DICOM series directories (ITK's GDCM series reader, first series found, sorted by position).
#pragma once

#include "mmrepImageTypes.h"

#include <string>

namespace mmrep
{

// Reads a file or a DICOM directory. Throws std::runtime_error naming the path on any problem
// (missing, truncated, not 3D, unknown format).
CTImage::Pointer ReadCTImage(const std::string& pathOrDicomDirectory);
FloatImage::Pointer ReadFloatImage(const std::string& path);
MaskImage::Pointer ReadMaskImage(const std::string& path); // values cast to unsigned char
void WriteImage(const CTImage* image, const std::string& path);
void WriteImage(const FloatImage* image, const std::string& path);
void WriteImage(const MaskImage* image, const std::string& path);
// Vector images with 3 components (NRRD, MetaImage, NIfTI), readable by ITK and by Slicer.
DisplacementField::Pointer ReadDisplacementField(const std::string& path);
void WriteDisplacementField(const DisplacementField* field, const std::string& path);
// Writes a DICOM series (one file per slice, CT modality) into an existing directory.
void WriteDicomSeries(const CTImage* image, const std::string& directory);

} // namespace mmrep
