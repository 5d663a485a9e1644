// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The project's similarity (mmrep::SimilarityTransform: the registration's initial alignment fitted
// to the control points) as an itk::Similarity3DTransform, for ITK pipelines and transform files.
#pragma once

#include "mmrepSimilarityTransform.h"

#include <itkSimilarity3DTransform.h>

namespace mmrep
{

// x -> scale * rotation * x + translation, centre at the origin. Throws itk::ExceptionObject when
// the rotation is not orthogonal.
itk::Similarity3DTransform<double>::Pointer ToItkSimilarity(const SimilarityTransform& similarity);

} // namespace mmrep
