// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// DistanceMap as a user runs it: from a surface file and from a label volume.
#include "mmrepImageIO.h"
#include "mmrepModuleRunner.h"
#include "mmrepSurfaceDistanceMap.h"
#include "mmrepSurfaceIO.h"

#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkSphereSource.h>
#include <vtkStaticCellLocator.h>

#include <cstring>

using mmrep::testing::ReadReturnParameters;
using mmrep::testing::RunModuleExecutable;
using mmrep::testing::ScratchDirectory;

TEST(DistanceMapModule, SurfaceFileGivesTheLibraryMapAndExactBand)
{
  ScratchDirectory dir("dm");
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(25);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  sphere->Update();
  mmrep::WriteSurface(sphere->GetOutput(), dir / "sphere.vtp");
  const auto run = RunModuleExecutable("DistanceMap", {dir / "sphere.vtp", dir / "map.nrrd", "--spacing", "1.5",
                                                       "--margin", "6", "--returnparameterfile", dir / "rp.txt"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto map = mmrep::ReadFloatImage(dir / "map.nrrd");
  mmrep::SurfaceDistanceMapOptions o;
  o.spacing = 1.5;
  o.margin = 6;
  auto reference = mmrep::ComputeSurfaceDistanceMap(sphere->GetOutput(), o);
  const auto n = map->GetBufferedRegion().GetNumberOfPixels();
  ASSERT_EQ(n, reference->GetBufferedRegion().GetNumberOfPixels());
  EXPECT_EQ(0, std::memcmp(map->GetBufferPointer(), reference->GetBufferPointer(), n * sizeof(float)));
  // Near the surface the values are distances to the triangles (VTK's locator as reference).
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(sphere->GetOutput());
  locator->BuildLocator();
  std::size_t checked = 0;
  for (std::size_t v = 0; v < n; v += 7)
  {
    const float value = map->GetBufferPointer()[v];
    if (value > 2.9f)
      continue;
    mmrep::FloatImage::IndexType idx;
    const auto size = map->GetBufferedRegion().GetSize();
    idx[0] = v % size[0];
    idx[1] = (v / size[0]) % size[1];
    idx[2] = v / (size[0] * size[1]);
    mmrep::FloatImage::PointType p;
    map->TransformIndexToPhysicalPoint(idx, p);
    double closest[3], d2;
    vtkIdType cell;
    int sub;
    locator->FindClosestPoint(p.GetDataPointer(), closest, cell, sub, d2);
    EXPECT_NEAR(value, std::sqrt(d2), 1e-4);
    ++checked;
  }
  EXPECT_GT(checked, 100u);
  const auto values = ReadReturnParameters(dir / "rp.txt");
  EXPECT_EQ(values.count("maximumDistance"), 1u);
}

TEST(DistanceMapModule, LabelVolumeBoundary)
{
  ScratchDirectory dir("dm-label");
  // A 20 mm cube of label 3 in a label volume: the map is 0 on its boundary and grows outside.
  auto labels = mmrep::CTImage::New();
  mmrep::CTImage::RegionType r;
  r.SetSize({{40, 40, 40}});
  labels->SetRegions(r);
  labels->Allocate(true);
  for (int k = 10; k < 30; ++k)
    for (int j = 10; j < 30; ++j)
      for (int i = 10; i < 30; ++i)
        labels->SetPixel({{i, j, k}}, 3);
  labels->SetPixel({{2, 2, 2}}, 5); // another label, ignored with --labelValue 3
  mmrep::WriteImage(labels.GetPointer(), dir / "labels.nrrd");
  const auto run = RunModuleExecutable(
    "DistanceMap", {dir / "labels.nrrd", dir / "map.mha", "--labelValue", "3", "--spacing", "0.5", "--margin", "4"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto map = mmrep::ReadFloatImage(dir / "map.mha");
  // The iso-surface at 0.5 of the cube indicator is the box [9.5, 29.5]^3 (voxel units = mm here).
  itk::Point<double, 3> outside;
  outside[0] = 33.5, outside[1] = 19.5, outside[2] = 19.5; // 4 mm from the face x = 29.5
  mmrep::FloatImage::IndexType idx;
  ASSERT_TRUE(map->TransformPhysicalPointToIndex(outside, idx));
  EXPECT_NEAR(map->GetPixel(idx), 4.0, 1e-4);
  itk::Point<double, 3> onFace;
  onFace[0] = 29.5, onFace[1] = 19.5, onFace[2] = 19.5;
  ASSERT_TRUE(map->TransformPhysicalPointToIndex(onFace, idx));
  EXPECT_NEAR(map->GetPixel(idx), 0.0, 1e-4);
}

TEST(DistanceMapModule, BadInputOneLineNonZeroNoOutput)
{
  ScratchDirectory dir("dm-bad");
  vtkNew<vtkPolyData> empty;
  mmrep::WriteSurface(empty, dir / "empty.vtp");
  struct Case
  {
    std::vector<std::string> args;
    std::string expect;
  };
  const std::vector<Case> cases = {
    {{dir / "missing.vtp", dir / "m.nrrd"}, "missing.vtp"},
    {{dir / "empty.vtp", dir / "m.nrrd"}, "empty.vtp"},
    {{dir / "empty.vtp", dir / "m.nrrd", "--spacing", "-1"}, "spacing"},
    {{dir / "empty.vtp", dir / "m.nrrd", "--region", "1,2,3"}, "region"},
  };
  for (const auto& c : cases)
  {
    const auto run = RunModuleExecutable("DistanceMap", c.args);
    EXPECT_NE(run.exitCode, 0) << c.expect;
    const auto lines = run.ErrLines();
    ASSERT_EQ(lines.size(), 1u) << run.err;
    EXPECT_NE(lines[0].find(c.expect), std::string::npos) << lines[0];
    for (const auto& e : dir.Entries())
      EXPECT_EQ(e, "empty.vtp") << "left behind: " << e;
  }
}
