// Subject surfaces of a head CT for the registration benchmark and the sample control points:
// the image stage exactly as BuildFaceAtlas runs it on the atlas's reference CT (automatic
// thresholds, SegmentHead, axial slits of at most two slices closed in the head mask so the lips
// meet, Marching Cubes of the masked intensities), plus the estimated symmetry plane.
#pragma once

#include "mmrepCTThresholds.h"
#include "mmrepHeadSegmentation.h"
#include "mmrepImageIO.h"
#include "mmrepSurfaceExtraction.h"
#include "mmrepSymmetryPlane.h"

#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <limits>
#include <string>

namespace mmrep::bench
{

struct SubjectSurfaces
{
  vtkSmartPointer<vtkPolyData> skin, skull;
  CTThresholds thresholds;
  SymmetryPlaneResult symmetry;
};

// Background runs of at most `maxRun` voxels along the axial axis with tissue at both ends are
// filled (the lip slit of a closed mouth); the rule of BuildFaceAtlas's CloseAxialSlits.
inline std::size_t CloseAxialSlitsOf(MaskImage* mask, int maxRun)
{
  const unsigned axis = AxialAxis(mask);
  const auto size = mask->GetLargestPossibleRegion().GetSize();
  const std::size_t stride[3] = {1, size[0], size[0] * size[1]};
  unsigned char* data = mask->GetBufferPointer();
  const unsigned a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  std::size_t filled = 0;
  for (std::size_t p = 0; p < size[a1]; ++p)
    for (std::size_t q = 0; q < size[a2]; ++q)
    {
      const std::size_t base = p * stride[a1] + q * stride[a2];
      long last = -1;
      for (long k = 0; k < static_cast<long>(size[axis]); ++k)
      {
        if (!data[base + k * stride[axis]])
          continue;
        if (last >= 0 && k - last > 1 && k - last - 1 <= maxRun)
          for (long g = last + 1; g < k; ++g, ++filled)
            data[base + g * stride[axis]] = 1;
        last = k;
      }
    }
  mask->Modified();
  return filled;
}

inline SubjectSurfaces SubjectSurfacesFromCT(const CTImage* ct, bool estimatePlane = true)
{
  // Sequential VTK locators: the plane's ICP gives the same bytes on every run (as BuildFaceAtlas).
  vtkSMPTools::SetBackend("Sequential");
  SubjectSurfaces s;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  s.thresholds = ChooseThresholds(ct, ThresholdMode::Automatic, nan, nan);
  HeadSegmentationOptions seg;
  seg.skinThreshold = s.thresholds.skin;
  seg.boneThreshold = s.thresholds.bone;
  const auto head = SegmentHead(ct, seg);
  CloseAxialSlitsOf(head.skin.GetPointer(), 2);
  s.skin = ExtractSurface(MaskedIntensities(ct, head.skin, s.thresholds.skin), s.thresholds.skin);
  s.skull = ExtractSurface(MaskedIntensities(ct, head.bone, s.thresholds.bone), s.thresholds.bone);
  if (estimatePlane)
    s.symmetry = EstimateSymmetryPlane(s.skin);
  return s;
}

} // namespace mmrep::bench
