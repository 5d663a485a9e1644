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
  CloseAxialSlits(head.skin.GetPointer(), 2); // as BuildFaceAtlas
  s.skin = ExtractSurface(MaskedIntensities(ct, head.skin, s.thresholds.skin), s.thresholds.skin);
  s.skull = ExtractSurface(MaskedIntensities(ct, head.bone, s.thresholds.bone), s.thresholds.bone);
  if (estimatePlane)
    s.symmetry = EstimateSymmetryPlane(s.skin);
  return s;
}

} // namespace mmrep::bench
