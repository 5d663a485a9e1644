// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The generic face atlas: a symmetric three-layer hexahedral mesh of the facial soft tissue of a
// reference head (skin and bone surfaces + symmetry plane), with node sets, landmarks and muscles.
//
// Construction (details and reasons in Resources/Atlas/README.md):
//  1. Face frame on the symmetry plane (mmrepFaceFrame.h); the face centre lies on the plane,
//     halfway through the head behind the nose tip, 10 mm below it. Landmarks are detected from
//     rays cast from it (mmrepFaceLandmarks.h).
//  2. Left half: a structured (theta, phi) grid of rays, from `chinMargin` mm below the pogonion to
//     `browMargin` mm above the nasion and from the plane to `lateralAngle`; spacing `meshSize` mm,
//     `lipsMeshSize` mm over the mouth (subnasale to labiomental fold, out to 6 mm past the
//     corner), changing gradually over `gradingLength` mm.
//  3. Skin node = outermost crossing of the ray with the skin. Through-thickness direction = blend
//     of the inward ray and the inward smoothed skin normal (`normalBlend` = weight of the normal);
//     on the plane it is kept in the plane.
//  4. Inner node = first bone crossing along that direction within `maxBoneDepth` mm (node set
//     `skull`), except over the mouth (teeth and metal streaks, lips not attached to bone) and
//     where the depth jumps by more than `outlierDepth` mm from its neighbourhood's median or is
//     below `minThickness`; there the thickness is the harmonic interpolation of the accepted bone
//     depths (node set `inner`), and no column is thinner than `minThickness`.
//  5. Levels split the thickness in epidermis : dermis : hypodermis = `layerRatios`.
//  6. Mirror: the right half is the mirror image, nodes on the plane are shared.
//  7. Quality: smoothing of the inner nodes that are not on bone and, when needed, RepairMesh
//     (skin nodes on the skin, skull nodes on the bone, mid-sagittal nodes on the plane); the
//     result is re-symmetrised exactly.
//  8. Node sets skin, skull, inner, midsagittal, lips; landmarks; muscles (mmrepFaceMuscles.h).
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepFaceFrame.h"
#include "mmrepFaceGrid.h"
#include "mmrepFaceLandmarks.h"
#include "mmrepPlane.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace mmrep
{

struct FaceAtlasOptions
{
  double meshSize = 4.0;       // mm, in-plane element size
  double lipsMeshSize = 2.0;   // mm, over the mouth
  double gradingLength = 12.0; // mm over which the size changes
  double lateralAngle = 70.0;  // degrees from the front, each side
  double browMargin = 30.0;    // mm above the nasion (above the eyebrows)
  double chinMargin = 12.0;    // mm below the pogonion (below the chin)
  double maxBoneDepth = 20.0;  // mm: bone farther under the skin is not followed
  // mm: bone nearer the skin is not followed either, and no column is thinner. Facial soft tissue
  // is 3 mm or more almost everywhere (forensic depth tables); shallower "bone" crossings are metal
  // streaks or the nasal rim, and columns thinner than this invert under any registration.
  double minThickness = 3.0;
  double outlierDepth = 3.0; // mm: bone depths this far from the local median are ignored
  double normalBlend = 0.5;  // weight of the smoothed skin normal in the through-thickness direction
  std::array<double, 3> layerRatios{0.15, 0.30, 0.55}; // epidermis, dermis, hypodermis
  double qualityThreshold = 0.5;                       // minimum scaled Jacobian to reach
  double muscleSpacing = 4.0;                          // mm between muscle track points
};

struct FaceAtlas
{
  FEMesh mesh;                                      // world (LPS) coordinates
  Plane plane;                                      // symmetry plane used
  FaceFrame frame;                                  // local frame
  FaceGrid grid;                                    // left-half grid (local coordinates)
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(); // face centre (local)
  FaceLandmarkSet landmarks;                        // local coordinates
  // Reference surfaces of the atlas (world): the reference head's left half and its mirror image,
  // cut to the atlas region (+15 mm). Skin nodes lie on `skinSurface`, skull nodes on `skullSurface`.
  vtkSmartPointer<vtkPolyData> skinSurface, skullSurface;
  std::size_t repairedNodes = 0;
  std::vector<std::string> log; // construction report, one line per entry
};

// Throws std::runtime_error with a one-line reason when the head does not have the expected shape.
FaceAtlas BuildFaceAtlas(vtkPolyData* skin, vtkPolyData* skull, const Plane& plane, const FaceAtlasOptions& options,
                         const std::function<void(double)>& progress = {});

// Landmark names of the atlas, in their order: LeftEyeInnerCorner, LeftEyeOuterCorner,
// LeftLipCorner, UpperLipCenter, LowerLipCenter.
const std::vector<std::string>& FaceAtlasLandmarkNames();
// Those landmarks (world) from the detected ones: eye inner and outer corner, lip corner, upper
// and lower lip.
std::vector<Landmark> FaceAtlasLandmarks(const FaceLandmarkSet& landmarks, const FaceFrame& frame);

} // namespace mmrep
