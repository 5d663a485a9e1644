// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The image types of the whole toolkit (ITK images in physical LPS space, millimetres).
#pragma once

#include <itkImage.h>
#include <itkVector.h>

namespace mmrep
{

using CTImage = itk::Image<short, 3>;           // CT volumes as stored by scanners (HU or scanner units)
using FloatImage = itk::Image<float, 3>;        // distance maps and other scalar fields
using MaskImage = itk::Image<unsigned char, 3>; // binary masks: 1 inside, 0 outside
// Displacement fields (mm, LPS): the transform's direction is documented where a field is made.
using DisplacementField = itk::Image<itk::Vector<float, 3>, 3>;

} // namespace mmrep
