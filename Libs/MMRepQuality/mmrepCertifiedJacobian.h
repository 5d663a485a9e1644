// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Validity inside an element, not only at its corners. The Jacobian determinant of a trilinear
// hexahedron is a tri-quadratic polynomial: its 27 Bernstein coefficients bound it from below over
// the element, the corner values bound its minimum from above, and subdividing (Johnen, Remacle,
// Geuzaine 2013) tightens both until the sign is decided. A wedge's determinant is linear over the
// triangle and quadratic along the height, so its minimum is found exactly; a tetrahedron's is a
// constant. A hexahedron whose eight corner Jacobians are positive can still fold inside (two nodes
// nearly touching): the corner test misses it, this one does not.
#pragma once

#include "mmrepFEMesh.h"

#include <cstddef>
#include <vector>

namespace mmrep::quality
{

enum class Validity
{
  Valid,          // det J > 0 over the whole element (certified)
  InvertedCorner, // det J <= 0 at a corner: the corner test sees it too
  InvertedInside, // positive at every corner, det J <= 0 at an inner point
  Undecided,      // neither proved at the subdivision depth: counted as not valid
  NotSolid        // a cable element
};

struct CertifiedJacobian
{
  Validity validity = Validity::NotSolid;
  // Bounds of min det J over the element, relative to its mean det J (1 for a parallelepiped):
  // lower <= min <= upper, within 1 % of the mean where the subdivision depth allows.
  double lower = 0, upper = 0;
};

// `maximumDepth` halvings of each parametric axis at most (hexahedra only).
CertifiedJacobian CertifyElement(const FEMesh& mesh, std::size_t element, int maximumDepth = 6);

// A quality for a repair that must make every element valid inside: `cornerQuality` (the element's
// corner measure, > 0) when det J is certified positive over the element, otherwise the certified
// lower bound of det J / mean det J (<= 0), which grows as the fold inside opens. Cheap for the usual
// element (one set of Bernstein coefficients, all positive). Hexahedra and wedges; any other element
// gets `cornerQuality`.
double CertifiedQuality(const FEMesh& mesh, std::size_t element, double cornerQuality);

struct CertificationSummary
{
  std::size_t solids = 0, valid = 0, invertedCorner = 0, invertedInside = 0, undecided = 0;
  std::size_t NotValid() const { return invertedCorner + invertedInside + undecided; }
  double minimumLower = 0;           // smallest relative lower bound over the solids
  std::vector<std::size_t> notValid; // the elements not certified valid, ascending
  std::vector<double> notValidLower; // their relative lower bounds, same order
};

// Every element, in parallel (threads as mmrep::WorkerThreads); the result does not depend on the
// thread count.
CertificationSummary CertifyMesh(const FEMesh& mesh, int maximumDepth = 6);

} // namespace mmrep::quality
