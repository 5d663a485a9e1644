// Mid-sagittal pseudo-symmetry plane of a head from its skin surface (Chang & Park 2008): mirror
// the surface by a rough plane, rigidly register the mirror onto the original (trimmed ICP), and
// derive the plane from the composed reflection S = T∘M: its normal is the eigenvector of S's
// linear part with eigenvalue -1, and the plane holds the midpoints of p and S(p).
#pragma once

#include "mmrepPlane.h" // struct Plane

#include <Eigen/Core>
#include <vtkPolyData.h>

namespace mmrep
{

struct SymmetryPlaneOptions
{
  int maximumIterations = 50;    // ICP iterations
  std::size_t samplePoints = 4000; // surface points used (deterministic subsample)
  double trimFraction = 0.2;     // worst pairs ignored each iteration (asymmetric parts, cut planes)
  double tolerance = 1e-4;       // stop when the transform changes by less than this (mm / rad)
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

// Throws std::runtime_error for an empty surface or when ICP does not produce a reflection.
SymmetryPlaneResult EstimateSymmetryPlane(vtkPolyData* skin, const SymmetryPlaneOptions& options = {});

} // namespace mmrep
