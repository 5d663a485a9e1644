// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// DistanceMap: surface or label volume -> Euclidean distance map (float, mm) on an LPS grid.
#include "mmrepCLI.h"
#include "mmrepImageIO.h"
#include "mmrepSurfaceDistanceMap.h"
#include "mmrepSurfaceExtraction.h"
#include "mmrepSurfaceIO.h"

#include <algorithm>
#include <iostream>
#include <set>

extern const char DistanceMapXML[];

namespace
{
bool IsVolumePath(const std::string& path)
{
  static const std::set<std::string> volumes = {".nrrd", ".nhdr", ".mha", ".mhd", ".nii", ".nii.gz"};
  return volumes.count(mmrep::cli::FileExtension(path)) > 0;
}

// The object's boundary in a label volume, as a triangle surface: Marching Cubes at 0.5 on the
// object's indicator, closed at the volume border.
vtkSmartPointer<vtkPolyData> LabelBoundary(const std::string& path, long long label)
{
  auto labels = mmrep::ReadCTImage(path);
  short* p = labels->GetBufferPointer();
  const std::size_t n = labels->GetBufferedRegion().GetNumberOfPixels();
  std::size_t inside = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    p[i] = label == 0 ? p[i] != 0 : p[i] == label;
    inside += p[i];
  }
  if (inside == 0)
    throw mmrep::cli::ModuleError(path + ": no voxel with label " +
                                  (label == 0 ? std::string("!= 0") : std::to_string(label)));
  mmrep::SurfaceExtractionOptions o;
  o.largestPieceOnly = false;
  return mmrep::ExtractSurface(labels, 0.5, o);
}

void Run(mmrep::cli::ModuleContext& ctx)
{
  const auto& args = ctx.args;
  const std::string input = args.String("input");
  mmrep::cli::AtomicOutput out(args.String("outputMap"));
  ctx.progress.Start("Distance map");

  mmrep::SurfaceDistanceMapOptions o;
  o.spacing = args.Double("spacing");
  o.margin = args.Double("margin");
  o.exactBand = args.Double("exactBand");
  o.signedDistance = args.Bool("signed");
  if (args.Given("region"))
  {
    const auto r = args.Doubles("region");
    if (r.size() != 6 || r[0] > r[1] || r[2] > r[3] || r[4] > r[5])
      throw mmrep::cli::ModuleError("--region needs six numbers xmin,xmax,ymin,ymax,zmin,zmax with min <= max");
    std::copy(r.begin(), r.end(), o.region.begin());
  }
  auto surface = IsVolumePath(input) ? LabelBoundary(input, args.Int("labelValue")) : mmrep::ReadSurface(input);
  ctx.progress.Report(0.1);
  auto map = mmrep::ComputeSurfaceDistanceMap(surface, o, [&](double f) { ctx.progress.ReportRange(0.1, 0.9, f); });
  mmrep::WriteImage(map.GetPointer(), out.TempPath());
  out.Commit();

  const auto size = map->GetBufferedRegion().GetSize();
  const float* v = map->GetBufferPointer();
  const float maximum = *std::max_element(v, v + map->GetBufferedRegion().GetNumberOfPixels());
  std::cout << "Distance map " << size[0] << "x" << size[1] << "x" << size[2] << " at " << o.spacing
            << " mm, largest distance " << maximum << " mm" << std::endl;
  ctx.outputs.Set("mapSize", std::vector<double>{double(size[0]), double(size[1]), double(size[2])});
  ctx.outputs.Set("maximumDistance", static_cast<double>(maximum));
  ctx.progress.End();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, DistanceMapXML, Run);
}
