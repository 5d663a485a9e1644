// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Distance-map section of the image-stage benchmark: our Saito–Toriwaki EDT against
// itk::SignedMaurerDistanceMapImageFilter, itk::DanielssonDistanceMapImageFilter and
// vtkImageEuclideanDistance on the skin and bone masks of the CT, with 2 threads where the tool threads.
// Ratios < 1 mean ours is faster; "cpu" columns are process CPU time (all threads), robust to other load.
#include "mmrepBenchmarks.h"

#include "itkSaitoToriwakiDistanceMapImageFilter.h"

#include <itkBinaryThresholdImageFilter.h>
#include <itkDanielssonDistanceMapImageFilter.h>
#include <itkImageFileReader.h>
#include <itkMultiThreaderBase.h>
#include <itkSignedMaurerDistanceMapImageFilter.h>

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkImageEuclideanDistance.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <string>
#include <vector>

namespace mmrep::bench
{
namespace
{
using CTImage = itk::Image<short, 3>;
using MaskImage = itk::Image<unsigned char, 3>;
using DistanceImage = itk::Image<float, 3>;

constexpr unsigned int kThreads = 2;

struct Timing
{
  double wall = std::numeric_limits<double>::infinity(); // best wall time, seconds
  double cpu = std::numeric_limits<double>::infinity();  // best process CPU time (all threads), seconds
};

// Best times of `repeats` runs of `run` (which must redo the whole computation). CPU time is shown too
// because wall time is unreliable when other jobs share the cores.
Timing BestSeconds(int repeats, const std::function<void()>& run)
{
  Timing best;
  for (int i = 0; i < std::max(repeats, 1); ++i)
  {
    const std::clock_t cpuStart = std::clock();
    const auto start = std::chrono::steady_clock::now();
    run();
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    best.wall = std::min(best.wall, elapsed.count());
    best.cpu = std::min(best.cpu, static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC);
  }
  return best;
}

DistanceImage::Pointer RunOurs(const MaskImage* mask, bool signedDistance, bool squared)
{
  auto filter = itk::SaitoToriwakiDistanceMapImageFilter<MaskImage, DistanceImage>::New();
  filter->SetInput(mask);
  filter->SetSignedDistance(signedDistance);
  filter->SetSquaredDistance(squared);
  filter->SetNumberOfWorkUnits(kThreads);
  filter->Update();
  return filter->GetOutput();
}

DistanceImage::Pointer RunMaurer(const MaskImage* mask)
{
  auto filter = itk::SignedMaurerDistanceMapImageFilter<MaskImage, DistanceImage>::New();
  filter->SetInput(mask);
  filter->SetUseImageSpacing(true);
  filter->SetSquaredDistance(false);
  filter->SetNumberOfWorkUnits(kThreads);
  filter->Update();
  return filter->GetOutput();
}

DistanceImage::Pointer RunDanielsson(const MaskImage* mask)
{
  auto filter = itk::DanielssonDistanceMapImageFilter<MaskImage, DistanceImage>::New();
  filter->SetInput(mask);
  filter->SetInputIsBinary(true);
  filter->SetUseImageSpacing(true);
  filter->SetNumberOfWorkUnits(kThreads); // not used: Danielsson runs in one thread
  filter->Update();
  return filter->GetOutput();
}

// VTK measures the distance to the zero voxels, so foreground becomes 0 and background 1.
vtkSmartPointer<vtkImageData> ToVTKSites(const MaskImage* mask)
{
  const auto size = mask->GetBufferedRegion().GetSize();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(static_cast<int>(size[0]), static_cast<int>(size[1]), static_cast<int>(size[2]));
  image->SetSpacing(mask->GetSpacing()[0], mask->GetSpacing()[1], mask->GetSpacing()[2]);
  image->SetOrigin(mask->GetOrigin()[0], mask->GetOrigin()[1], mask->GetOrigin()[2]);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  const unsigned char* in = mask->GetBufferPointer();
  const size_t n = mask->GetBufferedRegion().GetNumberOfPixels();
  for (size_t i = 0; i < n; ++i)
  {
    out[i] = in[i] != 0 ? 0 : 1;
  }
  return image;
}

vtkSmartPointer<vtkImageData> RunVTK(vtkImageData* sites)
{
  vtkNew<vtkImageEuclideanDistance> filter;
  filter->SetInputData(sites);
  filter->ConsiderAnisotropyOn();
  filter->InitializeOn();
  filter->SetAlgorithmToSaitoCached();
  filter->Update();
  vtkSmartPointer<vtkImageData> out = filter->GetOutput();
  return out;
}

// max |a - b| over voxels, after mapping each side by its own function.
template <typename A, typename B> double MaxDifference(size_t n, A a, B b)
{
  double worst = 0;
  for (size_t i = 0; i < n; ++i)
  {
    worst = std::max(worst, std::abs(a(i) - b(i)));
  }
  return worst;
}

struct Row
{
  std::string name;
  Timing time;
  Timing ours; // matching "ours" row; wall 0 for our own rows
  int runs;
  unsigned threads;
};

void PrintTable(const std::vector<Row>& rows, size_t voxels, std::ostream& out)
{
  out << "  " << std::left << std::setw(46) << "implementation" << std::right << std::setw(10) << "seconds"
      << std::setw(10) << "Mvox/s" << std::setw(13) << "ours/theirs" << std::setw(9) << "threads" << std::setw(6)
      << "runs" << std::setw(10) << "cpu s" << std::setw(12) << "cpu ratio"
      << "\n";
  for (const Row& r : rows)
  {
    out << "  " << std::left << std::setw(46) << r.name << std::right << std::fixed << std::setprecision(4)
        << std::setw(10) << r.time.wall << std::setprecision(1) << std::setw(10)
        << static_cast<double>(voxels) / r.time.wall * 1e-6;
    const bool theirs = r.ours.wall > 0;
    out << std::setprecision(3) << std::setw(13);
    if (theirs)
    {
      out << r.ours.wall / r.time.wall;
    }
    else
    {
      out << "-";
    }
    out << std::setw(9) << r.threads << std::setw(6) << r.runs << std::setprecision(4) << std::setw(10) << r.time.cpu
        << std::setprecision(3) << std::setw(12);
    if (theirs)
    {
      out << r.ours.cpu / r.time.cpu;
    }
    else
    {
      out << "-";
    }
    out << "\n";
  }
  out.unsetf(std::ios::floatfield);
}

void BenchmarkMask(const std::string& label, const MaskImage* mask, int repeats, std::ostream& out)
{
  const size_t n = mask->GetBufferedRegion().GetNumberOfPixels();
  const size_t foreground =
    std::count_if(mask->GetBufferPointer(), mask->GetBufferPointer() + n, [](unsigned char v) { return v != 0; });
  out << label << ": " << std::fixed << std::setprecision(2) << static_cast<double>(n) * 1e-6 << " Mvoxels, "
      << std::setprecision(1) << 100.0 * static_cast<double>(foreground) / static_cast<double>(n) << "% foreground\n";
  out.unsetf(std::ios::floatfield);

  DistanceImage::Pointer oursSigned, oursUnsigned, oursSquared, maurer, danielsson;
  vtkSmartPointer<vtkImageData> vtk;
  const auto sites = ToVTKSites(mask);

  const Timing tSigned = BestSeconds(repeats, [&] { oursSigned = RunOurs(mask, true, false); });
  const Timing tUnsigned = BestSeconds(repeats, [&] { oursUnsigned = RunOurs(mask, false, false); });
  const Timing tSquared = BestSeconds(repeats, [&] { oursSquared = RunOurs(mask, false, true); });
  const Timing tMaurer = BestSeconds(repeats, [&] { maurer = RunMaurer(mask); });
  const Timing tDanielsson = BestSeconds(1, [&] { danielsson = RunDanielsson(mask); });
  const Timing tVTK = BestSeconds(repeats, [&] { vtk = RunVTK(sites); });

  const Timing none{0, 0};
  PrintTable({{"ours SaitoToriwaki signed", tSigned, none, repeats, kThreads},
              {"ours SaitoToriwaki unsigned", tUnsigned, none, repeats, kThreads},
              {"ours SaitoToriwaki unsigned squared", tSquared, none, repeats, kThreads},
              {"itk::SignedMaurerDistanceMap (vs ours signed)", tMaurer, tSigned, repeats, kThreads},
              {"itk::DanielssonDistanceMap (vs ours unsigned)", tDanielsson, tUnsigned, 1, 1},
              {"vtkImageEuclideanDistance (vs ours squared)", tVTK, tSquared, repeats, 1}},
             n, out);

  const float* s = oursSigned->GetBufferPointer();
  const float* u = oursUnsigned->GetBufferPointer();
  const float* m = maurer->GetBufferPointer();
  const float* dn = danielsson->GetBufferPointer();
  vtkDataArray* v = vtk->GetPointData()->GetScalars();
  out << "  max |ours signed - SignedMaurer|        = "
      << MaxDifference(
           n, [&](size_t i) { return double(s[i]); }, [&](size_t i) { return double(m[i]); })
      << " mm\n";
  out << "  max |ours unsigned - max(SignedMaurer,0)| = "
      << MaxDifference(
           n, [&](size_t i) { return double(u[i]); }, [&](size_t i) { return std::max(0.0, double(m[i])); })
      << " mm\n";
  out << "  max |ours unsigned - sqrt(VTK)|         = "
      << MaxDifference(
           n, [&](size_t i) { return double(u[i]); }, [&](size_t i) { return std::sqrt(v->GetTuple1(i)); })
      << " mm\n";
  out << "  max |ours unsigned - Danielsson|        = "
      << MaxDifference(
           n, [&](size_t i) { return double(u[i]); }, [&](size_t i) { return double(dn[i]); })
      << " mm (Danielsson is approximate)\n";
}

MaskImage::Pointer Threshold(const CTImage* ct, short lower)
{
  auto filter = itk::BinaryThresholdImageFilter<CTImage, MaskImage>::New();
  filter->SetInput(ct);
  filter->SetLowerThreshold(lower);
  filter->SetInsideValue(1);
  filter->SetOutsideValue(0);
  filter->Update();
  return filter->GetOutput();
}
} // namespace

void RunDistanceMapBenchmark(const std::string& ctPath, int repeats, std::ostream& out)
{
  itk::MultiThreaderBase::SetGlobalDefaultNumberOfThreads(kThreads);
  auto reader = itk::ImageFileReader<CTImage>::New();
  reader->SetFileName(ctPath);
  reader->Update(); // throws itk::ExceptionObject (a std::exception) naming the file when unreadable
  const CTImage* ct = reader->GetOutput();

  out << "== Euclidean distance maps (best of " << repeats << "; Danielsson once) ==\n";
  BenchmarkMask("skin mask (CT >= 500)", Threshold(ct, 500), repeats, out);
  out << "\n";
  BenchmarkMask("bone mask (CT >= 1300)", Threshold(ct, 1300), repeats, out);
}
} // namespace mmrep::bench
