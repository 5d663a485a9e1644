// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Tests of itk::MarchingCubesImageToMeshFilter against vtkFlyingEdges3D / vtkMarchingCubes, analytic spheres and
// topological invariants (closed 2-manifold, outward orientation).
#include "itkMarchingCubesImageToMeshFilter.h"

#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkImageRegionIteratorWithIndex.h>
#include <itkMesh.h>
#include <itkMultiThreaderBase.h>

#include <vtkFlyingEdges3D.h>
#include <vtkImageConstantPad.h>
#include <vtkImageData.h>
#include <vtkMath.h>
#include <vtkPoints.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkShortArray.h>
#include <vtkStaticPointLocator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using ShortImage = itk::Image<short, 3>;
using FloatImage = itk::Image<float, 3>;
using Mesh = itk::Mesh<float, 3>;
using ShortFilter = itk::MarchingCubesImageToMeshFilter<ShortImage, Mesh>;
using FloatFilter = itk::MarchingCubesImageToMeshFilter<FloatImage, Mesh>;
using Vec = std::array<double, 3>;

ShortImage::Pointer ReadSample(const std::string& name)
{
  auto reader = itk::ImageFileReader<ShortImage>::New();
  reader->SetFileName(std::string(MMREP_SAMPLE_DATA) + "/" + name);
  reader->Update();
  ShortImage::Pointer image = reader->GetOutput();
  image->DisconnectPipeline();
  return image;
}

// Same voxels, origin, spacing and direction as a VTK image.
vtkSmartPointer<vtkImageData> ToVtk(const ShortImage* image)
{
  const auto size = image->GetLargestPossibleRegion().GetSize();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(int(size[0]), int(size[1]), int(size[2]));
  out->SetSpacing(image->GetSpacing()[0], image->GetSpacing()[1], image->GetSpacing()[2]);
  out->SetOrigin(image->GetOrigin()[0], image->GetOrigin()[1], image->GetOrigin()[2]);
  const auto& d = image->GetDirection();
  out->SetDirectionMatrix(d[0][0], d[0][1], d[0][2], d[1][0], d[1][1], d[1][2], d[2][0], d[2][1], d[2][2]);
  vtkNew<vtkShortArray> scalars;
  scalars->SetNumberOfTuples(vtkIdType(image->GetPixelContainer()->Size()));
  std::copy_n(image->GetBufferPointer(), image->GetPixelContainer()->Size(), scalars->GetPointer(0));
  out->GetPointData()->SetScalars(scalars);
  return out;
}

template <typename TFilter, typename TImage>
Mesh::Pointer RunFilter(const TImage* image, double iso, bool pad = false, unsigned int workUnits = 0,
                        bool compact = true)
{
  auto filter = TFilter::New();
  filter->SetInput(image);
  filter->SetIsoValue(iso);
  filter->SetPadBoundary(pad);
  filter->SetCompactCells(compact);
  if (workUnits > 0)
  {
    filter->SetNumberOfWorkUnits(workUnits);
  }
  filter->Update();
  Mesh::Pointer mesh = filter->GetOutput();
  mesh->DisconnectPipeline();
  return mesh;
}

std::vector<std::array<Mesh::PointIdentifier, 3>> Triangles(const Mesh* mesh)
{
  std::vector<std::array<Mesh::PointIdentifier, 3>> out;
  out.reserve(mesh->GetNumberOfCells());
  for (auto it = mesh->GetCells()->Begin(); it != mesh->GetCells()->End(); ++it)
  {
    const Mesh::CellType* cell = it.Value();
    EXPECT_EQ(cell->GetType(), itk::CellGeometryEnum::TRIANGLE_CELL);
    EXPECT_EQ(cell->GetNumberOfPoints(), 3u);
    const auto* ids = cell->PointIdsBegin();
    out.push_back({{ids[0], ids[1], ids[2]}});
  }
  return out;
}

Vec P(const Mesh* mesh, Mesh::PointIdentifier id)
{
  const auto& p = mesh->GetPoints()->ElementAt(id);
  return {{p[0], p[1], p[2]}};
}

Vec Cross(const Vec& a, const Vec& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

Vec Sub(const Vec& a, const Vec& b)
{
  return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
}

// Closed, consistently oriented 2-manifold: every directed edge occurs once and its reverse occurs once, so
// every edge is in exactly two triangles that traverse it in opposite directions. Returns failures found.
::testing::AssertionResult IsClosedOrientedManifold(const Mesh* mesh)
{
  const auto tris = Triangles(mesh);
  std::vector<std::pair<Mesh::PointIdentifier, Mesh::PointIdentifier>> directed;
  directed.reserve(3 * tris.size());
  for (const auto& t : tris)
  {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
    {
      return ::testing::AssertionFailure() << "triangle with a repeated point";
    }
    for (int e = 0; e < 3; ++e)
    {
      directed.emplace_back(t[e], t[(e + 1) % 3]);
    }
  }
  std::sort(directed.begin(), directed.end());
  for (std::size_t n = 0; n < directed.size(); ++n)
  {
    if (n + 1 < directed.size() && directed[n] == directed[n + 1])
    {
      return ::testing::AssertionFailure() << "directed edge " << directed[n].first << "->" << directed[n].second
                                           << " used twice (non-manifold or inconsistent orientation)";
    }
    if (!std::binary_search(directed.begin(), directed.end(), std::make_pair(directed[n].second, directed[n].first)))
    {
      return ::testing::AssertionFailure()
             << "edge " << directed[n].first << "-" << directed[n].second << " is on the border (only one triangle)";
    }
  }
  return ::testing::AssertionSuccess();
}

double SignedVolume(const Mesh* mesh)
{
  double volume = 0.0;
  for (const auto& t : Triangles(mesh))
  {
    const Vec a = P(mesh, t[0]), b = P(mesh, t[1]), c = P(mesh, t[2]);
    const Vec n = Cross(b, c);
    volume += (a[0] * n[0] + a[1] * n[1] + a[2] * n[2]) / 6.0;
  }
  return volume;
}

double Area(const Mesh* mesh)
{
  double area = 0.0;
  for (const auto& t : Triangles(mesh))
  {
    const Vec n = Cross(Sub(P(mesh, t[1]), P(mesh, t[0])), Sub(P(mesh, t[2]), P(mesh, t[0])));
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return area;
}

vtkSmartPointer<vtkPolyData> ToPolyData(const Mesh* mesh)
{
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(vtkIdType(mesh->GetNumberOfPoints()));
  for (Mesh::PointIdentifier id = 0; id < mesh->GetNumberOfPoints(); ++id)
  {
    points->SetPoint(vtkIdType(id), P(mesh, id).data());
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  return out;
}

// Largest distance from a point of `from` to the nearest point of `to`.
double OneSidedDistance(vtkPolyData* from, vtkPolyData* to)
{
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  double worst = 0.0;
  for (vtkIdType id = 0; id < from->GetNumberOfPoints(); ++id)
  {
    double p[3];
    from->GetPoint(id, p);
    double q[3];
    to->GetPoint(locator->FindClosestPoint(p), q);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
  }
  return worst;
}

// Same point count and every point of either set within tol of a point of the other. (Points can coincide
// when a sample equals the iso-value, so a one-to-one matching is not required.)
void ExpectSamePoints(const Mesh* ours, vtkPolyData* theirs, double tol)
{
  ASSERT_EQ(vtkIdType(ours->GetNumberOfPoints()), theirs->GetNumberOfPoints());
  if (theirs->GetNumberOfPoints() == 0)
  {
    return;
  }
  const auto mine = ToPolyData(ours);
  EXPECT_LE(OneSidedDistance(mine, theirs), tol) << "a point of ours is not a VTK point";
  EXPECT_LE(OneSidedDistance(theirs, mine), tol) << "a VTK point is not one of ours";
}

vtkSmartPointer<vtkPolyData> FlyingEdges(vtkImageData* image, double iso)
{
  vtkNew<vtkFlyingEdges3D> fe;
  fe->SetInputData(image);
  fe->SetValue(0, iso);
  fe->ComputeNormalsOff();
  fe->ComputeGradientsOff();
  fe->ComputeScalarsOff();
  fe->Update();
  return fe->GetOutput();
}

struct CtCase
{
  const char* file;
  double iso;
};
void PrintTo(const CtCase& c, std::ostream* os)
{
  *os << c.file << " at " << c.iso;
}

class MarchingCubesVsFlyingEdges : public ::testing::TestWithParam<CtCase>
{
};

TEST_P(MarchingCubesVsFlyingEdges, SamePointsAndTriangleCount)
{
  const auto image = ReadSample(GetParam().file);
  const auto mesh = RunFilter<ShortFilter>(image.GetPointer(), GetParam().iso);
  const auto vtkImage = ToVtk(image);
  const auto fe = FlyingEdges(vtkImage, GetParam().iso);
  ASSERT_GT(fe->GetNumberOfPoints(), 1000);
  ExpectSamePoints(mesh, fe, 1e-4);
  EXPECT_EQ(vtkIdType(mesh->GetNumberOfCells()), fe->GetNumberOfPolys());
  // (vtkMarchingCubes is no exact reference: its point locator merges the coincident points produced where a
  // sample equals the iso-value, and drops the triangles that become degenerate.)
}

TEST_P(MarchingCubesVsFlyingEdges, PadBoundaryMatchesConstantPadAndIsClosed)
{
  const auto image = ReadSample(GetParam().file);
  const auto mesh = RunFilter<ShortFilter>(image.GetPointer(), GetParam().iso, true);
  // VTK reference: pad one voxel on every side with the image minimum.
  const auto vtkImage = ToVtk(image);
  double range[2];
  vtkImage->GetScalarRange(range);
  int extent[6];
  vtkImage->GetExtent(extent);
  vtkNew<vtkImageConstantPad> pad;
  pad->SetInputData(vtkImage);
  pad->SetConstant(range[0]);
  pad->SetOutputWholeExtent(extent[0] - 1, extent[1] + 1, extent[2] - 1, extent[3] + 1, extent[4] - 1, extent[5] + 1);
  pad->Update();
  vtkNew<vtkImageData> padded; // vtkImageConstantPad (VTK 9.1) drops the direction matrix
  padded->ShallowCopy(pad->GetOutput());
  padded->SetDirectionMatrix(vtkImage->GetDirectionMatrix());
  const auto fe = FlyingEdges(padded, GetParam().iso);
  ExpectSamePoints(mesh, fe, 1e-4);
  EXPECT_EQ(vtkIdType(mesh->GetNumberOfCells()), fe->GetNumberOfPolys());
  EXPECT_TRUE(IsClosedOrientedManifold(mesh));
  EXPECT_GT(SignedVolume(mesh), 0.0) << "normals must point outwards";
}

INSTANTIATE_TEST_SUITE_P(SampleCTs, MarchingCubesVsFlyingEdges,
                         ::testing::Values(CtCase{"headsq.nrrd", 500.0}, CtCase{"headsq.nrrd", 1150.0},
                                           CtCase{"cthead.nrrd", 500.0}, CtCase{"cthead.nrrd", 1300.0}),
                         [](const ::testing::TestParamInfo<CtCase>& info) {
                           return std::string(info.param.file[1] == 'e' ? "headsq" : "cthead") +
                                  std::to_string(int(info.param.iso));
                         });

// Values R - |x - c| (positive inside a sphere of radius R mm) sampled at the physical points of the voxels.
FloatImage::Pointer SphereImage(const std::array<double, 3>& spacing, double radius,
                                const FloatImage::DirectionType* direction, Vec* centre)
{
  auto image = FloatImage::New();
  FloatImage::SizeType size;
  FloatImage::SpacingType sp;
  FloatImage::PointType origin;
  for (int d = 0; d < 3; ++d)
  {
    size[d] = static_cast<itk::SizeValueType>(std::ceil(2.0 * (radius + 4.0) / spacing[d]));
    sp[d] = spacing[d];
    origin[d] = -7.0 + 3.0 * d;
  }
  image->SetRegions(size);
  image->SetSpacing(sp);
  image->SetOrigin(origin);
  if (direction)
  {
    image->SetDirection(*direction);
  }
  image->Allocate();
  // Centre: the physical point of the middle continuous index.
  itk::ContinuousIndex<double, 3> mid;
  for (int d = 0; d < 3; ++d)
  {
    mid[d] = 0.5 * double(size[d] - 1);
  }
  FloatImage::PointType c;
  image->TransformContinuousIndexToPhysicalPoint(mid, c);
  *centre = {{c[0], c[1], c[2]}};
  for (itk::ImageRegionIteratorWithIndex<FloatImage> it(image, image->GetLargestPossibleRegion()); !it.IsAtEnd(); ++it)
  {
    FloatImage::PointType p;
    image->TransformIndexToPhysicalPoint(it.GetIndex(), p);
    it.Set(static_cast<float>(radius - p.EuclideanDistanceTo(c)));
  }
  return image;
}

void ExpectSphere(const std::array<double, 3>& spacing, const FloatImage::DirectionType* direction)
{
  const double radius = 20.0;
  Vec c;
  const auto image = SphereImage(spacing, radius, direction, &c);
  const auto mesh = RunFilter<FloatFilter>(image.GetPointer(), 0.0);
  ASSERT_GT(mesh->GetNumberOfCells(), 1000u);
  EXPECT_TRUE(IsClosedOrientedManifold(mesh));
  const double pi = std::acos(-1.0);
  const double area = Area(mesh);
  const double volume = SignedVolume(mesh);
  EXPECT_NEAR(area / (4.0 * pi * radius * radius), 1.0, 0.01);
  EXPECT_NEAR(volume / (4.0 / 3.0 * pi * radius * radius * radius), 1.0, 0.01);
  // Points are in physical space: on the sphere up to the chord error of a voxel.
  const double maxSpacing = *std::max_element(spacing.begin(), spacing.end());
  double worst = 0.0;
  for (Mesh::PointIdentifier id = 0; id < mesh->GetNumberOfPoints(); ++id)
  {
    const Vec d = Sub(P(mesh, id), c);
    worst = std::max(worst, std::abs(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - radius));
  }
  EXPECT_LT(worst, 0.05 * maxSpacing) << "points must lie on the sphere in physical space";
}

TEST(MarchingCubes, SphereIsotropicAreaAndVolume)
{
  ExpectSphere({{0.7, 0.7, 0.7}}, nullptr);
}

TEST(MarchingCubes, SphereAnisotropicAreaAndVolume)
{
  ExpectSphere({{0.6, 0.75, 0.9}}, nullptr);
}

FloatImage::DirectionType Rotation(bool mirror)
{
  // Rotation about the axis (1, 2, 2)/3 by 40 degrees, optionally followed by a mirror of x.
  const double a = 40.0 * std::acos(-1.0) / 180.0;
  const Vec u{{1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0}};
  const double cs = std::cos(a), sn = std::sin(a);
  FloatImage::DirectionType r;
  const double k[3][3] = {{0, -u[2], u[1]}, {u[2], 0, -u[0]}, {-u[1], u[0], 0}};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      double kk = 0.0;
      for (int m = 0; m < 3; ++m)
      {
        kk += k[i][m] * k[m][j];
      }
      r[i][j] = (i == j ? 1.0 : 0.0) + sn * k[i][j] + (1.0 - cs) * kk;
    }
  }
  if (mirror)
  {
    for (int j = 0; j < 3; ++j)
    {
      r[0][j] = -r[0][j];
    }
  }
  return r;
}

TEST(MarchingCubes, RotatedDirectionPutsPointsAtPhysicalPoints)
{
  const auto rotation = Rotation(false);
  ExpectSphere({{0.7, 0.8, 0.9}}, &rotation);
}

TEST(MarchingCubes, MirroredDirectionKeepsOutwardNormals)
{
  const auto mirror = Rotation(true);
  ExpectSphere({{0.7, 0.8, 0.9}}, &mirror);
}

TEST(MarchingCubes, DirectionMapsIndexPointsExactly)
{
  // Same voxels with identity and rotated direction: point n of one maps to point n of the other through
  // p = origin + D (q - origin).
  const auto image = ReadSample("headsq.nrrd");
  image->SetDirection(ShortImage::DirectionType::GetIdentity());
  const auto plain = RunFilter<ShortFilter>(image.GetPointer(), 500.0);
  auto rotated = ShortImage::New();
  rotated->Graft(image);
  const auto D = Rotation(false);
  ShortImage::DirectionType direction;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      direction[i][j] = D[i][j];
    }
  }
  rotated->SetDirection(direction);
  const auto mesh = RunFilter<ShortFilter>(rotated.GetPointer(), 500.0);
  ASSERT_EQ(mesh->GetNumberOfPoints(), plain->GetNumberOfPoints());
  ASSERT_GT(mesh->GetNumberOfPoints(), 0u);
  const auto o = image->GetOrigin();
  double worst = 0.0;
  for (Mesh::PointIdentifier id = 0; id < mesh->GetNumberOfPoints(); ++id)
  {
    const Vec q = P(plain, id), p = P(mesh, id);
    for (int i = 0; i < 3; ++i)
    {
      double expected = o[i];
      for (int j = 0; j < 3; ++j)
      {
        expected += D[i][j] * (q[j] - o[j]);
      }
      worst = std::max(worst, std::abs(expected - p[i]));
    }
  }
  EXPECT_LT(worst, 1e-4);
  EXPECT_EQ(Triangles(mesh), Triangles(plain));
}

// Each of the 255 non-empty corner configurations as a 2x2x2 block in a 4x4x4 image of zeros (iso 0.5): a
// closed, outward-oriented manifold, the same points and triangle count as Flying Edges, and PadBoundary on the
// bare 2x2x2 block gives the same surface.
TEST(MarchingCubes, All256CubeCasesAreClosedManifolds)
{
  const double iso = 0.5;
  for (unsigned int code = 1; code < 256; ++code)
  {
    SCOPED_TRACE("case " + std::to_string(code));
    auto padded = ShortImage::New();
    ShortImage::SizeType size4 = {{4, 4, 4}};
    padded->SetRegions(size4);
    padded->Allocate(true);
    auto cube = ShortImage::New();
    ShortImage::SizeType size2 = {{2, 2, 2}};
    cube->SetRegions(size2);
    cube->Allocate(true);
    ShortImage::PointType origin;
    origin.Fill(1.0); // index 0 of the bare cube sits at index 1 of the padded image
    cube->SetOrigin(origin);
    for (int v = 0; v < 8; ++v)
    {
      const short value = (code >> v) & 1U ? 1 : 0;
      const ShortImage::IndexType c = {{v & 1, (v >> 1) & 1, (v >> 2) & 1}};
      cube->SetPixel(c, value);
      padded->SetPixel({{c[0] + 1, c[1] + 1, c[2] + 1}}, value);
    }
    const auto mesh = RunFilter<ShortFilter>(padded.GetPointer(), iso);
    ASSERT_GT(mesh->GetNumberOfCells(), 0u);
    EXPECT_TRUE(IsClosedOrientedManifold(mesh));
    EXPECT_GT(SignedVolume(mesh), 0.0);

    const auto fe = FlyingEdges(ToVtk(padded), iso);
    ExpectSamePoints(mesh, fe, 1e-6);
    EXPECT_EQ(vtkIdType(mesh->GetNumberOfCells()), fe->GetNumberOfPolys());

    if (code == 255)
    {
      continue; // the bare block has no value below iso, so PadBoundary pads with the lowest short instead of 0
    }
    const auto viaPad = RunFilter<ShortFilter>(cube.GetPointer(), iso, true);
    ASSERT_EQ(viaPad->GetNumberOfPoints(), mesh->GetNumberOfPoints());
    ExpectSamePoints(viaPad, fe, 1e-6);
    EXPECT_TRUE(IsClosedOrientedManifold(viaPad));
    EXPECT_NEAR(SignedVolume(viaPad), SignedVolume(mesh), 1e-9);
  }
}

TEST(MarchingCubes, TriangleNormalsPointTowardsDecreasingValues)
{
  // Linear ramp along a tilted direction g: inside (value >= iso) is where g.x is large, so every triangle
  // normal must point along -g. (The iso-value hits no sample exactly, so no triangle is degenerate.)
  auto image = FloatImage::New();
  FloatImage::SizeType size = {{12, 10, 9}};
  image->SetRegions(size);
  FloatImage::SpacingType spacing;
  spacing[0] = 0.8;
  spacing[1] = 1.1;
  spacing[2] = 1.7;
  image->SetSpacing(spacing);
  image->Allocate();
  const Vec g{{0.3, -0.5, 0.8}};
  for (itk::ImageRegionIteratorWithIndex<FloatImage> it(image, image->GetLargestPossibleRegion()); !it.IsAtEnd(); ++it)
  {
    FloatImage::PointType p;
    image->TransformIndexToPhysicalPoint(it.GetIndex(), p);
    it.Set(static_cast<float>(g[0] * p[0] + g[1] * p[1] + g[2] * p[2]));
  }
  const auto mesh = RunFilter<FloatFilter>(image.GetPointer(), 1.0371);
  ASSERT_GT(mesh->GetNumberOfCells(), 50u);
  std::size_t wrong = 0;
  for (const auto& t : Triangles(mesh))
  {
    const Vec n = Cross(Sub(P(mesh, t[1]), P(mesh, t[0])), Sub(P(mesh, t[2]), P(mesh, t[0])));
    const double along = (n[0] * g[0] + n[1] * g[1] + n[2] * g[2]) / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    wrong += along < -0.98 ? 0 : 1; // |g| = 0.99: every triangle lies in the plane g.x = iso, facing -g
  }
  EXPECT_EQ(wrong, 0u);
}

TEST(MarchingCubes, DeterministicForAnyThreadCount)
{
  const auto image = ReadSample("cthead.nrrd");
  const auto one = RunFilter<ShortFilter>(image.GetPointer(), 500.0, false, 1);
  const auto two = RunFilter<ShortFilter>(image.GetPointer(), 500.0, false, 2);
  const auto seven = RunFilter<ShortFilter>(image.GetPointer(), 500.0, false, 7);
  ASSERT_GT(one->GetNumberOfPoints(), 0u);
  for (Mesh* other : {two.GetPointer(), seven.GetPointer()})
  {
    ASSERT_EQ(one->GetNumberOfPoints(), other->GetNumberOfPoints());
    const auto& a = one->GetPoints()->CastToSTLContainer();
    const auto& b = other->GetPoints()->CastToSTLContainer();
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])));
    EXPECT_EQ(Triangles(one), Triangles(other));
  }
}

TEST(MarchingCubes, StandardCellsEqualCompactCells)
{
  const auto image = ReadSample("headsq.nrrd");
  const auto compact = RunFilter<ShortFilter>(image.GetPointer(), 1150.0, false, 0, true);
  const auto standard = RunFilter<ShortFilter>(image.GetPointer(), 1150.0, false, 0, false);
  EXPECT_EQ(Triangles(compact), Triangles(standard));
  // A compact cell behaves as a triangle: copies and boundary edges are ordinary ITK cells with its ids.
  Mesh::CellAutoPointer cell;
  ASSERT_TRUE(compact->GetCell(7, cell));
  Mesh::CellAutoPointer copy;
  cell->MakeCopy(copy);
  EXPECT_NE(dynamic_cast<itk::TriangleCell<Mesh::CellType>*>(copy.GetPointer()), nullptr);
  EXPECT_TRUE(std::equal(cell->PointIdsBegin(), cell->PointIdsEnd(), copy->PointIdsBegin()));
  EXPECT_EQ(cell->GetNumberOfBoundaryFeatures(1), 3u);
  Mesh::CellAutoPointer edge;
  ASSERT_TRUE(cell->GetBoundaryFeature(1, 0, edge));
  EXPECT_EQ(edge->GetNumberOfPoints(), 2u);
}

TEST(MarchingCubes, EmptySurfaceGivesEmptyMesh)
{
  const auto image = ReadSample("headsq.nrrd");
  const auto above = RunFilter<ShortFilter>(image.GetPointer(), 40000.0);
  EXPECT_EQ(above->GetNumberOfPoints(), 0u);
  EXPECT_EQ(above->GetNumberOfCells(), 0u);
  const auto below = RunFilter<ShortFilter>(image.GetPointer(), -40000.0);
  EXPECT_EQ(below->GetNumberOfPoints(), 0u);
  EXPECT_EQ(below->GetNumberOfCells(), 0u);
  const auto maxPlusHalf = RunFilter<ShortFilter>(image.GetPointer(), 32767.5, true);
  EXPECT_EQ(maxPlusHalf->GetNumberOfCells(), 0u);
  // A single voxel is too small for a cube, unless padded (then it is a closed octahedron around it).
  auto single = ShortImage::New();
  ShortImage::SizeType one = {{1, 1, 1}};
  single->SetRegions(one);
  single->Allocate();
  single->FillBuffer(10);
  EXPECT_EQ(RunFilter<ShortFilter>(single.GetPointer(), 5.0)->GetNumberOfCells(), 0u);
  // The image minimum (10) is inside, so the pad takes the lowest short value.
  const auto octahedron = RunFilter<ShortFilter>(single.GetPointer(), 5.0, true);
  EXPECT_EQ(octahedron->GetNumberOfPoints(), 6u);
  EXPECT_EQ(octahedron->GetNumberOfCells(), 8u);
  EXPECT_TRUE(IsClosedOrientedManifold(octahedron));
}

TEST(MarchingCubes, InvalidIsoValueThrows)
{
  const auto image = ReadSample("headsq.nrrd");
  EXPECT_THROW(RunFilter<ShortFilter>(image.GetPointer(), std::nan("")), itk::ExceptionObject);
  EXPECT_THROW(RunFilter<ShortFilter>(image.GetPointer(), -40000.0, true), itk::ExceptionObject);
}
} // namespace
