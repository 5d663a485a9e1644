// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Decimation benchmark (issue 17 item 4), run on demand: build/bin/DecimationBenchmark [ct.nrrd] [vertices]
// The full skin of a CT (as SkinSkullSurfaces extracts it) decimated to `vertices` by VTK's
// vtkQuadricDecimation (what SkinSkullSurfaces uses) and by OpenMesh's Decimater with ModQuadric and an
// Observer (progress, abort), the OpenMesh run including the conversions through Libs/MMRepBridge. Prints
// CPU time and the distances between the decimated and the full surface both ways (VTK's cell locator).
#include "mmrepBridge.h"
#include "mmrepCTThresholds.h"
#include "mmrepHeadSegmentation.h"
#include "mmrepImageIO.h"
#include "mmrepSurfaceExtraction.h"

#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Decimater/Observer.hh>

#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkQuadricDecimation.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>

namespace
{
// Process CPU time: both decimations run on one thread, and CPU time does not depend on the machine's load.
using Clock = std::clock_t;

double Seconds(Clock start)
{
  return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
}

struct Distances
{
  double mean = 0, max = 0;
};

// Distance from every point of `from` to the surface `to`.
Distances PointsToSurface(vtkPolyData* from, vtkPolyData* to)
{
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  Distances d;
  const vtkIdType n = from->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], q[3], d2;
    vtkIdType id;
    int sub;
    from->GetPoint(i, p);
    locator->FindClosestPoint(p, q, cell, id, sub, d2);
    const double e = std::sqrt(d2);
    d.mean += e / static_cast<double>(n);
    d.max = std::max(d.max, e);
  }
  return d;
}

// Progress every `interval` collapses; aborts when the deadline passes (never in this benchmark).
class ProgressObserver : public OpenMesh::Decimater::Observer
{
public:
  explicit ProgressObserver(std::size_t interval) : Observer(interval) {}
  void notify(std::size_t step) override { steps_ = step; }
  bool abort() const override { return false; }
  std::size_t steps_ = 0;
};

void Print(const std::string& name, double seconds, vtkPolyData* decimated, vtkPolyData* full)
{
  const Distances a = PointsToSurface(decimated, full);
  const Distances b = PointsToSurface(full, decimated);
  std::cout << name << ": " << seconds << " s CPU, " << decimated->GetNumberOfPoints() << " vertices, "
            << decimated->GetNumberOfPolys() << " triangles; decimated -> full " << a.mean << " mm mean, " << a.max
            << " mm max; full -> decimated " << b.mean << " mm mean, " << b.max << " mm max\n";
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string path = argc > 1 ? argv[1] : std::string(MMREP_SAMPLE_DATA) + "/cthead.nrrd";
  const std::size_t target = argc > 2 ? static_cast<std::size_t>(std::atol(argv[2])) : 30000;
  try
  {
    const auto ct = mmrep::ReadCTImage(path);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto t = mmrep::ChooseThresholds(ct, mmrep::ThresholdMode::Automatic, nan, nan);
    mmrep::HeadSegmentationOptions seg;
    seg.skinThreshold = t.skin;
    seg.boneThreshold = t.bone;
    const auto head = mmrep::SegmentHead(ct, seg);
    const auto full = mmrep::ExtractSurface(mmrep::MaskedIntensities(ct, head.skin, t.skin), t.skin, {});
    const auto n = static_cast<std::size_t>(full->GetNumberOfPoints());
    std::cout << "skin of " << path << ": " << n << " vertices, " << full->GetNumberOfPolys() << " triangles; target "
              << target << " vertices\n";

    auto start = std::clock();
    vtkNew<vtkQuadricDecimation> vtk;
    vtk->SetInputData(full);
    vtk->SetTargetReduction(1.0 - static_cast<double>(target) / static_cast<double>(n));
    vtk->VolumePreservationOn();
    vtk->Update();
    Print("vtkQuadricDecimation (volume preservation)", Seconds(start), vtk->GetOutput(), full);

    start = std::clock();
    std::size_t skipped = 0;
    mmrep::TriMesh mesh = mmrep::PolyDataToOpenMesh(full, &skipped);
    const double toOpenMesh = Seconds(start);
    using Decimater = OpenMesh::Decimater::DecimaterT<mmrep::TriMesh>;
    using Quadric = OpenMesh::Decimater::ModQuadricT<mmrep::TriMesh>::Handle;
    Decimater decimater(mesh);
    Quadric quadric;
    decimater.add(quadric);
    ProgressObserver observer(10000);
    decimater.set_observer(&observer);
    decimater.initialize();
    decimater.decimate_to(target);
    mesh.garbage_collection();
    const auto om = mmrep::OpenMeshToPolyData(mesh);
    Print("OpenMesh Decimater + ModQuadric (with the VTK <-> OpenMesh copies)", Seconds(start), om, full);
    std::cout << "  of which VTK -> OpenMesh " << toOpenMesh << " s CPU; " << skipped << " non-manifold faces skipped; "
              << observer.steps_ << " collapses notified\n";
  }
  catch (const std::exception& e)
  {
    std::cerr << "DecimationBenchmark: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
