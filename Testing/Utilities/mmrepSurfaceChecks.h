// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Test helper: topology checks of triangle surfaces with VTK's own filters (independent of ours).
#pragma once

#include <vtkFeatureEdges.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>

namespace mmrep::testing
{

// Number of connected pieces.
inline int SurfacePieces(vtkPolyData* s)
{
  vtkNew<vtkPolyDataConnectivityFilter> c;
  c->SetInputData(s);
  c->SetExtractionModeToAllRegions();
  c->Update();
  return c->GetNumberOfExtractedRegions();
}

// Edges used by one triangle (holes) or by more than two (non-manifold): 0 for a closed 2-manifold.
inline vtkIdType OpenOrNonManifoldEdges(vtkPolyData* s)
{
  vtkNew<vtkFeatureEdges> e;
  e->SetInputData(s);
  e->BoundaryEdgesOn();
  e->NonManifoldEdgesOn();
  e->FeatureEdgesOff();
  e->ManifoldEdgesOff();
  e->Update();
  return e->GetOutput()->GetNumberOfCells();
}

} // namespace mmrep::testing
