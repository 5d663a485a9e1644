// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Registration of a synthetic symmetric atlas onto a subject warped by a known map: accuracy,
// non-folding, exact symmetry, the displacement field, and the local refinement.
#include "mmrepAtlasRegistration.h"
#include "mmrepElasticTestData.h"
#include "mmrepJacobianSampling.h"
#include "mmrepMeshQuality.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <itkVectorLinearInterpolateImageFunction.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <map>
#include <random>
#include <sstream>

using namespace mmrep;
using namespace mmrep::elastictest;

namespace
{
struct Shared
{
  SyntheticAtlas atlas;
  Truth truth;
  SubjectData subject;
  AtlasRegistrationResult registration;
  LocalRefinementResult refinement;
};

Shared& Data()
{
  static std::unique_ptr<Shared> d;
  if (!d)
  {
    d = std::make_unique<Shared>();
    d->atlas = MakeAtlas();
    d->subject.skin = MakeSurface(SkinRadii(), d->truth);
    d->subject.skull = MakeSurface(SkullRadii(), d->truth);
    d->subject.controlPoints = SubjectControlPoints(d->atlas.mesh, d->truth);
    d->subject.plane = d->truth.SubjectPlane();
    AtlasRegistrationOptions o;
    d->registration = RegisterAtlas(d->atlas.mesh, d->atlas.plane, d->subject, o);
    LocalRefinementOptions q;
    q.symmetric = true;
    q.plane = d->subject.plane;
    d->refinement = RefineLocally(d->registration.mesh, d->subject.skin, q);
    std::cout << d->registration.report.ToJson() << std::endl;
    std::cout << "refinement: lips mean " << d->refinement.before.lips.mean << " -> " << d->refinement.after.lips.mean
              << " max " << d->refinement.before.lips.max << " -> " << d->refinement.after.lips.max << " ("
              << d->refinement.after.seconds << " s, steps";
    for (auto s : d->refinement.after.stepsPerLevel)
      std::cout << " " << s;
    std::cout << ")" << std::endl;
  }
  return *d;
}

double RelativeScale(const FEMesh& m)
{
  double r = 0;
  for (const auto& n : m.nodes)
    r = std::max(r, n.norm());
  return r;
}
} // namespace

TEST(ElasticRegistration, SyntheticSubjectIsMatched)
{
  const auto& d = Data();
  const auto& r = d.registration.report;
  const auto& sim = r.stages.front();
  const auto& last = r.Last();
  EXPECT_LT(last.skin.mean, 0.3);
  EXPECT_LT(last.skull.mean, 0.3);
  EXPECT_LT(last.controlMean, 0.5);
  EXPECT_LT(last.skin.mean, 0.2 * sim.skin.mean); // the elastic stage does the work
  // Node error against the known truth T(a) (correspondence, not only surface distance).
  double truthMean = 0, truthMax = 0, simTruthMean = 0;
  const auto& skin = d.atlas.mesh.nodeSets.at("skin");
  for (auto id : skin)
  {
    const Eigen::Vector3d truth = d.truth(d.atlas.mesh.nodes[id]);
    const double e = (d.registration.mesh.nodes[id] - truth).norm();
    truthMean += e / skin.size();
    truthMax = std::max(truthMax, e);
    simTruthMean += (d.registration.transform.PreApply(d.atlas.mesh.nodes[id]) - truth).norm() / skin.size();
  }
  std::cout << "skin node error vs truth: mean " << truthMean << " max " << truthMax
            << " mm (similarity only: " << simTruthMean << " mm)" << std::endl;
  // Surface distances say nothing about sliding along the surface: the distance to the true
  // corresponding point must drop too (the control points fix the correspondence locally).
  EXPECT_LT(truthMean, simTruthMean);
  // The result is what the transform gives (tracked points = replay).
  for (std::size_t i = 0; i < d.atlas.mesh.nodes.size(); i += 7)
    ASSERT_EQ(d.registration.mesh.nodes[i], d.registration.transform.Apply(d.atlas.mesh.nodes[i]));
}

TEST(ElasticRegistration, JacobianIsPositiveEverywhereInTheGrid)
{
  const auto& t = Data().registration.transform;
  ASSERT_FALSE(t.levels.empty());
  // 40³ samples over the grid box (frame), mapped back to atlas space through the similarity.
  const double minDet = mmrep::testing::MinimumJacobianDeterminantOverGrid(t, 40);
  std::cout << "min det J of the elastic part over the grid: " << minDet << std::endl;
  EXPECT_GT(minDet, 0.0);
}

TEST(ElasticRegistration, OutputIsSymmetricAboutTheSubjectPlane)
{
  const auto& d = Data();
  const double scale = RelativeScale(d.registration.mesh);
  double worst = 0;
  for (const auto& [a, b] : d.atlas.mirrorPairs)
  {
    const Eigen::Vector3d pa = d.registration.mesh.nodes[a], pb = d.registration.mesh.nodes[b];
    worst = std::max(worst, (d.subject.plane.Mirror(pa) - pb).norm());
  }
  for (auto id : d.atlas.mesh.nodeSets.at("midsagittal"))
    worst = std::max(worst, std::abs(d.subject.plane.SignedDistance(d.registration.mesh.nodes[id])));
  std::cout << "symmetry error " << worst << " mm (relative " << worst / scale << ")" << std::endl;
  EXPECT_LT(worst / scale, 1e-9);
  // Same after the symmetric refinement.
  worst = 0;
  for (const auto& [a, b] : d.atlas.mirrorPairs)
    worst = std::max(worst, (d.subject.plane.Mirror(d.refinement.mesh.nodes[a]) - d.refinement.mesh.nodes[b]).norm());
  EXPECT_LT(worst / scale, 1e-9);
}

namespace
{
// Max |x + u(x) − R(x)| at random points of a 12 mm cube in front of the lips (where the map bends
// most), u trilinearly interpolated (ITK) from the field sampled with `spacing`; also the largest
// error at the grid points themselves (float storage only) and the largest |u|.
struct FieldCheck
{
  double between = 0, atNodes = 0, largest = 0;
};
FieldCheck CheckField(const ElasticTransform& t, double spacing)
{
  const Eigen::Vector3d origin(-12, -100, -42);
  auto grid = itk::Image<float, 3>::New();
  itk::Image<float, 3>::RegionType region;
  const auto n = static_cast<itk::SizeValueType>(std::lround(12 / spacing)) + 1;
  region.SetSize({{n, n, n}});
  grid->SetRegions(region);
  grid->SetOrigin(itk::Image<float, 3>::PointType(origin.data()));
  grid->SetSpacing(spacing);
  const auto field = t.ToDisplacementField(grid);
  auto interp = itk::VectorLinearInterpolateImageFunction<DisplacementField, double>::New();
  interp->SetInputImage(field);
  FieldCheck c;
  auto error = [&](const Eigen::Vector3d& x) {
    DisplacementField::PointType p;
    for (int a = 0; a < 3; ++a)
      p[a] = x[a];
    const auto v = interp->Evaluate(p);
    const Eigen::Vector3d u(v[0], v[1], v[2]);
    c.largest = std::max(c.largest, u.norm());
    return (x + u - t.Apply(x)).norm();
  };
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(0.01, 11.99);
  for (int k = 0; k < 1000; ++k)
    c.between = std::max(c.between, error(origin + Eigen::Vector3d(unit(rng), unit(rng), unit(rng))));
  for (int k = 0; k < 200; ++k)
  {
    std::uniform_int_distribution<int> idx(0, static_cast<int>(n) - 1);
    c.atNodes = std::max(c.atNodes, error(origin + spacing * Eigen::Vector3d(idx(rng), idx(rng), idx(rng))));
  }
  return c;
}
} // namespace

TEST(ElasticRegistration, DisplacementFieldReproducesTheTransform)
{
  const auto& t = Data().registration.transform;
  const auto coarse = CheckField(t, 1.0), fine = CheckField(t, 0.5);
  std::cout << "displacement field vs transform: 1 mm grid " << coarse.between << " mm, 0.5 mm grid " << fine.between
            << " mm, at grid points " << fine.atNodes << " mm (|u| up to " << fine.largest << " mm)" << std::endl;
  EXPECT_GT(fine.largest, 1.0);
  EXPECT_LT(fine.atNodes, 1e-4);                 // float storage of u
  EXPECT_LT(fine.between, 0.1);                  // interpolation accuracy at 0.5 mm …
  EXPECT_LT(fine.between, 0.5 * coarse.between); // … and it converges (trilinear: O(spacing²))
}

TEST(ElasticRefinement, LipsErrorDropsAndOutsideIsUntouched)
{
  const auto& d = Data();
  const auto& q = d.refinement;
  EXPECT_LT(q.after.lips.mean, q.before.lips.mean);
  EXPECT_LE(q.after.lips.mean, 0.05);
  EXPECT_LE(q.after.lips.max, 0.15);
  EXPECT_LE(q.after.skin.mean, q.before.skin.mean);
  std::size_t outside = 0, inside = 0;
  for (std::size_t i = 0; i < d.registration.mesh.nodes.size(); ++i)
  {
    const Eigen::Vector3d f = q.transform.ToFrame(d.registration.mesh.nodes[i]);
    const bool in = (f.array() > q.boxMin.array()).all() && (f.array() < q.boxMax.array()).all();
    if (!in)
    {
      ++outside;
      ASSERT_EQ(q.mesh.nodes[i], d.registration.mesh.nodes[i]) << i; // bit for bit
    }
    else
      inside += q.mesh.nodes[i] != d.registration.mesh.nodes[i] ? 1 : 0;
  }
  EXPECT_GT(outside, d.registration.mesh.nodes.size() / 2);
  EXPECT_GT(inside, 20u);
  // Q does not fold: det J > 0 sampled over its box.
  double minDet = 1e9;
  const int n = 30;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
      {
        const Eigen::Vector3d f =
          q.boxMin + (q.boxMax - q.boxMin).cwiseProduct(Eigen::Vector3d((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n));
        minDet = std::min(minDet, q.transform.Jacobian(q.transform.ToWorld(f)).determinant());
      }
  EXPECT_GT(minDet, 0.0);
}

TEST(ElasticRegistration, IsDeterministic)
{
  const auto& d = Data();
  const auto again = RegisterAtlas(d.atlas.mesh, d.atlas.plane, d.subject, {});
  ASSERT_EQ(again.transform.StepsPerLevel(), d.registration.transform.StepsPerLevel());
  for (std::size_t i = 0; i < d.atlas.mesh.nodes.size(); ++i)
    ASSERT_EQ(again.mesh.nodes[i], d.registration.mesh.nodes[i]) << i; // same bytes
}

TEST(ElasticRegistration, BadInputIsRejectedWithAClearMessage)
{
  const auto& d = Data();
  SubjectData s = d.subject;
  s.controlPoints[2].name = "Nose";
  try
  {
    RegisterAtlas(d.atlas.mesh, d.atlas.plane, s, {});
    FAIL() << "mismatched names accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("LeftLipCorner"), std::string::npos) << e.what();
  }
  s = d.subject;
  s.skin = vtkSmartPointer<vtkPolyData>::New();
  EXPECT_THROW(RegisterAtlas(d.atlas.mesh, d.atlas.plane, s, {}), std::runtime_error);
  s = d.subject;
  for (auto& c : s.controlPoints)
    c.position += Eigen::Vector3d(0, 0, 1000); // the surfaces stay where they were
  try
  {
    RegisterAtlas(d.atlas.mesh, d.atlas.plane, s, {});
    FAIL() << "non-overlapping input accepted";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("do not overlap"), std::string::npos) << e.what();
  }
}

// The Markdown report holds one table row per stage with the same figures as the stages (3
// decimals), "—" where a stage measured nothing, and one row per control point.
TEST(ElasticReport, MarkdownTableMatchesTheStages)
{
  const auto& d = Data();
  RegistrationReport report = d.registration.report;
  AddRefinementStage(report, d.refinement, d.subject.controlPoints);
  const std::string md = report.ToMarkdown("Synthetic");
  std::istringstream lines(md);
  std::map<std::string, std::vector<std::string>> rows;
  for (std::string line; std::getline(lines, line);)
  {
    if (line.size() < 2 || line[0] != '|' || line[1] == '-')
      continue;
    std::vector<std::string> cells;
    std::istringstream cellStream(line.substr(1));
    for (std::string cell; std::getline(cellStream, cell, '|');)
      cells.push_back(
        cell.substr(cell.find_first_not_of(' '), cell.find_last_not_of(' ') - cell.find_first_not_of(' ') + 1));
    rows[cells[0]] = cells;
  }
  auto fmt = [](double v) {
    char b[32];
    std::snprintf(b, sizeof(b), "%.3f", v);
    return std::string(b);
  };
  ASSERT_TRUE(rows.count("similarity") && rows.count("elastic") && rows.count("distance maps") &&
              rows.count("refinement (Q∘R)"))
    << md;
  for (const char* name : {"similarity", "elastic"})
  {
    const auto& st =
      *std::find_if(report.stages.begin(), report.stages.end(), [&](const auto& s) { return s.name == name; });
    const auto& r = rows[name];
    ASSERT_EQ(r.size(), 14u) << md;
    EXPECT_EQ(r[1], fmt(st.skin.mean));
    EXPECT_EQ(r[2], fmt(st.skin.max));
    EXPECT_EQ(r[3], fmt(st.skin.sigma));
    EXPECT_EQ(r[4], fmt(st.skull.mean));
    EXPECT_EQ(r[7], fmt(st.lips.mean));
    EXPECT_EQ(r[10], fmt(st.controlMean));
    EXPECT_EQ(r[11], fmt(st.controlMax));
  }
  EXPECT_EQ(rows["distance maps"][1], "—");
  EXPECT_EQ(rows["distance maps"][10], "—");
  // Refinement row: lips after Q (all lips nodes that are skin nodes), control points recomputed.
  EXPECT_EQ(rows["refinement (Q∘R)"][7], fmt(d.refinement.after.lips.mean));
  EXPECT_EQ(rows["refinement (Q∘R)"][8], fmt(d.refinement.after.lips.max));
  EXPECT_NE(rows["refinement (Q∘R)"][10], "—");
  for (const auto& name : report.controlNames)
    EXPECT_TRUE(rows.count(name)) << name;
  // Q's own report: before / after rows, no control points.
  const std::string q = d.refinement.Report().ToMarkdown("Q");
  EXPECT_NE(q.find("| Q∘R | " + fmt(d.refinement.after.skin.mean)), std::string::npos) << q;
}

// The mesh guard: with it, no hexahedron of R's or Q∘R's mesh ends below the floor (quality
// measured independently of the optimiser's bookkeeping). The floor is set between the atlas's
// worst element and what the unguarded registration leaves, so the guard has to act.
TEST(ElasticRegistration, MeshGuardKeepsEveryElementAboveTheFloor)
{
  const auto& d = Data();
  for (const FEMesh* mesh : {&d.registration.mesh, &d.refinement.mesh})
  {
    const auto q = quality::SummarizeScaledJacobian(*mesh, AtlasRegistrationOptions{}.elementQualityFloor);
    EXPECT_EQ(q.inverted, 0u);
    EXPECT_GE(q.min, AtlasRegistrationOptions{}.elementQualityFloor - 1e-12);
  }
  AtlasRegistrationOptions unguarded;
  unguarded.elementQualityFloor = -1;
  const auto free = RegisterAtlas(d.atlas.mesh, d.atlas.plane, d.subject, unguarded);
  const double atlasMin = quality::SummarizeScaledJacobian(d.atlas.mesh, 0.3).min;
  const double freeMin = quality::SummarizeScaledJacobian(free.mesh, 0.3).min;
  ASSERT_LT(freeMin, atlasMin - 0.01) << "the unguarded registration should lower the worst element";
  AtlasRegistrationOptions guarded;
  guarded.elementQualityFloor = 0.5 * (atlasMin + freeMin);
  const auto r = RegisterAtlas(d.atlas.mesh, d.atlas.plane, d.subject, guarded);
  const double guardedMin = quality::SummarizeScaledJacobian(r.mesh, 0.3).min;
  std::cout << "worst scaled Jacobian: atlas " << atlasMin << ", unguarded R " << freeMin << ", R guarded at "
            << guarded.elementQualityFloor << ": " << guardedMin << "; skin mean " << free.report.Last().skin.mean
            << " -> " << r.report.Last().skin.mean << " mm" << std::endl;
  EXPECT_GE(guardedMin, guarded.elementQualityFloor - 1e-12);
  EXPECT_LT(r.report.Last().skin.mean, 0.3); // still a fit
}

// The tie: tying the attracted nodes to their start trades surface fit for correspondence, so the
// node error against the known truth must not grow while the surface error may.
TEST(ElasticRegistration, TieKeepsCorrespondenceAtSomeSurfaceCost)
{
  const auto& d = Data();
  auto truthError = [&](const FEMesh& mesh) {
    double sum = 0;
    const auto& skin = d.atlas.mesh.nodeSets.at("skin");
    for (auto id : skin)
      sum += (mesh.nodes[id] - d.truth(d.atlas.mesh.nodes[id])).norm();
    return sum / skin.size();
  };
  AtlasRegistrationOptions tied;
  tied.tieWeight = 0.1;
  const auto r = RegisterAtlas(d.atlas.mesh, d.atlas.plane, d.subject, tied);
  std::cout << "skin node error vs truth: free " << truthError(d.registration.mesh) << ", tied " << truthError(r.mesh)
            << " mm; skin mean " << d.registration.report.Last().skin.mean << " -> " << r.report.Last().skin.mean
            << " mm" << std::endl;
  EXPECT_LE(truthError(r.mesh), truthError(d.registration.mesh));
  EXPECT_GE(r.report.Last().skin.mean, d.registration.report.Last().skin.mean - 1e-9);
  EXPECT_LT(r.report.Last().skin.mean, 0.5);
}
