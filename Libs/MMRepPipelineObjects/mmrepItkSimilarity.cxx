// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// mmrep::SimilarityTransform -> itk::Similarity3DTransform (see the header).
#include "mmrepItkSimilarity.h"

namespace mmrep
{

itk::Similarity3DTransform<double>::Pointer ToItkSimilarity(const SimilarityTransform& similarity)
{
  auto transform = itk::Similarity3DTransform<double>::New();
  itk::Similarity3DTransform<double>::MatrixType m;
  itk::Similarity3DTransform<double>::OutputVectorType t;
  const Eigen::Matrix3d linear = similarity.Linear();
  for (unsigned r = 0; r < 3; ++r)
  {
    for (unsigned c = 0; c < 3; ++c)
      m(r, c) = linear(r, c);
    t[r] = similarity.translation[r];
  }
  transform->SetMatrix(m, 1e-10); // ITK recovers scale and versor from scale * rotation
  transform->SetTranslation(t);
  return transform;
}

} // namespace mmrep
