// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepElementLocation.h"

#include <vtkHexahedron.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkTetra.h>
#include <vtkWedge.h>

#include <cmath>

namespace mmrep
{

ElementLocation LocateInElement(const FEMesh& mesh, const Element& e, const Point3& p)
{
  vtkNew<vtkHexahedron> hex;
  vtkNew<vtkWedge> wedge;
  vtkNew<vtkTetra> tet;
  vtkCell* cell = e.type == ElementType::Hexahedron ? static_cast<vtkCell*>(hex.Get())
                  : e.type == ElementType::Wedge    ? static_cast<vtkCell*>(wedge.Get())
                                                    : static_cast<vtkCell*>(tet.Get());
  const int n = NodeCount(e.type);
  for (int k = 0; k < n; ++k)
  {
    cell->GetPoints()->SetPoint(k, mesh.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])].data());
    cell->GetPointIds()->SetId(k, k);
  }
  double x[3] = {p.x(), p.y(), p.z()}, closest[3], dist2 = 0, weights[8];
  int subId = 0;
  ElementLocation hit;
  const int status = cell->EvaluatePosition(x, closest, subId, hit.pcoords.data(), dist2, weights);
  if (status < 0)
    return hit;
  hit.valid = true;
  hit.inside = status == 1;
  hit.distance = hit.inside ? 0.0 : std::sqrt(dist2);
  if (!hit.inside)
  {
    // Weights of the closest point, not of the (extrapolated) outside point.
    double cp[3], pc[3];
    cell->EvaluatePosition(closest, cp, subId, pc, dist2, weights);
  }
  hit.weights.assign(weights, weights + n);
  return hit;
}

} // namespace mmrep
