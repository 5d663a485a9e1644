// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Image-stage benchmark (issue 3), run on demand: build/bin/ImageStageBenchmark [ct.nrrd] [repeats]
// Times our Saito–Toriwaki EDT and Marching Cubes against the tools a user would otherwise pick,
// on the same data in one run, and prints ratios (ours / theirs).
#include "mmrepBenchmarks.h"

#include <itkMultiThreaderBase.h>

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  const std::string ct = argc > 1 ? argv[1] : std::string(MMREP_SAMPLE_DATA) + "/cthead.nrrd";
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
  std::cout << "MMRep image-stage benchmark on " << ct << "\n"
            << "threads: " << itk::MultiThreaderBase::GetGlobalDefaultNumberOfThreads() << ", repeats: " << repeats
            << " (best time kept)\n\n";
  try
  {
    mmrep::bench::RunDistanceMapBenchmark(ct, repeats, std::cout);
    std::cout << "\n";
    mmrep::bench::RunMarchingCubesBenchmark(ct, repeats, std::cout);
  }
  catch (const std::exception& e)
  {
    std::cerr << "ImageStageBenchmark: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
