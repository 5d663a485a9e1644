// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Mesh reparation (Bucki, Lobos, Payan, Hitschfeld 2011, improved as the MMRep-for-speech paper's
// conclusion proposes): first make every element regular (positive Jacobian at every corner), all the
// nodes around the inverted elements at once (foldover-free untangling) and then node by node,
// then raise every element's scaled Jacobian to a threshold, moving the nodes of the worst elements
// first and inner nodes before surface nodes; what stays below it is relaxed globally and repaired
// node by node again; last, elements whose corners are good but that fold inside are opened (success
// means valid inside every element, quality::CertifyMesh). Surface nodes slide on their surface
// (projected back onto it), mid-sagittal nodes stay on the symmetry plane and the nodes beside it on
// their side of it, so accuracy and symmetry are kept. A mesh already valid (at the threshold and
// inside every element) is returned unchanged, bit for bit.
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepPlane.h"

#include <vtkPolyData.h>

#include <functional>
#include <string>
#include <vector>

namespace mmrep
{

struct RepairOptions
{
  double scaledJacobianThreshold = 0.3; // every solid element must reach this
  int maximumSweeps = 200;              // passes over the elements below the threshold
  // Untangle the inverted elements globally first (mmrepFoldoverFreeUntangling.h), then node by node.
  bool globalUntangling = true;
  // Nodes next to the symmetry plane's sheet of nodes stay on the side where their elements lie;
  // pushed across (a tangle can leave every corner positive while the two halves overlap), they go
  // back first (mmrepRepairConstraints.h).
  bool keepPlaneSides = true;
  // Success means valid inside every element, not only at the corners: an element whose corners are
  // good but whose det J is not certified positive inside (quality::CertifiedQuality) counts as
  // inverted, and the repair opens its fold.
  bool certifyInside = true;
  // Surfaces the `skin` and `skull` node sets must stay on (nullptr: the mesh's own boundary).
  vtkPolyData* skinSurface = nullptr;
  vtkPolyData* skullSurface = nullptr;
  // Nodes of the `midsagittal` set stay on this plane (and the result stays symmetric about it
  // when the input is) when set. Without a plane, `midsagittal` nodes stay on the plane fitted to
  // them when they are coplanar.
  bool hasSymmetryPlane = false;
  Plane symmetryPlane;
  std::function<void(double)> progress; // fraction done
};

struct RepairReport
{
  // Every element regular and >= threshold at its corners, and (with certifyInside) valid inside.
  bool success = false;
  double minScaledJacobianBefore = 0, minScaledJacobianAfter = 0;   // NaN when every element is degenerate
  double meanScaledJacobianBefore = 0, meanScaledJacobianAfter = 0; // (as quality::SummarizeScaledJacobian)
  std::size_t invertedBefore = 0, invertedAfter = 0;
  std::size_t belowThresholdBefore = 0, belowThresholdAfter = 0; // degenerate elements included
  // Validity inside the elements (quality::CertifyMesh), reported beside the corner measures: elements
  // not proved valid everywhere inside, and the smallest certified lower bound of det J / mean det J.
  std::size_t notCertifiedBefore = 0, notCertifiedAfter = 0;
  double certifiedMinimumBefore = 0, certifiedMinimumAfter = 0;
  int untanglingSteps = 0; // minimisations of the global untangling (0: nothing inverted, or switched off)
  double untanglingSeconds = 0;
  std::size_t movedNodes = 0;
  std::size_t movedSurfaceNodes = 0;       // of which in `skin` or `skull`
  bool symmetricPairs = false;             // mirror node pairs were moved together
  std::vector<std::size_t> failedElements; // elements still below the threshold, worst first
  // Their scaled Jacobians, same order; a degenerate element (zero-length edge, Verdict's 1e30
  // flag) is reported as -infinity.
  std::vector<double> failedValues;
  // Elements whose corners meet the threshold but that are not certified valid inside, worst first,
  // with their certified lower bounds of det J / mean det J.
  std::vector<std::size_t> foldedInside;
  std::vector<double> foldedInsideValues;
  double seconds = 0;
};

// Repairs `mesh` in place and reports. Never throws for a mesh that cannot be repaired: the report
// says which elements fail and how bad they are. Throws std::invalid_argument for invalid meshes
// (bad indices, no solid element), a threshold outside [-1, 1] or an empty surface.
RepairReport RepairMesh(FEMesh& mesh, const RepairOptions& options);

} // namespace mmrep
