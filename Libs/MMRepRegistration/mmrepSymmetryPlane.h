// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Mid-sagittal pseudo-symmetry plane of a head from its skin surface (Chang & Park 2008): mirror
// the surface by a rough plane, rigidly register the mirror onto the original (trimmed, on the
// surface's distance map), and derive the plane from the composed reflection S = T∘M: its normal
// is the eigenvector of S's linear part with eigenvalue -1, and the plane holds the midpoints of p
// and S(p). The samples are one vertex per cell of a regular grid and the matching uses a distance
// map, so the plane does not depend on the order of the vertices or of the CT's voxels.
#pragma once

#include "mmrepPlane.h" // struct Plane

#include <Eigen/Core>
#include <vtkPolyData.h>

namespace mmrep
{

struct SymmetryPlaneOptions
{
  int maximumIterations = 50;      // Gauss-Newton iterations of the fine registration
  std::size_t samplePoints = 4000; // about this many surface points: one vertex per occupied grid cell
  double mapSpacing = 2.0;         // mm, the skin's distance map the mirror image is registered onto
  double trimFraction = 0.2;       // worst pairs ignored each iteration (asymmetric parts, cut planes)
  double tolerance = 1e-4;         // stop when the transform changes by less than this (mm / rad)
  // Initial plane; default: the sagittal plane x = centre of the surface's bounding box.
  bool hasInitialPlane = false;
  Plane initialPlane;
};

struct SymmetryPlaneResult
{
  Plane plane;
  double rmsResidual = 0; // mm, RMS distance between mirrored kept points and the surface
  int iterations = 0;
};

// Throws std::runtime_error for an empty surface or when the registration does not produce a reflection.
SymmetryPlaneResult EstimateSymmetryPlane(vtkPolyData* skin, const SymmetryPlaneOptions& options = {});

} // namespace mmrep
