// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// SpeakerRepairBenchmark: the repair on tangles that a registration really makes. R and Q are run
// with the mesh guard off (element quality floor -1) on the sample CTs with their control points
// (Resources/SampleData: the bundled CT, headsq, the Visible Human Female CT); the model after Q∘R
// is then repaired as the pipeline repairs it (its sweeps, the subject's surfaces cropped around
// the model, the symmetry plane), node by node alone and with the global untangling first, side by
// side (the node-by-node repair before issue 28, and today's): success (0 inverted, every element at scaled Jacobian 0.3), the corner minimum, elements not
// certified valid inside (mmrepCertifiedJacobian.h) and the certified minimum, the skin and skull
// nodes' mean distance to the subject's surfaces before and after, the time.
//
//   SpeakerRepairBenchmark [cthead,headsq,vhf]
#include "mmrepFEMeshIO.h"
#include "mmrepFaceModelPipeline.h"
#include "mmrepImageIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepSurfaceDistance.h"

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace mmrep;

const std::string kSample = MMREP_SAMPLE_DATA;

struct Speaker
{
  std::string name, ct, points;
};

void PrintRepair(const char* name, const FEMesh& tangled, const RepairOptions& options, const FaceModelResult& r)
{
  FEMesh mesh = tangled;
  const RepairReport report = RepairMesh(mesh, options);
  const SurfaceDistance skin = MeasureSurfaceDistance(mesh, "skin", r.skin);
  const SurfaceDistance skull = MeasureSurfaceDistance(mesh, "skull", r.skull);
  std::printf("  %-22s %7s %9.3f %8zu %8zu %9zu %10.3f %8.3f %8.3f %8.1f\n", name, report.success ? "yes" : "no",
              report.minScaledJacobianAfter, report.invertedAfter, report.belowThresholdAfter, report.notCertifiedAfter,
              report.certifiedMinimumAfter, skin.mean, skull.mean, report.seconds);
}
} // namespace

int main(int argc, char* argv[])
{
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const std::vector<Speaker> all = {
    {"cthead", kSample + "/cthead.nrrd", kSample + "/cthead.ControlPoints.mrk.json"},
    {"headsq", kSample + "/headsq.nrrd", kSample + "/headsq.ControlPoints.mrk.json"},
    {"vhf", kSample + "/vhf_head_ct.nrrd", kSample + "/vhf_head_ct.ControlPoints.mrk.json"}};
  const std::string wanted = argc > 1 ? "," + std::string(argv[1]) + "," : ",cthead,headsq,vhf,";
  const FEMesh atlas = ReadFEMesh(std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu");
  std::printf("speaker models after Q∘R with the mesh guard off, repaired as the pipeline repairs them\n");
  for (const Speaker& speaker : all)
  {
    if (wanted.find("," + speaker.name + ",") == std::string::npos)
      continue;
    FaceModelOptions options;
    options.registration.elementQualityFloor = -1; // the guard off: R and Q tangle the mesh
    options.allowPartialFieldOfView = true;        // headsq misses the brow, VHF the nose tip
    const FaceModelResult r = BuildFaceModel(ReadCTImage(speaker.ct), ReadLandmarks(speaker.points), atlas, options);
    const FEMesh& tangled = r.refined;
    const quality::QualitySummary before = quality::SummarizeScaledJacobian(tangled, options.repairThreshold);
    std::printf("%s: %zu solid elements; after Q∘R: %zu inverted, %zu below 0.3, min %.3f; skin %.3f, skull %.3f mm "
                "(mean node distance)\n",
                speaker.name.c_str(), tangled.SolidElementCount(), before.inverted, before.belowThreshold, before.min,
                MeasureSurfaceDistance(tangled, "skin", r.skin).mean,
                MeasureSurfaceDistance(tangled, "skull", r.skull).mean);
    std::printf("  %-22s %7s %9s %8s %8s %9s %10s %8s %8s %8s\n", "repair", "success", "min SJ", "inverted", "below",
                "not cert", "cert. min", "skin mm", "skull mm", "s");
    RepairOptions repair;
    repair.scaledJacobianThreshold = options.repairThreshold;
    repair.maximumSweeps = options.repairSweeps;
    const auto skin = CropSurfaceAround(r.skin, tangled, kRepairSurfaceMargin);
    const auto skull = CropSurfaceAround(r.skull, tangled, kRepairSurfaceMargin);
    repair.skinSurface = skin;
    repair.skullSurface = skull;
    repair.hasSymmetryPlane = options.registration.symmetric;
    repair.symmetryPlane = r.plane;
    for (const bool global : {false, true})
    {
      // false: the repair before issue 28 (node by node, no plane sides, success at the corners only)
      repair.globalUntangling = repair.keepPlaneSides = repair.certifyInside = global;
      PrintRepair(global ? "global + node by node" : "node by node", tangled, repair, r);
    }
  }
  return 0;
}
