// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// SymmetryPlane: skin surface -> mid-sagittal plane (point, normal) and an optional Slicer plane markup.
#include "mmrepCLI.h"
#include "mmrepSurfaceIO.h"
#include "mmrepSymmetryPlane.h"

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

extern const char SymmetryPlaneXML[];

namespace
{

std::vector<double> Vec(const Eigen::Vector3d& v)
{
  return {v.x(), v.y(), v.z()};
}

// Slicer markups plane (schema v1.0.3), point-normal type, LPS. Slicer rebuilds a point-normal plane
// from its first control point (the origin) and objectToBase (columns: the plane's x, y axes and
// normal); "center" and "normal" are written too for other readers.
void WritePlaneMarkup(const mmrep::Plane& plane, const std::string& path)
{
  const Eigen::Vector3d n = plane.normal.normalized();
  // In-plane axes: y along the projection of LPS superior, x completes a right-handed frame.
  Eigen::Vector3d y = Eigen::Vector3d::UnitZ() - n.z() * n;
  if (y.norm() < 1e-6)
    y = Eigen::Vector3d::UnitY() - n.y() * n;
  y.normalize();
  const Eigen::Vector3d x = y.cross(n);
  std::vector<double> objectToBase(16, 0.0);
  for (int r = 0; r < 3; ++r)
  {
    objectToBase[4 * r + 0] = x(r);
    objectToBase[4 * r + 1] = y(r);
    objectToBase[4 * r + 2] = n(r);
  }
  objectToBase[15] = 1.0;
  nlohmann::ordered_json point;
  point["id"] = "1";
  point["label"] = "midsagittal";
  point["position"] = Vec(plane.point);
  point["positionStatus"] = "defined";
  nlohmann::ordered_json markup;
  markup["type"] = "Plane";
  markup["name"] = "midsagittal";
  markup["coordinateSystem"] = "LPS";
  markup["coordinateUnits"] = "mm";
  markup["planeType"] = "pointNormal";
  markup["sizeMode"] = "auto";
  markup["center"] = Vec(plane.point);
  markup["normal"] = Vec(n);
  markup["objectToBase"] = objectToBase;
  markup["controlPoints"] = nlohmann::ordered_json::array({point});
  nlohmann::ordered_json doc;
  doc["@schema"] = "https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/Markups/Resources/Schema/"
                   "markups-schema-v1.0.3.json#";
  doc["markups"] = nlohmann::ordered_json::array({markup});
  std::ofstream f(path);
  f << std::setprecision(17) << doc.dump(2) << "\n";
  if (!f.good())
    throw mmrep::cli::ModuleError("cannot write the plane markup '" + path + "'");
}

void Run(mmrep::cli::ModuleContext& ctx)
{
  const auto& args = ctx.args;
  std::unique_ptr<mmrep::cli::AtomicOutput> planeOut;
  if (args.Given("outputPlane"))
  {
    if (mmrep::cli::FileExtension(args.String("outputPlane")) != ".mrk.json")
      throw mmrep::cli::ModuleError("outputPlane '" + args.String("outputPlane") + "' must end in .mrk.json");
    planeOut = std::make_unique<mmrep::cli::AtomicOutput>(args.String("outputPlane"));
  }

  ctx.progress.Start("Symmetry plane");
  const auto skin = mmrep::ReadSurface(args.String("inputSurface"));
  ctx.progress.Report(0.1);
  mmrep::SymmetryPlaneOptions options;
  options.maximumIterations = static_cast<int>(args.Int("maximumIterations"));
  options.samplePoints = static_cast<std::size_t>(args.Int("samplePoints"));
  options.trimFraction = args.Double("trimFraction");
  mmrep::SymmetryPlaneResult result;
  try
  {
    result = mmrep::EstimateSymmetryPlane(skin, options);
  }
  catch (const std::exception& e)
  {
    throw mmrep::cli::ModuleError("'" + args.String("inputSurface") + "': " + e.what());
  }
  ctx.progress.Report(0.9);
  if (planeOut)
  {
    WritePlaneMarkup(result.plane, planeOut->TempPath());
    planeOut->Commit();
  }
  std::cout << std::setprecision(6) << "Plane: point " << result.plane.point.transpose() << " mm, normal "
            << result.plane.normal.transpose() << ", rms residual " << result.rmsResidual << " mm, "
            << result.iterations << " iterations" << std::endl;
  ctx.outputs.Set("planePoint", Vec(result.plane.point));
  ctx.outputs.Set("planeNormal", Vec(result.plane.normal));
  ctx.outputs.Set("rmsResidual", result.rmsResidual);
  ctx.outputs.Set("iterations", result.iterations);
  ctx.progress.End();
}
} // namespace

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, SymmetryPlaneXML, Run);
}
