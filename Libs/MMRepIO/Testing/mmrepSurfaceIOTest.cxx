// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Surface round trips through every supported format, checked triangle by triangle.
#include "mmrepSurfaceIO.h"
#include "mmrepTestDir.h"

#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataWriter.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>

namespace fs = std::filesystem;

namespace
{

// A closed triangulated sphere at an awkward position, so coordinates use all float digits.
vtkSmartPointer<vtkPolyData> TestSurface()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(17);
  sphere->SetRadius(37.3);
  vtkNew<vtkTransform> t;
  t->Translate(12.345678, -98.7654321, 45.6789);
  t->RotateWXYZ(33.0, 0.2, 0.5, 0.8);
  vtkNew<vtkTransformPolyDataFilter> move;
  move->SetInputConnection(sphere->GetOutputPort());
  move->SetTransform(t);
  move->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(move->GetOutput());
  out->GetPointData()->Initialize(); // geometry only: normals would make OBJ split vertices
  return out;
}

std::vector<std::array<double, 9>> TriangleCorners(vtkPolyData* surface)
{
  std::vector<std::array<double, 9>> corners;
  vtkNew<vtkIdList> ids;
  vtkCellArray* polys = surface->GetPolys();
  polys->InitTraversal();
  while (polys->GetNextCell(ids))
  {
    EXPECT_EQ(ids->GetNumberOfIds(), 3);
    std::array<double, 9> c{};
    for (int k = 0; k < 3; ++k)
    {
      surface->GetPoint(ids->GetId(k), &c[3 * k]);
    }
    corners.push_back(c);
  }
  return corners;
}

void RoundTrip(const std::string& extension)
{
  const fs::path dir = mmrep::test::ScratchDir();
  vtkSmartPointer<vtkPolyData> original = TestSurface();
  const std::string path = (dir / ("surface." + extension)).string();
  mmrep::WriteSurface(original, path);
  vtkSmartPointer<vtkPolyData> back = mmrep::ReadSurface(path);
  ASSERT_EQ(back->GetNumberOfPoints(), original->GetNumberOfPoints());
  ASSERT_EQ(back->GetNumberOfPolys(), original->GetNumberOfPolys());
  // Float precision (STL and PLY store float32): relative 1e-6 of the coordinate magnitude.
  const double tol = 2e-7 * 150.0;
  const auto a = TriangleCorners(original);
  const auto b = TriangleCorners(back);
  ASSERT_EQ(a.size(), b.size());
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    for (int k = 0; k < 9; ++k)
    {
      worst = std::max(worst, std::abs(a[i][k] - b[i][k]));
    }
  }
  EXPECT_LE(worst, tol) << extension;
  if (extension != "stl") // STL has no shared points; the others keep point order
  {
    for (vtkIdType i = 0; i < original->GetNumberOfPoints(); ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        ASSERT_NEAR(original->GetPoint(i)[k], back->GetPoint(i)[k], tol) << extension << " point " << i;
      }
    }
  }
}

void ExpectThrowsNaming(const std::function<void()>& f, const std::string& path, const std::string& what)
{
  try
  {
    f();
    ADD_FAILURE() << "no exception for " << path;
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

} // namespace

TEST(SurfaceIO, RoundTripVtp)
{
  RoundTrip("vtp");
}
TEST(SurfaceIO, RoundTripLegacyVtk)
{
  RoundTrip("vtk");
}
TEST(SurfaceIO, RoundTripStl)
{
  RoundTrip("stl");
}
TEST(SurfaceIO, RoundTripPly)
{
  RoundTrip("ply");
}
TEST(SurfaceIO, RoundTripObj)
{
  RoundTrip("obj");
}

TEST(SurfaceIO, DoublePrecisionFormatsAreExact)
{
  const fs::path dir = mmrep::test::ScratchDir();
  vtkSmartPointer<vtkPolyData> original = TestSurface();
  for (const char* ext : {"vtp", "vtk"})
  {
    const std::string path = (dir / (std::string("s.") + ext)).string();
    mmrep::WriteSurface(original, path);
    vtkSmartPointer<vtkPolyData> back = mmrep::ReadSurface(path);
    for (vtkIdType i = 0; i < original->GetNumberOfPoints(); ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        ASSERT_EQ(original->GetPoint(i)[k], back->GetPoint(i)[k]) << ext;
      }
    }
  }
}

TEST(SurfaceIO, SlicerRasLegacyFileIsConvertedToLps)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const std::string path = (dir / "ras.vtk").string();
  std::ofstream(path) << "# vtk DataFile Version 4.2\nSPACE=RAS\nASCII\nDATASET POLYDATA\n"
                         "POINTS 3 float\n1 2 3\n4 5 6\n-7 8 9\nPOLYGONS 1 4\n3 0 1 2\n";
  vtkSmartPointer<vtkPolyData> s = mmrep::ReadSurface(path);
  ASSERT_EQ(s->GetNumberOfPoints(), 3);
  EXPECT_DOUBLE_EQ(s->GetPoint(0)[0], -1);
  EXPECT_DOUBLE_EQ(s->GetPoint(0)[1], -2);
  EXPECT_DOUBLE_EQ(s->GetPoint(0)[2], 3);
  EXPECT_DOUBLE_EQ(s->GetPoint(2)[0], 7);
  EXPECT_DOUBLE_EQ(s->GetPoint(2)[1], -8);
}

// Slicer's convention for XML files (vtkMRMLModelStorageNode): a string array "SPACE" in the field data.
TEST(SurfaceIO, VtpTaggedRasBySlicerIsConvertedToLps)
{
  const fs::path dir = mmrep::test::ScratchDir();
  vtkNew<vtkPolyData> triangle;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(1, 2, 3);
  points->InsertNextPoint(4, 5, 6);
  points->InsertNextPoint(-7, 8, 9);
  triangle->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  const vtkIdType ids[3] = {0, 1, 2};
  polys->InsertNextCell(3, ids);
  triangle->SetPolys(polys);
  // Slicer before 4.11 wrote RAS: converted to LPS.
  vtkNew<vtkPolyData> ras;
  ras->DeepCopy(triangle);
  vtkNew<vtkStringArray> rasTag;
  rasTag->SetName("SPACE");
  rasTag->InsertNextValue("RAS");
  ras->GetFieldData()->AddArray(rasTag);
  const std::string theirs = (dir / "ras.vtp").string();
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(ras);
  writer->SetFileName(theirs.c_str());
  ASSERT_EQ(writer->Write(), 1);
  auto converted = mmrep::ReadSurface(theirs);
  EXPECT_EQ(converted->GetFieldData()->GetAbstractArray("SPACE"), nullptr); // file metadata, not data
  EXPECT_DOUBLE_EQ(converted->GetPoint(0)[0], -1);
  EXPECT_DOUBLE_EQ(converted->GetPoint(0)[1], -2);
  EXPECT_DOUBLE_EQ(converted->GetPoint(0)[2], 3);
  EXPECT_DOUBLE_EQ(converted->GetPoint(2)[0], 7);
  EXPECT_DOUBLE_EQ(converted->GetPoint(2)[1], -8);
}

TEST(SurfaceIO, BadInputsThrowNamingThePath)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const std::string missing = (dir / "missing.vtp").string();
  ExpectThrowsNaming([&] { mmrep::ReadSurface(missing); }, missing, "does not exist");
  const std::string unknown = (dir / "surface.off").string();
  std::ofstream(unknown) << "OFF\n";
  ExpectThrowsNaming([&] { mmrep::ReadSurface(unknown); }, unknown, "extension");
  // An XML file without points is a reader error; a legacy file with zero points reads "fine".
  vtkNew<vtkPolyData> nothing;
  const std::string emptyXml = (dir / "empty.vtp").string();
  vtkNew<vtkXMLPolyDataWriter> xmlWriter;
  xmlWriter->SetInputData(nothing);
  xmlWriter->SetFileName(emptyXml.c_str());
  ASSERT_EQ(xmlWriter->Write(), 1);
  ExpectThrowsNaming([&] { mmrep::ReadSurface(emptyXml); }, emptyXml, "");
  const std::string emptyLegacy = (dir / "empty.vtk").string();
  vtkNew<vtkPolyDataWriter> legacyWriter;
  legacyWriter->SetInputData(nothing);
  legacyWriter->SetFileName(emptyLegacy.c_str());
  ASSERT_EQ(legacyWriter->Write(), 1);
  ExpectThrowsNaming([&] { mmrep::ReadSurface(emptyLegacy); }, emptyLegacy, "no points");
  const std::string garbage = (dir / "garbage.vtp").string();
  std::ofstream(garbage) << "this is not XML at all";
  ExpectThrowsNaming([&] { mmrep::ReadSurface(garbage); }, garbage, "");
  const std::string badOut = (dir / "out.off").string();
  ExpectThrowsNaming([&] { mmrep::WriteSurface(TestSurface(), badOut); }, badOut, "extension");
  const std::string noDir = (dir / "no-such-dir" / "s.vtp").string();
  ExpectThrowsNaming([&] { mmrep::WriteSurface(TestSurface(), noDir); }, noDir, "cannot write");
}
