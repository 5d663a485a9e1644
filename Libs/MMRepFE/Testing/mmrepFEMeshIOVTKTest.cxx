// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// .vtu / .vtk reading and writing: exact round trips, foreign grids, error reporting.
#include "mmrepFEMeshIO.h"
#include "mmrepFETestMesh.h"
#include "mmrepFETestUtilities.h"

#include <vtkCellData.h>
#include <vtkCellValidator.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <gtest/gtest.h>

#include <stdexcept>

using namespace mmrep;
using mmrep::testing::MakeTestMesh;

namespace
{

// Expects fn to throw std::runtime_error whose single-line message names `path` and contains `what`.
template <class Fn> void ExpectFileError(Fn fn, const std::string& path, const std::string& what)
{
  try
  {
    fn();
    ADD_FAILURE() << "no error for " << path;
  }
  catch (const std::runtime_error& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

} // namespace

TEST(FEMeshIO, TestMeshIsValidInVTK)
{
  // Guards the fixture itself: every solid is a valid VTK cell and every embedding maps back to
  // its node through VTK's own interpolation.
  const FEMesh mesh = MakeTestMesh();
  ASSERT_NO_THROW(mesh.Validate());
  auto grid = ToVTK(mesh);
  vtkNew<vtkCellValidator> validator;
  validator->SetInputData(grid);
  validator->Update();
  auto* state = validator->GetOutput()->GetCellData()->GetArray("ValidityState");
  for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i)
    EXPECT_EQ(state->GetTuple1(i), 0) << "cell " << i;
  vtkNew<vtkGenericCell> cell;
  for (const auto& [name, muscle] : mesh.muscles)
    for (std::size_t k = 0; k < muscle.nodes.size(); ++k)
    {
      grid->GetCell(muscle.embedding[k].element, cell);
      double pcoords[3] = {muscle.embedding[k].pcoords[0], muscle.embedding[k].pcoords[1],
                           muscle.embedding[k].pcoords[2]};
      double x[3], weights[8];
      int subId = 0;
      cell->EvaluateLocation(subId, pcoords, x, weights);
      EXPECT_NEAR((Point3(x[0], x[1], x[2]) - mesh.nodes[muscle.nodes[k]]).norm(), 0.0, 1e-12) << name << " " << k;
    }
}

TEST(FEMeshIO, VtuRoundTripIsExact)
{
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  const FEMesh mesh = MakeTestMesh();
  const auto path = (dir / "mesh.vtu").string();
  WriteFEMesh(mesh, path);
  mmrep::testing::ExpectSameMesh(mesh, ReadFEMesh(path));
  // Binary appended data, not ASCII (which would round coordinates).
  const std::string text = mmrep::testing::ReadText(path);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
  EXPECT_NE(text.find("type=\"Float64\" Name=\"Points\""), std::string::npos);
  EXPECT_EQ(text.find("format=\"ascii\""), std::string::npos);
  // Same bytes when written again: deterministic output.
  WriteFEMesh(ReadFEMesh(path), (dir / "again.vtu").string());
  EXPECT_EQ(text, mmrep::testing::ReadText(dir / "again.vtu"));
}

TEST(FEMeshIO, LegacyVtkRoundTripIsExact)
{
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  const FEMesh mesh = MakeTestMesh();
  const auto path = (dir / "mesh.vtk").string();
  WriteFEMesh(mesh, path);
  mmrep::testing::ExpectSameMesh(mesh, ReadFEMesh(path));
  // Explicit format with a foreign extension (as modules do with temporary names).
  const auto tmp = (dir / "mesh.tmp").string();
  WriteFEMesh(mesh, tmp, "vtk");
  EXPECT_EQ(mmrep::testing::ReadText(tmp), mmrep::testing::ReadText(path));
}

// Slicer's SPACE tag (vtkMRMLModelStorageNode): field data of .vtu, header of legacy .vtk (ours say
// LPS); meshes Slicer wrote in RAS come back in LPS, nodes and landmarks alike.
TEST(FEMeshIO, SlicersSpaceTagIsHonouredAndRasFilesAreConverted)
{
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  const FEMesh mesh = MakeTestMesh();
  ASSERT_FALSE(mesh.landmarks.empty());
  const auto vtu = (dir / "tagged.vtu").string(), vtk = (dir / "tagged.vtk").string();
  WriteFEMesh(mesh, vtu);
  WriteFEMesh(mesh, vtk);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(vtu.c_str());
  reader->Update();
  EXPECT_NE(mmrep::testing::ReadText(vtk).find("SPACE=LPS"), std::string::npos);

  // The same grid tagged RAS, as older Slicer versions wrote it.
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->DeepCopy(reader->GetOutput());
  vtkNew<vtkPoints> ras;
  ras->SetDataTypeToDouble();
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    const double* p = grid->GetPoint(i);
    ras->InsertNextPoint(-p[0], -p[1], p[2]);
  }
  grid->SetPoints(ras);
  vtkNew<vtkStringArray> tag;
  tag->SetName("SPACE");
  tag->InsertNextValue("RAS");
  grid->GetFieldData()->AddArray(tag);
  if (auto* positions = vtkDataArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("MMRep.LandmarkPositions")))
    for (vtkIdType i = 0; i < positions->GetNumberOfTuples(); ++i)
    {
      positions->SetComponent(i, 0, -positions->GetComponent(i, 0));
      positions->SetComponent(i, 1, -positions->GetComponent(i, 1));
    }
  const auto rasVtu = (dir / "ras.vtu").string(), rasVtk = (dir / "ras.vtk").string();
  vtkNew<vtkXMLUnstructuredGridWriter> xml;
  xml->SetInputData(grid);
  xml->SetFileName(rasVtu.c_str());
  ASSERT_EQ(xml->Write(), 1);
  grid->GetFieldData()->RemoveArray("SPACE");
  vtkNew<vtkUnstructuredGridWriter> legacy;
  legacy->SetInputData(grid);
  legacy->SetFileName(rasVtk.c_str());
  legacy->SetFileTypeToBinary();
  legacy->SetHeader("3D Slicer output. SPACE=RAS");
  ASSERT_EQ(legacy->Write(), 1);
  mmrep::testing::ExpectSameMesh(mesh, ReadFEMesh(rasVtu));
  mmrep::testing::ExpectSameMesh(mesh, ReadFEMesh(rasVtk));
}

TEST(FEMeshIO, GridShowsLayersAndSetMasks)
{
  const FEMesh mesh = MakeTestMesh();
  auto grid = ToVTK(mesh);
  ASSERT_EQ(grid->GetNumberOfPoints(), static_cast<vtkIdType>(mesh.nodes.size()));
  EXPECT_EQ(grid->GetPoints()->GetDataType(), VTK_DOUBLE);
  auto* layer = vtkIntArray::SafeDownCast(grid->GetCellData()->GetArray("Layer"));
  ASSERT_NE(layer, nullptr);
  for (std::size_t i = 0; i < mesh.elements.size(); ++i)
  {
    EXPECT_EQ(grid->GetCellType(static_cast<vtkIdType>(i)), static_cast<int>(mesh.elements[i].type));
    EXPECT_EQ(layer->GetValue(static_cast<vtkIdType>(i)), static_cast<int>(mesh.elements[i].layer));
  }
  // Masks: 1 exactly on the set members (skin: the 6 top grid nodes and the 2 wedge tips).
  auto* skin = grid->GetPointData()->GetArray("NodeSet.skin");
  ASSERT_NE(skin, nullptr);
  EXPECT_EQ(skin->GetDataType(), VTK_UNSIGNED_CHAR);
  double sum = 0;
  for (vtkIdType i = 0; i < skin->GetNumberOfTuples(); ++i)
    sum += skin->GetTuple1(i);
  EXPECT_EQ(sum, 8);
  EXPECT_EQ(skin->GetTuple1(mmrep::testing::GridNode(1, 1, 3)), 1);
  EXPECT_EQ(skin->GetTuple1(mmrep::testing::GridNode(1, 1, 2)), 0);
  auto* mixed = grid->GetCellData()->GetArray("ElementSet.mixed%C3%A9");
  ASSERT_NE(mixed, nullptr);
  for (vtkIdType i = 0; i < mixed->GetNumberOfTuples(); ++i)
    EXPECT_EQ(mixed->GetTuple1(i), (i == 0 || i == 7 || i == 9) ? 1 : 0) << i;
  // Field data names follow the documented scheme.
  auto* field = grid->GetFieldData();
  EXPECT_NE(field->GetAbstractArray("MMRep.NodeSet.lips%20%28upper%29"), nullptr);
  EXPECT_NE(field->GetAbstractArray("MMRep.Muscle.levator%2Elabii%2050%25.EmbeddingPCoords"), nullptr);
  EXPECT_NE(field->GetAbstractArray("MMRep.LandmarkNames"), nullptr);
}

TEST(FEMeshIO, ReadsPlainGridWithoutMMRepArrays)
{
  // A hexahedron, a wedge and a line written by VTK itself, float points, ASCII, no MMRep arrays.
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  vtkNew<vtkPoints> points; // float by default
  const double coords[10][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},      {0, 0, 1},
                                {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {0.1f, 0.5, 2}, {2.5, 0.3, 0.7}};
  for (const auto& c : coords)
    points->InsertNextPoint(c);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  const vtkIdType hex[8] = {0, 1, 2, 3, 4, 5, 6, 7}, line[2] = {8, 9}, wedge[6] = {4, 6, 5, 8, 9, 7};
  grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  grid->InsertNextCell(VTK_LINE, 2, line);
  grid->InsertNextCell(VTK_WEDGE, 6, wedge);
  for (const std::string name : {"plain.vtu", "plain.vtk"})
  {
    const auto path = (dir / name).string();
    if (name == "plain.vtu")
    {
      vtkNew<vtkXMLUnstructuredGridWriter> writer;
      writer->SetDataModeToAscii();
      writer->SetInputData(grid);
      writer->SetFileName(path.c_str());
      ASSERT_EQ(writer->Write(), 1);
    }
    else
    {
      vtkNew<vtkUnstructuredGridWriter> writer;
      writer->SetInputData(grid);
      writer->SetFileName(path.c_str());
      ASSERT_EQ(writer->Write(), 1);
    }
    const FEMesh mesh = ReadFEMesh(path);
    ASSERT_EQ(mesh.nodes.size(), 10u) << name;
    for (int i = 0; i < 10; ++i)
      for (int d = 0; d < 3; ++d)
        EXPECT_EQ(mesh.nodes[i][d], static_cast<double>(static_cast<float>(coords[i][d]))) << name;
    ASSERT_EQ(mesh.elements.size(), 3u);
    EXPECT_EQ(mesh.elements[0].type, ElementType::Hexahedron);
    EXPECT_EQ(mesh.elements[1].type, ElementType::Cable);
    EXPECT_EQ(mesh.elements[2].type, ElementType::Wedge);
    for (int k = 0; k < 6; ++k)
      EXPECT_EQ(mesh.elements[2].nodes[k], wedge[k]);
    for (const auto& e : mesh.elements)
      EXPECT_EQ(e.layer, TissueLayer::None);
    EXPECT_TRUE(mesh.nodeSets.empty() && mesh.elementSets.empty() && mesh.muscles.empty() && mesh.landmarks.empty());
  }
}

TEST(FEMeshIO, RejectsNonFECells)
{
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  const vtkIdType tri[3] = {0, 1, 2};
  grid->InsertNextCell(VTK_TRIANGLE, 3, tri);
  const auto path = (dir / "triangle.vtu").string();
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1);
  ExpectFileError([&] { ReadFEMesh(path); }, path, "vtkTriangle");
}

// Files written before the maximum force was stored: their tracks read the documented default.
TEST(FEMeshIO, MuscleWithoutMaximumForceReadsTheDefault)
{
  const FEMesh mesh = MakeTestMesh();
  auto grid = ToVTK(mesh);
  ASSERT_NE(grid->GetFieldData()->GetAbstractArray("MMRep.Muscle.orbicularis%20oris.MaximumForce"), nullptr);
  EXPECT_EQ(FromVTK(grid).muscles.at("orbicularis oris").maximumForce, 0.43);
  grid->GetFieldData()->RemoveArray("MMRep.Muscle.orbicularis%20oris.MaximumForce");
  EXPECT_EQ(FromVTK(grid).muscles.at("orbicularis oris").maximumForce, MuscleTrack::kDefaultMaximumForce);
  EXPECT_EQ(MuscleTrack::kDefaultMaximumForce, 1.0);
}

TEST(FEMeshIO, InconsistentFieldDataIsRejected)
{
  const FEMesh mesh = MakeTestMesh();
  {
    auto grid = ToVTK(mesh);
    auto* set = vtkIntArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("MMRep.NodeSet.skull"));
    ASSERT_NE(set, nullptr);
    set->SetValue(2, static_cast<int>(mesh.nodes.size())); // one past the last node
    EXPECT_THROW(FromVTK(grid), std::runtime_error);
  }
  {
    // A cable list that no longer matches the track points.
    auto grid = ToVTK(mesh);
    auto* cables =
      vtkIntArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("MMRep.Muscle.orbicularis%20oris.Cables"));
    ASSERT_NE(cables, nullptr);
    cables->SetValue(0, 9);
    try
    {
      FromVTK(grid);
      ADD_FAILURE() << "mismatched cables accepted";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_NE(std::string(e.what()).find("orbicularis oris"), std::string::npos) << e.what();
    }
  }
  {
    auto grid = ToVTK(mesh);
    grid->GetCellData()->GetArray("Layer")->SetTuple1(3, 7);
    EXPECT_THROW(FromVTK(grid), std::runtime_error);
  }
  {
    auto grid = ToVTK(mesh);
    auto* force = vtkDataArray::SafeDownCast(
      grid->GetFieldData()->GetAbstractArray("MMRep.Muscle.orbicularis%20oris.MaximumForce"));
    ASSERT_NE(force, nullptr);
    force->SetTuple1(0, -1);
    EXPECT_THROW(FromVTK(grid), std::runtime_error);
  }
}

TEST(FEMeshIO, ValidateReportsTheFirstProblem)
{
  auto expectInvalid = [](const FEMesh& mesh, const std::string& what) {
    try
    {
      mesh.Validate();
      ADD_FAILURE() << "accepted: " << what;
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  FEMesh mesh = MakeTestMesh();
  mesh.elements[3].nodes[5] = -1;
  expectInvalid(mesh, "element 3");
  mesh = MakeTestMesh();
  mesh.nodeSets["skin"].push_back(1000);
  expectInvalid(mesh, "node set 'skin'");
  mesh = MakeTestMesh();
  mesh.muscles["orbicularis oris"].embedding[1].element = 8; // a cable, not a solid
  expectInvalid(mesh, "non-solid");
  mesh = MakeTestMesh();
  mesh.nodes[4].y() = std::numeric_limits<double>::quiet_NaN();
  expectInvalid(mesh, "node 4");
  // Writers refuse invalid meshes without creating the file.
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  for (const std::string ext : {".vtu", ".vtk", ".inp", ".feb", ".msh"})
  {
    const auto path = (dir / ("bad" + ext)).string();
    ExpectFileError([&] { WriteFEMesh(mesh, path); }, path, "node 4");
    EXPECT_FALSE(std::filesystem::exists(path)) << path;
  }
}

TEST(FEMeshIO, FileErrorsAreOneLineNamingTheFile)
{
  const auto dir = mmrep::testing::ScratchDir("FEMeshIO");
  const FEMesh mesh = MakeTestMesh();
  const auto missing = (dir / "missing.vtu").string();
  ExpectFileError([&] { ReadFEMesh(missing); }, missing, "not found");
  const auto stl = (dir / "mesh.stl").string();
  std::ofstream(stl) << "solid x\nendsolid x\n";
  ExpectFileError([&] { ReadFEMesh(stl); }, stl, "unsupported");
  ExpectFileError([&] { WriteFEMesh(mesh, stl); }, stl, "unsupported");
  ExpectFileError([&] { WriteFEMesh(mesh, (dir / "x.vtu").string(), "obj"); }, (dir / "x.vtu").string(), "unsupported");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.vtu"));
  // Empty mesh: refused when writing, and an empty grid is refused when reading.
  const auto empty = (dir / "empty.vtu").string();
  ExpectFileError([&] { WriteFEMesh(FEMesh{}, empty); }, empty, "empty");
  EXPECT_FALSE(std::filesystem::exists(empty));
  {
    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkPoints> points;
    grid->SetPoints(points);
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetInputData(grid);
    writer->SetFileName(empty.c_str());
    ASSERT_EQ(writer->Write(), 1);
  }
  ExpectFileError([&] { ReadFEMesh(empty); }, empty, "no mesh");
  // Truncated and garbage files in both formats.
  for (const std::string ext : {".vtu", ".vtk"})
  {
    const auto full = (dir / ("full" + ext)).string();
    WriteFEMesh(mesh, full);
    const std::string bytes = mmrep::testing::ReadText(full);
    for (double fraction : {0.3, 0.6, 0.9, 0.99})
    {
      const auto truncated = (dir / ("truncated" + std::to_string(int(fraction * 100)) + ext)).string();
      std::ofstream(truncated, std::ios::binary) << bytes.substr(0, std::size_t(bytes.size() * fraction));
      ExpectFileError([&] { ReadFEMesh(truncated); }, truncated, "");
    }
    const auto garbage = (dir / ("garbage" + ext)).string();
    std::ofstream(garbage) << "this is not a mesh\n";
    ExpectFileError([&] { ReadFEMesh(garbage); }, garbage, "not a");
  }
  // Unwritable location.
  const auto nowhere = (dir / "no-such-folder" / "mesh.inp").string();
  ExpectFileError([&] { WriteFEMesh(mesh, nowhere); }, nowhere, "cannot");
  const auto nowhereVtu = (dir / "no-such-folder" / "mesh.vtu").string();
  ExpectFileError([&] { WriteFEMesh(mesh, nowhereVtu); }, nowhereVtu, "cannot");
}

TEST(FEMeshIO, ExtensionLists)
{
  EXPECT_EQ(ReadableFEMeshExtensions(), (std::vector<std::string>{".vtu", ".vtk"}));
  EXPECT_EQ(WritableFEMeshExtensions(), (std::vector<std::string>{".vtu", ".vtk", ".inp", ".feb", ".msh"}));
}
