// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Repair benchmark on the real atlas (not a ctest): tangles of Resources/Atlas/FaceAtlas.vtu
// (mmrepAtlasTangles.h) repaired against the atlas's skin and skull reference surfaces and its
// mid-sagittal plane. Reports the success rate (0 inverted and min scaled Jacobian >= 0.3), the
// lips accuracy loss, the symmetry error of symmetric cases, the time per mesh, and the time per
// element on lower parts of the atlas (the scaling in element count).
// Usage: AtlasRepairBenchmark [cases = 100] [maximum noise = 0.18] [scaling cases = 10] [atlas folder]
#include "mmrepAtlasTangles.h"
#include "mmrepMeshRepair.h"
#include "mmrepSurfaceDistance.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char* argv[])
{
  using namespace mmrep;
  const int cases = argc > 1 ? std::atoi(argv[1]) : 100;
  const double maximumNoise = argc > 2 ? std::atof(argv[2]) : 0.18;
  const int scalingCases = argc > 3 ? std::atoi(argv[3]) : 10;
  const std::string folder = argc > 4 ? argv[4] : std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas";
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const testing::MeshTangleContext context = testing::LoadTangleContext(
    folder + "/FaceAtlas.vtu", folder + "/FaceAtlasSkin.vtp", folder + "/FaceAtlasSkull.vtp");
  std::printf("atlas: %zu nodes, %zu solid elements, mean edge %.2f mm, symmetric %s\n", context.mesh.nodes.size(),
              context.mesh.SolidElementCount(), context.meanSize, context.partner.empty() ? "no" : "yes");
  std::printf("tangles: noise up to %.2f element sizes, 0-4 folds, warps of 0.5-2 element sizes in half the cases, "
              "symmetric for even seeds\n",
              maximumNoise);

  int ok = 0, symmetricCases = 0;
  double seconds = 0, slowest = 0, lipsLoss = -1e300, symmetry = 0, bad = 0, inverted = 0, minAfter = 1e300;
  for (int k = 0; k < cases; ++k)
  {
    const testing::TangleOptions tangle = testing::RandomTangle(static_cast<std::uint32_t>(k + 1), maximumNoise);
    FEMesh mesh = testing::TangleMesh(context, tangle);
    const SurfaceDistance lipsBefore = MeasureSurfaceDistance(mesh, "lips", context.skin);
    const double symmetryBefore = tangle.symmetric ? testing::SymmetryError(mesh, context) : 0.0;
    const RepairReport report = RepairMesh(mesh, testing::TangleRepairOptions(context));
    const SurfaceDistance lipsAfter = MeasureSurfaceDistance(mesh, "lips", context.skin);
    ok += report.success ? 1 : 0;
    seconds += report.seconds;
    slowest = std::max(slowest, report.seconds);
    bad += static_cast<double>(report.belowThresholdBefore);
    inverted += static_cast<double>(report.invertedBefore);
    minAfter = std::min(minAfter, report.minScaledJacobianAfter);
    lipsLoss = std::max(lipsLoss, lipsAfter.max - lipsBefore.max);
    if (tangle.symmetric)
    {
      ++symmetricCases;
      const double after = testing::SymmetryError(mesh, context);
      symmetry = std::max(symmetry, after);
      std::printf("   case %d (symmetric): symmetry error %.1e before, %.1e after (relative); mirror pairs %s\n", k + 1,
                  symmetryBefore, after, report.symmetricPairs ? "moved together" : "not detected");
    }
    if (!report.success || std::getenv("MMREP_BENCHMARK_VERBOSE") != nullptr)
      std::printf("   case %d: %s in %.3f s; before: %zu inverted, %zu below 0.3, min %.3f; after: min %.3f, "
                  "%zu below (noise %.2f folds %d warp %.2f sym %d)\n",
                  k + 1, report.success ? "ok" : "FAILED", report.seconds, report.invertedBefore,
                  report.belowThresholdBefore, report.minScaledJacobianBefore, report.minScaledJacobianAfter,
                  report.failedElements.size(), tangle.noise, tangle.folds, tangle.warp, tangle.symmetric ? 1 : 0);
    if (!report.success && std::getenv("MMREP_BENCHMARK_VERBOSE") != nullptr)
      for (std::size_t f = 0; f < report.failedElements.size() && f < 8; ++f)
      {
        const Element& e = mesh.elements[report.failedElements[f]];
        std::printf("     element %zu (%.3f) nodes", report.failedElements[f], report.failedValues[f]);
        for (int k = 0; k < 8; ++k)
          std::printf(" %d(d%.2f%s)", e.nodes[k], context.depth[e.nodes[k]],
                      context.partner.empty() || context.partner[e.nodes[k]] != e.nodes[k] ? "" : ",mid");
        std::printf("\n");
      }
  }
  std::printf("success %d / %d = %.1f %%; before repair (mean per case): %.1f inverted, %.1f below 0.3; "
              "worst min scaled Jacobian after %.3f\n",
              ok, cases, 100.0 * ok / cases, inverted / cases, bad / cases, minAfter);
  std::printf("lips: largest increase of the max distance to the skin %.2e mm; symmetry error (%d symmetric cases) "
              "%.1e relative\n",
              lipsLoss, symmetricCases, symmetry);
  std::printf("time: mean %.3f s, slowest %.3f s per atlas (sequential)\n", seconds / cases, slowest);

  // Scaling: the lower 25 %, 50 %, 75 % and all of the atlas, same tangles.
  std::printf("%9s %8s %6s %12s %12s\n", "fraction", "elements", "ok", "s per mesh", "us/element");
  for (const double fraction : {0.25, 0.5, 0.75, 1.0})
  {
    const testing::MeshTangleContext part =
      testing::MakeTangleContext(testing::CropMesh(context.mesh, context.plane, fraction), context.skin, context.skull);
    int partOk = 0;
    double partSeconds = 0;
    for (int k = 0; k < scalingCases; ++k)
    {
      FEMesh mesh = testing::TangleMesh(part, testing::RandomTangle(static_cast<std::uint32_t>(k + 1), maximumNoise));
      const RepairReport report = RepairMesh(mesh, testing::TangleRepairOptions(part));
      partOk += report.success ? 1 : 0;
      partSeconds += report.seconds;
    }
    const std::size_t elements = part.mesh.SolidElementCount();
    std::printf("%9.2f %8zu %6d %12.3f %12.2f\n", fraction, elements, partOk, partSeconds / scalingCases,
                1e6 * partSeconds / scalingCases / double(elements));
  }
  return 0;
}
