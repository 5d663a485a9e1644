// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Repair benchmark on the real atlas (not a ctest): tangles of Resources/Atlas/FaceAtlas.vtu
// (mmrepAtlasTangles.h) repaired against the atlas's skin and skull reference surfaces and its
// mid-sagittal plane, node by node alone (the repair before issue 28) and with the global untangling,
// relaxation rounds and the plane-side rule (side by side).
// Reports the success rate (0 inverted and min scaled Jacobian >= 0.3), the cases also certified valid
// inside every element (mmrepCertifiedJacobian.h) and the smallest certified det J / mean det J, the lips accuracy loss, the
// symmetry error of symmetric cases, the time per mesh, and the time per element on lower parts of
// the atlas (the scaling in element count).
// Usage: AtlasRepairBenchmark [cases = 100] [maximum noise = 0.18] [scaling cases = 10] [atlas folder]
#include "mmrepAtlasTangles.h"
#include "mmrepMeshRepair.h"
#include "mmrepSurfaceDistance.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
using namespace mmrep;

struct Figures
{
  int ok = 0, certified = 0;
  double certifiedMin = 1e300;
  double seconds = 0, slowest = 0, lipsLoss = -1e300, symmetry = 0, minAfter = 1e300;
};

// Repairs tangles 1..cases with the global untangling stage on or off; prints the failures.
Figures RunCases(const testing::MeshTangleContext& context, int cases, double maximumNoise, bool global)
{
  Figures f;
  double bad = 0, inverted = 0;
  for (int k = 0; k < cases; ++k)
  {
    const testing::TangleOptions tangle = testing::RandomTangle(static_cast<std::uint32_t>(k + 1), maximumNoise);
    FEMesh mesh = testing::TangleMesh(context, tangle);
    const SurfaceDistance lipsBefore = MeasureSurfaceDistance(mesh, "lips", context.skin);
    RepairOptions options = testing::TangleRepairOptions(context);
    options.globalUntangling = global; // the repair before issue 28: node by node alone,
    options.keepPlaneSides = global;   // without the plane-side rule,
    options.certifyInside = global;    // success at the corners only
    const RepairReport report = RepairMesh(mesh, options);
    const SurfaceDistance lipsAfter = MeasureSurfaceDistance(mesh, "lips", context.skin);
    f.ok += report.success ? 1 : 0;
    f.certified += report.success && report.notCertifiedAfter == 0 ? 1 : 0;
    f.certifiedMin = std::min(f.certifiedMin, report.certifiedMinimumAfter);
    f.seconds += report.seconds;
    f.slowest = std::max(f.slowest, report.seconds);
    bad += static_cast<double>(report.belowThresholdBefore);
    inverted += static_cast<double>(report.invertedBefore);
    f.minAfter = std::min(f.minAfter, report.minScaledJacobianAfter);
    f.lipsLoss = std::max(f.lipsLoss, lipsAfter.max - lipsBefore.max);
    if (tangle.symmetric)
      f.symmetry = std::max(f.symmetry, testing::SymmetryError(mesh, context));
    if (!report.success || std::getenv("MMREP_BENCHMARK_VERBOSE") != nullptr)
      std::printf(
        "   case %d: %s in %.3f s (untangling %.3f s, %d steps); before: %zu inverted, %zu below 0.3, min %.3f; after: min %.3f, "
        "%zu below, %zu not certified (noise %.2f folds %d warp %.2f sym %d)\n",
        k + 1, report.success ? "ok" : "FAILED", report.seconds, report.untanglingSeconds, report.untanglingSteps,
        report.invertedBefore, report.belowThresholdBefore, report.minScaledJacobianBefore,
        report.minScaledJacobianAfter, report.failedElements.size(), report.notCertifiedAfter, tangle.noise,
        tangle.folds, tangle.warp, tangle.symmetric ? 1 : 0);
  }
  std::printf("%s: before repair (mean per case) %.1f inverted, %.1f below 0.3\n",
              global ? "global + node by node" : "node by node", inverted / cases, bad / cases);
  return f;
}
} // namespace

int main(int argc, char* argv[])
{
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

  std::printf("%-22s %9s %10s %10s %11s %11s %10s %12s %14s\n", "repair", "success", "certified", "mean s", "slowest s",
              "worst min", "cert. min", "lips loss mm", "symmetry (rel)");
  for (const bool global : {false, true})
  {
    const Figures f = RunCases(context, cases, maximumNoise, global);
    std::printf("%-22s %8.1f%% %9.1f%% %10.3f %11.3f %11.3f %10.3f %12.2e %14.1e\n",
                global ? "global + node by node" : "node by node", 100.0 * f.ok / cases, 100.0 * f.certified / cases,
                f.seconds / cases, f.slowest, f.minAfter, f.certifiedMin, f.lipsLoss, f.symmetry);
  }

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
