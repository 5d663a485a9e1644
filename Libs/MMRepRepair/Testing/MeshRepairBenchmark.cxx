// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Repair benchmark (not a ctest): success rate over generated tangled shells and time per mesh
// against element count, to check the linear scaling.
// Usage: MeshRepairBenchmark [cases per size = 20] [number of sizes = 4] [maximum noise = 0.18]
#include "mmrepMeshQuality.h"
#include "mmrepMeshRepair.h"
#include "mmrepTangledMeshGenerator.h"

#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char* argv[])
{
  using namespace mmrep;
  const int cases = argc > 1 ? std::atoi(argv[1]) : 20;
  const std::size_t sizeCount = argc > 2 ? static_cast<std::size_t>(std::atoi(argv[2])) : 4;
  const double maximumNoise = argc > 3 ? std::atof(argv[3]) : 0.18; // RandomTangle's default
  std::printf("tangles: noise up to %.2f element sizes, 0-4 folds, warps in half the cases\n", maximumNoise);
  std::setvbuf(stdout, nullptr, _IOLBF, 0); // line by line, also into a pipe
  std::printf("%8s %8s %6s %9s %12s %12s %14s %12s\n", "elements", "cases", "ok", "rate", "bad before", "moved nodes",
              "s per mesh", "us/element");
  // Grids of growing size with the same element shape (columns x rows x 3 layers).
  const std::vector<std::pair<int, int>> sizes{{24, 20}, {48, 40}, {68, 50}, {96, 80}};
  for (std::size_t s = 0; s < sizes.size() && s < sizeCount; ++s)
  {
    const auto [columns, rows] = sizes[s];
    testing::ShellAtlasOptions options;
    options.columns = columns;
    options.rows = rows;
    const testing::ShellAtlas atlas = testing::MakeShellAtlas(options);
    int ok = 0;
    double seconds = 0, bad = 0, moved = 0;
    for (int c = 0; c < cases; ++c)
    {
      const testing::TangleOptions tangle = testing::RandomTangle(static_cast<std::uint32_t>(c + 1), maximumNoise);
      FEMesh mesh = testing::Tangle(atlas, tangle);
      RepairOptions repair;
      repair.skinSurface = atlas.skin;
      repair.skullSurface = atlas.skull;
      repair.hasSymmetryPlane = tangle.symmetric;
      const RepairReport report = RepairMesh(mesh, repair);
      ok += report.success ? 1 : 0;
      seconds += report.seconds;
      bad += static_cast<double>(report.belowThresholdBefore);
      moved += static_cast<double>(report.movedNodes);
      if (std::getenv("MMREP_BENCHMARK_VERBOSE") != nullptr)
        std::printf("   case %d: %s in %.3f s, %zu below before, %zu moved\n", c + 1, report.success ? "ok" : "FAIL",
                    report.seconds, report.belowThresholdBefore, report.movedNodes);
      if (!report.success)
        std::printf("   case %d failed: %zu elements below, worst %g (noise %.2f folds %d warp %.2f sym %d)\n", c + 1,
                    report.failedElements.size(), report.failedValues.empty() ? 0.0 : report.failedValues[0],
                    tangle.noise, tangle.folds, tangle.warp, tangle.symmetric ? 1 : 0);
      if (!report.success && std::getenv("MMREP_BENCHMARK_VERBOSE") != nullptr)
        for (const std::size_t e : report.failedElements)
        {
          std::printf("     element %zu:", e);
          const auto corners = quality::CornerJacobians(mesh, e);
          for (int k = 0; k < 8; ++k)
          {
            const auto g = atlas.grid[mesh.elements[e].nodes[k]];
            std::printf(" (%d,%d,%d|%.2g)", g.x(), g.y(), g.z(), corners[k]);
          }
          std::printf("\n");
        }
    }
    const std::size_t elements = atlas.mesh.elements.size();
    std::printf("%8zu %8d %6d %9.3f %12.1f %12.1f %14.4f %12.3f\n", elements, cases, ok, double(ok) / cases,
                bad / cases, moved / cases, seconds / cases, 1e6 * seconds / cases / double(elements));
  }
  return 0;
}
