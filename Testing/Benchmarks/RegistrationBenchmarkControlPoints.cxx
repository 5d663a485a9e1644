// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// PlaceSampleControlPoints: the five atlas control points of a head CT by the atlas's automatic
// landmark rules (DetectFaceControlPoints), written as Slicer markups, with a QC picture.
//
//   PlaceSampleControlPoints <ct.nrrd> <out.mrk.json> [picture.png] [reference.mrk.json]
//
// With a reference markups file (e.g. the atlas landmarks of the same CT), prints the distance
// of each point to the reference point of the same name.
#include "RegistrationBenchmarkSubjects.h"

#include "mmrepFaceControlPoints.h"
#include "mmrepLandmarkIO.h"
#include "mmrepSnapshot.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>

#include <iomanip>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: PlaceSampleControlPoints <ct.nrrd> <out.mrk.json> [picture.png] [reference.mrk.json]\n";
    return 2;
  }
  try
  {
    const auto ct = mmrep::ReadCTImage(argv[1]);
    const auto s = mmrep::bench::SubjectSurfacesFromCT(ct);
    std::cout << std::setprecision(6) << "thresholds skin " << s.thresholds.skin << ", bone " << s.thresholds.bone
              << "; skin " << s.skin->GetNumberOfPoints() << " vertices, skull " << s.skull->GetNumberOfPoints()
              << "; skin bounds " << s.skin->GetBounds()[0] << " " << s.skin->GetBounds()[1] << " "
              << s.skin->GetBounds()[2] << " " << s.skin->GetBounds()[3] << " " << s.skin->GetBounds()[4] << " "
              << s.skin->GetBounds()[5] << "\nplane: point " << s.symmetry.plane.point.transpose() << ", normal "
              << s.symmetry.plane.normal.transpose() << ", RMS " << s.symmetry.rmsResidual << " mm\n";
    const auto cp = mmrep::DetectFaceControlPoints(s.skin, s.skull, s.symmetry.plane);
    for (const auto& l : cp.log)
      std::cout << "  " << l << "\n";
    for (const auto& p : cp.points)
      std::cout << p.name << ": " << p.position.transpose() << " (" << s.symmetry.plane.SignedDistance(p.position)
                << " mm from the plane)\n";
    mmrep::WriteLandmarks(cp.points, argv[2], mmrep::CoordinateSystem::LPS);
    if (argc > 4)
    {
      const auto ref = mmrep::ReadLandmarks(argv[4]);
      for (const auto& p : cp.points)
        for (const auto& r : ref)
          if (r.name == p.name)
            std::cout << "  vs reference " << p.name << ": " << (p.position - r.position).norm() << " mm\n";
    }
    if (argc > 3)
    {
      auto points = vtkSmartPointer<vtkPoints>::New();
      auto verts = vtkSmartPointer<vtkCellArray>::New();
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
      for (const auto& p : cp.points)
      {
        const vtkIdType id = points->InsertNextPoint(p.position.data());
        verts->InsertNextCell(1, &id);
        lo = lo.cwiseMin(p.position);
        hi = hi.cwiseMax(p.position);
      }
      auto marks = vtkSmartPointer<vtkPolyData>::New();
      marks->SetPoints(points);
      marks->SetVerts(verts);
      mmrep::SnapshotLayer skin, m;
      skin.surface = s.skin;
      m.surface = marks;
      m.color = {0.0, 0.8, 0.1};
      m.pointSize = 12;
      mmrep::SnapshotOptions view;
      view.views = {mmrep::View::Anterior, mmrep::View::Left};
      view.title = std::string(argv[1]).substr(std::string(argv[1]).find_last_of('/') + 1) +
                   ": control points (green) on the skin";
      const Eigen::Vector3d c = 0.5 * (lo + hi);
      view.focus = {c.x() - 60, c.x() + 60, c.y() - 60, c.y() + 60, c.z() - 60, c.z() + 60};
      mmrep::WriteSnapshot({skin, m}, view, argv[3]);
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
