// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Marching Cubes section of the image-stage benchmark: itk::MarchingCubesImageToMeshFilter against
// vtkFlyingEdges3D, vtkMarchingCubes and itk::BinaryMask3DMeshSource at the skin and bone iso-values of the CT.
// Every implementation gets the same voxels (VTK reads the ITK buffer without copying) and 2 threads; the time is
// that of Update() only, best of `repeats` (BinaryMask3DMeshSource: once, it is slow), with a fresh filter each
// time so that releasing the previous output is not timed.
#include "mmrepBenchmarks.h"

#include "itkMarchingCubesImageToMeshFilter.h"

#include <itkBinaryMask3DMeshSource.h>
#include <itkBinaryThresholdImageFilter.h>
#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkMesh.h>
#include <itkMultiThreaderBase.h>

#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkMarchingCubes.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkShortArray.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace mmrep::bench
{
namespace
{
using ImageType = itk::Image<short, 3>;
using MaskType = itk::Image<unsigned char, 3>;
using MeshType = itk::Mesh<float, 3>;

constexpr int Threads = 2;

struct Row
{
  std::string name;
  double seconds;
  long long points;
  long long triangles;
  int threads; // threads the implementation can use (vtkMarchingCubes and BinaryMask3DMeshSource are serial)
};

// One implementation: `run` executes it once, sets the wall time of the timed part and returns
// {points, triangles} of its result.
struct Candidate
{
  std::string name;
  int threads; // threads it can use
  int repeats;
  std::function<std::pair<long long, long long>(double&)> run;
};

// Best wall time of each candidate. Repeats are interleaved (round r runs every candidate once) so that changes in
// machine load affect all candidates alike.
std::vector<Row> TimeInterleaved(const std::vector<Candidate>& candidates)
{
  std::vector<Row> rows;
  int rounds = 0;
  for (const Candidate& c : candidates)
  {
    rows.push_back(Row{c.name, std::numeric_limits<double>::infinity(), 0, 0, c.threads});
    rounds = std::max(rounds, c.repeats);
  }
  for (int r = 0; r < rounds; ++r)
  {
    for (std::size_t n = 0; n < candidates.size(); ++n)
    {
      if (r >= candidates[n].repeats)
      {
        continue;
      }
      double seconds = 0.0;
      const auto counts = candidates[n].run(seconds);
      rows[n].seconds = std::min(rows[n].seconds, seconds);
      rows[n].points = counts.first;
      rows[n].triangles = counts.second;
    }
  }
  return rows;
}

template <typename TFunction> double Seconds(TFunction&& f)
{
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace

void RunMarchingCubesBenchmark(const std::string& ctPath, int repeats, std::ostream& out)
{
  repeats = std::max(repeats, 1);
  auto reader = itk::ImageFileReader<ImageType>::New();
  reader->SetFileName(ctPath);
  reader->Update();
  const ImageType::Pointer image = reader->GetOutput();
  const auto size = image->GetLargestPossibleRegion().GetSize();
  const double voxels = double(size[0]) * double(size[1]) * double(size[2]);

  // VTK view of the same buffer (the sample CTs have an identity direction).
  vtkNew<vtkImageData> vtkImage;
  vtkImage->SetDimensions(int(size[0]), int(size[1]), int(size[2]));
  vtkImage->SetSpacing(image->GetSpacing()[0], image->GetSpacing()[1], image->GetSpacing()[2]);
  vtkImage->SetOrigin(image->GetOrigin()[0], image->GetOrigin()[1], image->GetOrigin()[2]);
  vtkNew<vtkShortArray> scalars;
  scalars->SetArray(image->GetBufferPointer(), vtkIdType(voxels), 1); // 1: VTK must not free ITK's buffer
  vtkImage->GetPointData()->SetScalars(scalars);

  vtkSMPTools::Initialize(Threads);

  out << "Marching Cubes: " << size[0] << "x" << size[1] << "x" << size[2] << " voxels, " << Threads
      << " threads, best of " << repeats << " (itk::BinaryMask3DMeshSource: 1 run)\n";
  const struct
  {
    const char* label;
    double iso;
  } levels[] = {{"skin", 500.0}, {"bone", 1300.0}};

  for (const auto& level : levels)
  {
    // BinaryMask3DMeshSource meshes a binary mask; the thresholding is not timed.
    auto threshold = itk::BinaryThresholdImageFilter<ImageType, MaskType>::New();
    threshold->SetInput(image);
    threshold->SetLowerThreshold(static_cast<short>(std::ceil(level.iso)));
    threshold->SetInsideValue(1);
    threshold->SetOutsideValue(0);
    threshold->Update();

    std::vector<Candidate> candidates;
    candidates.push_back({"ours (itk::MarchingCubesImageToMeshFilter)", Threads, repeats, [&](double& seconds) {
                            auto filter = itk::MarchingCubesImageToMeshFilter<ImageType, MeshType>::New();
                            filter->SetInput(image);
                            filter->SetIsoValue(level.iso);
                            filter->SetNumberOfWorkUnits(Threads);
                            seconds = Seconds([&] { filter->Update(); });
                            return std::make_pair((long long)filter->GetOutput()->GetNumberOfPoints(),
                                                  (long long)filter->GetOutput()->GetNumberOfCells());
                          }});
    candidates.push_back({"ours, CompactCells off (itk::TriangleCell)", Threads, repeats, [&](double& seconds) {
                            auto filter = itk::MarchingCubesImageToMeshFilter<ImageType, MeshType>::New();
                            filter->SetInput(image);
                            filter->SetIsoValue(level.iso);
                            filter->SetCompactCells(false);
                            filter->SetNumberOfWorkUnits(Threads);
                            seconds = Seconds([&] { filter->Update(); });
                            return std::make_pair((long long)filter->GetOutput()->GetNumberOfPoints(),
                                                  (long long)filter->GetOutput()->GetNumberOfCells());
                          }});
    candidates.push_back({"vtkFlyingEdges3D", Threads, repeats, [&](double& seconds) {
                            vtkNew<vtkFlyingEdges3D> fe;
                            fe->SetInputData(vtkImage);
                            fe->SetValue(0, level.iso);
                            fe->ComputeNormalsOff();
                            fe->ComputeGradientsOff();
                            fe->ComputeScalarsOff();
                            seconds = Seconds([&] { fe->Update(); });
                            return std::make_pair((long long)fe->GetOutput()->GetNumberOfPoints(),
                                                  (long long)fe->GetOutput()->GetNumberOfPolys());
                          }});
    candidates.push_back({"vtkMarchingCubes", 1, repeats, [&](double& seconds) {
                            vtkNew<vtkMarchingCubes> mc;
                            mc->SetInputData(vtkImage);
                            mc->SetValue(0, level.iso);
                            mc->ComputeNormalsOff();
                            mc->ComputeGradientsOff();
                            mc->ComputeScalarsOff();
                            seconds = Seconds([&] { mc->Update(); });
                            return std::make_pair((long long)mc->GetOutput()->GetNumberOfPoints(),
                                                  (long long)mc->GetOutput()->GetNumberOfPolys());
                          }});
    candidates.push_back({"itk::BinaryMask3DMeshSource (mask >= iso)", 1, 1, [&](double& seconds) {
                            auto source = itk::BinaryMask3DMeshSource<MaskType, MeshType>::New();
                            source->SetInput(threshold->GetOutput());
                            source->SetObjectValue(1);
                            seconds = Seconds([&] { source->Update(); });
                            return std::make_pair((long long)source->GetOutput()->GetNumberOfPoints(),
                                                  (long long)source->GetOutput()->GetNumberOfCells());
                          }});
    const std::vector<Row> rows = TimeInterleaved(candidates);

    char line[256];
    std::snprintf(line, sizeof(line), "\n%s (iso %.1f)\n", level.label, level.iso);
    out << line;
    std::snprintf(line, sizeof(line), "  %-44s %10s %10s %12s %10s %10s %8s\n", "implementation", "seconds", "Mvoxel/s",
                  "ours/theirs", "points", "triangles", "threads");
    out << line;
    const double ours = rows.front().seconds;
    for (const Row& row : rows)
    {
      std::snprintf(line, sizeof(line), "  %-44s %10.4f %10.1f %12.3f %10lld %10lld %8d\n", row.name.c_str(),
                    row.seconds, voxels / row.seconds / 1e6, ours / row.seconds, row.points, row.triangles,
                    row.threads);
      out << line;
    }
  }
}
} // namespace mmrep::bench
