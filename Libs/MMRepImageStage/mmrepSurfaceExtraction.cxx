// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepSurfaceExtraction.h"

#include "itkMarchingCubesImageToMeshFilter.h"
#include "mmrepBridge.h"

#include <vtkPolyDataConnectivityFilter.h>
#include <vtkQuadricDecimation.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include <stdexcept>

namespace mmrep
{

vtkSmartPointer<vtkPolyData> ExtractSurface(const CTImage* image, double isoValue, const SurfaceExtractionOptions& o)
{
  using MC = itk::MarchingCubesImageToMeshFilter<CTImage, SurfaceMesh>;
  auto mc = MC::New();
  mc->SetInput(image);
  mc->SetIsoValue(isoValue);
  mc->SetPadBoundary(o.closeAtBorder);
  mc->Update();
  vtkSmartPointer<vtkPolyData> surface = ITKMeshToPolyData(mc->GetOutput());
  if (surface->GetNumberOfPolys() == 0)
    throw std::runtime_error("empty surface at iso-value " + std::to_string(isoValue));

  if (o.largestPieceOnly)
  {
    vtkNew<vtkPolyDataConnectivityFilter> largest;
    largest->SetInputData(surface);
    largest->SetExtractionModeToLargestRegion();
    largest->Update();
    surface = largest->GetOutput();
  }
  if (o.smoothingIterations > 0)
  {
    vtkNew<vtkWindowedSincPolyDataFilter> smooth;
    smooth->SetInputData(surface);
    smooth->SetNumberOfIterations(o.smoothingIterations);
    smooth->SetPassBand(o.smoothingPassBand);
    smooth->NormalizeCoordinatesOn();
    smooth->BoundarySmoothingOff();
    smooth->FeatureEdgeSmoothingOff();
    smooth->NonManifoldSmoothingOn();
    smooth->Update();
    surface = smooth->GetOutput();
  }
  const auto vertices = static_cast<std::size_t>(surface->GetNumberOfPoints());
  if (o.targetVertexCount > 0 && o.targetVertexCount < vertices)
  {
    vtkNew<vtkQuadricDecimation> decimate;
    decimate->SetInputData(surface);
    decimate->SetTargetReduction(1.0 - static_cast<double>(o.targetVertexCount) / vertices);
    decimate->VolumePreservationOn();
    decimate->Update();
    surface = decimate->GetOutput();
  }
  return surface;
}

} // namespace mmrep
