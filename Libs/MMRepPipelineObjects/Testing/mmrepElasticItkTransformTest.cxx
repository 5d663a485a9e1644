// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// ElasticItkTransform used as ITK uses transforms: point by point equal to the project's maps,
// composed in itk::CompositeTransform, applied to a mesh by itk::TransformMeshFilter and to an
// image by itk::ResampleImageFilter, vectors through the exact Jacobian.
#include "mmrepElasticItkTransform.h"
#include "mmrepItkSimilarity.h"

#include <gtest/gtest.h>

#include <itkCompositeTransform.h>
#include <itkDefaultStaticMeshTraits.h>
#include <itkImage.h>
#include <itkImageRegionIteratorWithIndex.h>
#include <itkLinearInterpolateImageFunction.h>
#include <itkMesh.h>
#include <itkResampleImageFilter.h>
#include <itkSimilarity3DTransform.h>
#include <itkTransformMeshFilter.h>

#include <random>

namespace
{
using mmrep::ElasticTransform;
using Point = itk::Point<double, 3>;

// A map with steps on two levels of a grid over [-40, 40]^3 (amplitudes below the non-folding bound)
// and a pre-alignment; `seed` varies the steps.
ElasticTransform SomeElasticMap(unsigned seed, double scale)
{
  ElasticTransform t;
  t.preLinear = scale * Eigen::AngleAxisd(0.1, Eigen::Vector3d(0, 0, 1)).toRotationMatrix();
  t.preTranslation = Eigen::Vector3d(1.5, -2, 0.5);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int l = 1; l <= 2; ++l)
  {
    mmrep::ElasticLevel level;
    level.level = l;
    level.cells = 2 << l;
    level.boxMin = Eigen::Vector3d(-40, -40, -40);
    level.h = Eigen::Vector3d::Constant(80.0 / level.cells);
    const double bound = 0.4 / mmrep::MaximumBumpGradient(level.h);
    for (int s = 0; s < 40; ++s)
    {
      std::uniform_int_distribution<int> node(1, level.cells - 1);
      mmrep::ElasticStep step;
      step.node = level.boxMin + Eigen::Vector3d(node(rng), node(rng), node(rng)).cwiseProduct(level.h);
      step.delta = bound * Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
      level.steps.push_back(step);
    }
    t.levels.push_back(level);
  }
  t.BuildIndex();
  return t;
}

Point P(const Eigen::Vector3d& x)
{
  return Point(x.data());
}
Eigen::Vector3d E(const Point& p)
{
  return {p[0], p[1], p[2]};
}

class ElasticItkTransformTest : public ::testing::Test
{
protected:
  ElasticTransform r = SomeElasticMap(1, 1.02), q = SomeElasticMap(2, 1.0);
  mmrep::ElasticItkTransform::Pointer qr = mmrep::ElasticItkTransform::New();
  void SetUp() override { qr->SetElasticTransforms({r, q}); }
  std::vector<Eigen::Vector3d> Sample(int n) const
  {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-30, 30);
    std::vector<Eigen::Vector3d> xs;
    for (int k = 0; k < n; ++k)
      xs.emplace_back(u(rng), u(rng), u(rng));
    return xs;
  }
};

TEST_F(ElasticItkTransformTest, PointsAreExactlyTheComposedMaps)
{
  int moved = 0;
  for (const auto& x : Sample(2000))
  {
    const Eigen::Vector3d expected = q.Apply(r.Apply(x));
    ASSERT_EQ(E(qr->TransformPoint(P(x))), expected); // bit for bit
    moved += (expected - q.PreApply(r.PreApply(x))).norm() > 1e-3;
  }
  EXPECT_GT(moved, 500); // the elastic steps act on the sample
  EXPECT_EQ(qr->GetNumberOfParameters(), 0u);
}

TEST_F(ElasticItkTransformTest, ComposesInCompositeTransformWithASimilarity)
{
  auto similarity = itk::Similarity3DTransform<double>::New();
  similarity->SetScale(1.1);
  itk::Similarity3DTransform<double>::OutputVectorType shift;
  shift[0] = 2;
  shift[1] = -1;
  shift[2] = 3;
  similarity->SetTranslation(shift);
  auto composite = itk::CompositeTransform<double, 3>::New();
  composite->AddTransform(similarity); // applied last (ITK applies the last added first)
  composite->AddTransform(qr);
  for (const auto& x : Sample(200))
  {
    const Point expected = similarity->TransformPoint(qr->TransformPoint(P(x)));
    const Point actual = composite->TransformPoint(P(x));
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(actual[a], expected[a]);
  }
}

TEST(ItkSimilarity, MapsPointsAsTheProjectsSimilarity)
{
  mmrep::SimilarityTransform s;
  s.rotation = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  s.scale = 1.07;
  s.translation = Eigen::Vector3d(4, -3, 12);
  const auto itkSimilarity = mmrep::ToItkSimilarity(s);
  EXPECT_NEAR(itkSimilarity->GetScale(), 1.07, 1e-14);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-80, 80);
  for (int k = 0; k < 100; ++k)
  {
    const Eigen::Vector3d x(u(rng), u(rng), u(rng));
    EXPECT_LT((E(itkSimilarity->TransformPoint(P(x))) - s.Apply(x)).norm(), 1e-11);
  }
}

TEST_F(ElasticItkTransformTest, VectorsGoThroughTheJacobianOfTheComposition)
{
  double worst = 0;
  for (const auto& x : Sample(100))
  {
    itk::Vector<double, 3> v;
    v[0] = 0.3;
    v[1] = -0.5;
    v[2] = 0.8;
    const auto tv = qr->TransformVector(v, P(x));
    // Central differences of the composed map along v.
    const double h = 1e-5;
    const Eigen::Vector3d ev(v[0], v[1], v[2]);
    const Eigen::Vector3d fd = (q.Apply(r.Apply(x + h * ev)) - q.Apply(r.Apply(x - h * ev))) / (2 * h);
    worst = std::max(worst, (E(Point(tv.GetDataPointer())) - fd).cwiseAbs().maxCoeff());
    // Covariant vectors (normals) stay orthogonal to transformed tangents.
    itk::CovariantVector<double, 3> n;
    n[0] = 0.8;
    n[1] = 0.0;
    n[2] = -0.3; // orthogonal to v
    const auto tn = qr->TransformCovariantVector(n, P(x));
    EXPECT_NEAR(tn[0] * tv[0] + tn[1] * tv[1] + tn[2] * tv[2], 0.0, 1e-12);
  }
  EXPECT_LT(worst, 1e-6);
}

TEST_F(ElasticItkTransformTest, TransformMeshFilterMovesEveryPoint)
{
  using Mesh =
    itk::Mesh<double, 3, itk::DefaultStaticMeshTraits<double, 3, 3, double, double, double>>; // double points
  auto mesh = Mesh::New();
  const auto xs = Sample(300);
  for (std::size_t i = 0; i < xs.size(); ++i)
    mesh->SetPoint(i, P(xs[i]));
  auto filter = itk::TransformMeshFilter<Mesh, Mesh, itk::Transform<double, 3, 3>>::New();
  filter->SetInput(mesh);
  filter->SetTransform(qr);
  filter->Update();
  ASSERT_EQ(filter->GetOutput()->GetNumberOfPoints(), xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i)
    ASSERT_EQ(E(filter->GetOutput()->GetPoint(i)), q.Apply(r.Apply(xs[i])));
}

TEST_F(ElasticItkTransformTest, ResampleImageFilterSamplesTheInputAtTheMappedPoints)
{
  // A linear intensity f(x) = a·x + b: linear interpolation reproduces it exactly, so every output
  // voxel must hold f(Q(R(x))) for its own physical point x.
  using Image = itk::Image<double, 3>;
  auto input = Image::New();
  Image::SizeType size;
  size.Fill(61);
  input->SetRegions(Image::RegionType(size));
  double origin[3] = {-60, -60, -60}, spacing[3] = {2, 2, 2};
  input->SetOrigin(origin);
  input->SetSpacing(spacing);
  input->Allocate();
  const Eigen::Vector3d a(0.7, -1.3, 2.1);
  const double b = 5;
  for (itk::ImageRegionIteratorWithIndex<Image> it(input, input->GetLargestPossibleRegion()); !it.IsAtEnd(); ++it)
  {
    Point p;
    input->TransformIndexToPhysicalPoint(it.GetIndex(), p);
    it.Set(a.dot(E(p)) + b);
  }
  auto resample = itk::ResampleImageFilter<Image, Image>::New();
  resample->SetInput(input);
  resample->SetTransform(qr);
  resample->SetInterpolator(itk::LinearInterpolateImageFunction<Image, double>::New());
  Image::SizeType outSize;
  outSize.Fill(21);
  resample->SetSize(outSize);
  double outOrigin[3] = {-20, -20, -20};
  resample->SetOutputOrigin(outOrigin);
  resample->SetOutputSpacing(spacing);
  resample->SetDefaultPixelValue(-1e9);
  resample->Update();
  double worst = 0;
  for (itk::ImageRegionIteratorWithIndex<Image> it(resample->GetOutput(),
                                                   resample->GetOutput()->GetLargestPossibleRegion());
       !it.IsAtEnd(); ++it)
  {
    Point x;
    resample->GetOutput()->TransformIndexToPhysicalPoint(it.GetIndex(), x);
    worst = std::max(worst, std::abs(it.Get() - (a.dot(q.Apply(r.Apply(E(x)))) + b)));
  }
  EXPECT_LT(worst, 1e-9);
}

} // namespace
