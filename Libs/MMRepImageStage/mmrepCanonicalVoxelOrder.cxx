// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepCanonicalVoxelOrder.h"

#include <itkOrientImageFilter.h>

#include <cmath>
#include <stdexcept>

namespace mmrep
{
namespace
{
// Rounding of origin and spacing: far below any voxel size, far above the 1e-12 mm by which two
// headers of one grid differ once one of them is re-expressed from its far corner.
constexpr double kGridQuantum = 1e-6;

double Snap(double v)
{
  return std::round(v / kGridQuantum) * kGridQuantum;
}

bool IsSignedPermutation(const CTImage::DirectionType& d)
{
  for (unsigned r = 0; r < 3; ++r)
  {
    int ones = 0;
    for (unsigned c = 0; c < 3; ++c)
    {
      const double a = std::abs(d[r][c]);
      if (std::abs(a - 1.0) < 1e-6)
        ++ones;
      else if (a > 1e-6)
        return false;
    }
    if (ones != 1)
      return false;
  }
  return true;
}
} // namespace

CTImage::Pointer CanonicalVoxelOrder(const CTImage* ct)
{
  if (ct == nullptr)
    throw std::invalid_argument("canonical voxel order: no image");
  if (!IsSignedPermutation(ct->GetDirection()))
  {
    CTImage::Pointer copy = CTImage::New();
    copy->Graft(ct);
    return copy;
  }
  using Orient = itk::OrientImageFilter<CTImage, CTImage>;
  auto orient = Orient::New();
  orient->SetInput(ct);
  orient->UseImageDirectionOn();
  // ITK names orientations by where the axes come FROM: "RAI" has i, j, k running towards L, P, S.
  orient->SetDesiredCoordinateOrientation(itk::SpatialOrientation::ITK_COORDINATE_ORIENTATION_RAI);
  orient->Update();
  CTImage::Pointer out = orient->GetOutput();
  out->DisconnectPipeline();
  CTImage::DirectionType identity;
  identity.SetIdentity();
  out->SetDirection(identity);
  auto origin = out->GetOrigin();
  auto spacing = out->GetSpacing();
  for (unsigned a = 0; a < 3; ++a)
  {
    origin[a] = Snap(origin[a]);
    spacing[a] = Snap(spacing[a]);
  }
  out->SetOrigin(origin);
  out->SetSpacing(spacing);
  // The region starts at 0 whatever the input's start index (ITK readers give 0; others may not).
  auto region = out->GetLargestPossibleRegion();
  if (region.GetIndex() != CTImage::IndexType{{0, 0, 0}})
  {
    CTImage::PointType first;
    out->TransformIndexToPhysicalPoint(region.GetIndex(), first);
    region.SetIndex(CTImage::IndexType{{0, 0, 0}});
    out->SetRegions(region);
    for (unsigned a = 0; a < 3; ++a)
      origin[a] = Snap(first[a]);
    out->SetOrigin(origin);
  }
  return out;
}

} // namespace mmrep
