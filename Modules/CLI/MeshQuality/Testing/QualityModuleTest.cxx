// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// MeshQuality module: output cell arrays against vtkMeshQuality run on the same grid, return
// parameters against the library summary, and failures (missing file, empty mesh) without output.
#include "mmrepFEMeshIO.h"
#include "mmrepMeshQuality.h"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkMeshQuality.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <sys/wait.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace
{
using namespace mmrep;
using namespace mmrep::quality;

struct RunResult
{
  int exitCode;
  std::string out, err;
};

std::string Slurp(const fs::path& p)
{
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

RunResult RunModule(const std::string& arguments, const fs::path& dir)
{
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command =
    std::string("'") + MESHQUALITY_EXE + "' " + arguments + " > '" + out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, Slurp(out), Slurp(err)};
}

fs::path TestDir(const std::string& name)
{
  const fs::path dir = fs::path(MMREP_BINARY_DIR) / "Testing" / "QualityModule" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A block of hexes (3 x 3 x 2) split in part into wedges and tets, randomly perturbed so that some
// elements are poor or inverted, plus one muscle cable.
FEMesh PerturbedMesh()
{
  FEMesh mesh;
  const int nx = 4, ny = 4, nz = 3;
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> jitter(-0.45, 0.45);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        mesh.nodes.emplace_back(i * 2.0 + jitter(rng), j * 1.5 + jitter(rng), k * 1.0 + 0.5 * jitter(rng));
  auto id = [&](int i, int j, int k) { return static_cast<std::int32_t>(i + nx * (j + ny * k)); };
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i)
      {
        const std::int32_t v[8] = {id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                                   id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        Element e;
        e.layer = TissueLayer::Dermis;
        if ((i + j) % 3 == 1)
        {
          // Two wedges (VTK order: base normal away from the top triangle).
          e.type = ElementType::Wedge;
          const std::int32_t w1[6] = {v[0], v[3], v[1], v[4], v[7], v[5]};
          const std::int32_t w2[6] = {v[1], v[3], v[2], v[5], v[7], v[6]};
          std::copy(w1, w1 + 6, e.nodes.begin());
          mesh.elements.push_back(e);
          std::copy(w2, w2 + 6, e.nodes.begin());
          mesh.elements.push_back(e);
        }
        else if ((i + j + k) % 4 == 2)
        {
          e.type = ElementType::Tetrahedron;
          const std::int32_t t[4] = {v[0], v[1], v[3], v[4]};
          std::copy(t, t + 4, e.nodes.begin());
          mesh.elements.push_back(e);
        }
        else
        {
          e.type = ElementType::Hexahedron;
          std::copy(v, v + 8, e.nodes.begin());
          mesh.elements.push_back(e);
        }
      }
  // One hex turned inside out (top and bottom faces swapped): every corner Jacobian negative.
  for (Element& e : mesh.elements)
    if (e.type == ElementType::Hexahedron)
    {
      std::swap_ranges(e.nodes.begin(), e.nodes.begin() + 4, e.nodes.begin() + 4);
      break;
    }
  Element cable;
  cable.type = ElementType::Cable;
  cable.nodes[0] = 0;
  cable.nodes[1] = 1;
  mesh.elements.push_back(cable);
  mesh.UpdateLayerSets();
  return mesh;
}

Measure ByName(const std::string& name)
{
  for (Measure m : AllMeasures())
    if (name == MeasureName(m))
      return m;
  throw std::invalid_argument("unknown measure " + name);
}

std::map<std::string, std::string> ReadReturnParameters(const fs::path& p)
{
  std::map<std::string, std::string> values;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line))
  {
    const auto eq = line.find(" = ");
    if (eq != std::string::npos)
      values[line.substr(0, eq)] = line.substr(eq + 3);
  }
  return values;
}

TEST(QualityModule, CellArraysMatchVtkMeshQualityAndSummaryMatchesLibrary)
{
  const fs::path dir = TestDir("Run");
  const FEMesh mesh = PerturbedMesh();
  WriteFEMesh(mesh, (dir / "in.vtu").string());
  const RunResult r = RunModule("'" + (dir / "in.vtu").string() + "' --outputMesh '" + (dir / "out.vtu").string() +
                                  "' --threshold 0.4 --returnparameterfile '" + (dir / "ret.txt").string() + "'",
                                dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("ScaledJacobian"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("<filter-end>"), std::string::npos) << r.out;

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir / "out.vtu").string().c_str());
  reader->Update();
  vtkUnstructuredGrid* out = reader->GetOutput();
  ASSERT_EQ(out->GetNumberOfCells(), static_cast<vtkIdType>(mesh.elements.size()));

  // vtkMeshQuality on the grid the test itself read back (hexes and tets).
  const std::pair<const char*, int> measures[] = {{"Jacobian", VTK_QUALITY_JACOBIAN},
                                                  {"ScaledJacobian", VTK_QUALITY_SCALED_JACOBIAN},
                                                  {"Shape", VTK_QUALITY_SHAPE},
                                                  {"EdgeRatio", VTK_QUALITY_EDGE_RATIO}};
  int compared = 0;
  for (const auto& [name, id] : measures)
  {
    vtkDataArray* ours = out->GetCellData()->GetArray(name);
    ASSERT_NE(ours, nullptr) << name;
    vtkNew<vtkMeshQuality> filter;
    filter->SetInputData(out);
    filter->SetHexQualityMeasure(id);
    filter->SetTetQualityMeasure(id);
    filter->Update();
    vtkDataArray* reference = filter->GetOutput()->GetCellData()->GetArray("Quality");
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
    {
      const int type = out->GetCellType(c);
      const double v = ours->GetTuple1(c);
      if (type == VTK_HEXAHEDRON || type == VTK_TETRA)
      {
        const double ref = reference->GetTuple1(c);
        EXPECT_NEAR(v, ref, 1e-9 * std::max(1.0, std::abs(ref))) << name << " cell " << c;
        ++compared;
      }
      else if (type == VTK_WEDGE) // VTK 9.1 has no wedge measures: the library is the reference
        EXPECT_DOUBLE_EQ(v, ElementQuality(mesh, static_cast<std::size_t>(c), ByName(name))) << name << " wedge " << c;
      else
        EXPECT_TRUE(std::isnan(v)) << name << " cable " << c;
    }
  }
  EXPECT_GT(compared, 40);

  // Return parameters = library summary of the same mesh.
  const QualitySummary s = SummarizeScaledJacobian(mesh, 0.4);
  const auto ret = ReadReturnParameters(dir / "ret.txt");
  ASSERT_EQ(ret.count("minScaledJacobian"), 1u);
  EXPECT_NEAR(std::stod(ret.at("minScaledJacobian")), s.min, 1e-9 * std::max(1.0, std::abs(s.min)));
  EXPECT_NEAR(std::stod(ret.at("meanScaledJacobian")), s.mean, 1e-9);
  EXPECT_EQ(std::stoll(ret.at("belowThreshold")), static_cast<long long>(s.belowThreshold));
  EXPECT_EQ(std::stoll(ret.at("invertedElements")), static_cast<long long>(s.inverted));
  EXPECT_EQ(std::stoll(ret.at("elementCount")), static_cast<long long>(s.count));
  EXPECT_EQ(s.count, mesh.SolidElementCount());
  // The mesh exercises the counts (poor and inverted elements exist, not all are poor).
  EXPECT_GT(s.belowThreshold, 0u);
  EXPECT_LT(s.belowThreshold, s.count);
  EXPECT_GT(s.inverted, 0u);
}

TEST(QualityModule, MissingInputFailsWithOneLineAndNoOutput)
{
  const fs::path dir = TestDir("Missing");
  const RunResult r = RunModule("'" + (dir / "nope.vtu").string() + "' --outputMesh '" + (dir / "out.vtu").string() +
                                  "' --returnparameterfile '" + (dir / "ret.txt").string() + "'",
                                dir);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("nope.vtu"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.vtu"));
  EXPECT_FALSE(fs::exists(dir / "ret.txt"));
  for (const auto& entry : fs::directory_iterator(dir)) // no temporary left behind
    EXPECT_EQ(entry.path().filename().string().find("mmrep-tmp"), std::string::npos) << entry.path();
}

TEST(QualityModule, MeshWithoutSolidElementsFailsWithoutOutput)
{
  const fs::path dir = TestDir("Empty");
  FEMesh mesh;
  mesh.nodes = {Point3(0, 0, 0), Point3(1, 0, 0)};
  Element cable;
  cable.type = ElementType::Cable;
  cable.nodes[0] = 0;
  cable.nodes[1] = 1;
  mesh.elements.push_back(cable);
  WriteFEMesh(mesh, (dir / "cables.vtu").string());
  const RunResult r = RunModule("'" + (dir / "cables.vtu").string() + "' --outputMesh '" + (dir / "out.vtu").string() +
                                  "' --returnparameterfile '" + (dir / "ret.txt").string() + "'",
                                dir);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.vtu"));
  EXPECT_FALSE(fs::exists(dir / "ret.txt"));
}
} // namespace
