// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Muscle inference against independent references: an analytic transform applied to the atlas
// track points directly, VTK's own point location, and a displacement field sampled from the
// same transform.
#include "mmrepDisplacementFieldMap.h"
#include "mmrepFEMeshIO.h"
#include "mmrepMuscleInference.h"

#include <vtkCell.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace mmrep;

namespace
{
const FEMesh& Atlas()
{
  static const FEMesh atlas = ReadFEMesh(std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu");
  return atlas;
}

// A smooth, invertible, non-affine map: rotation, scaling and a gentle sine bend (mm).
Point3 Bend(const Point3& x)
{
  const double c = std::cos(0.1), s = std::sin(0.1);
  Point3 y(1.05 * (c * x.x() - s * x.y()), 1.05 * (s * x.x() + c * x.y()), 0.97 * x.z());
  y.x() += 1.5 * std::sin(x.z() / 40.0);
  y.y() += 1.0 * std::sin(x.x() / 50.0);
  return y + Point3(3, -2, 5);
}

FEMesh Moved(const FEMesh& atlas)
{
  FEMesh m = atlas;
  for (auto& p : m.nodes)
    p = Bend(p);
  return m;
}

// Where the embedding puts a point, evaluated by VTK on the mesh's own cell.
Point3 EvaluateEmbedding(const FEMesh& mesh, const Embedding& e)
{
  auto grid = ToVTK(mesh);
  vtkNew<vtkGenericCell> cell;
  grid->GetCell(e.element, cell);
  double x[3], w[8];
  int sub = 0;
  double pc[3] = {e.pcoords[0], e.pcoords[1], e.pcoords[2]};
  cell->EvaluateLocation(sub, pc, x, w);
  return {x[0], x[1], x[2]};
}
} // namespace

TEST(MuscleInference, TracksFollowTheTransformAndStayEmbedded)
{
  const auto& atlas = Atlas();
  FEMesh subject = Moved(atlas);
  for (auto& [name, t] : subject.muscles) // forget the embedding: it must be recomputed
    for (auto& e : t.embedding)
      e = Embedding{};
  const auto report = InferMuscles(atlas, Bend, subject);
  EXPECT_EQ(report.muscles, atlas.muscles.size());
  std::size_t points = 0;
  for (const auto& [name, track] : atlas.muscles)
  {
    const auto& out = subject.muscles.at(name);
    ASSERT_EQ(out.nodes, track.nodes); // structure kept
    ASSERT_EQ(out.cables, track.cables);
    ASSERT_EQ(out.embedding.size(), track.nodes.size());
    for (std::size_t k = 0; k < track.nodes.size(); ++k)
    {
      const auto n = static_cast<std::size_t>(track.nodes[k]);
      EXPECT_EQ(subject.nodes[n], Bend(atlas.nodes[n])); // the transform, exactly
      // The embedding gives the point back through VTK's own interpolation.
      EXPECT_LT((EvaluateEmbedding(subject, out.embedding[k]) - subject.nodes[n]).norm(), 1e-6) << name << " " << k;
      ++points;
    }
  }
  EXPECT_EQ(report.points, points);
  // Insertions = first track points, in name order.
  ASSERT_EQ(report.insertions.size(), atlas.muscles.size());
  auto it = atlas.muscles.begin();
  for (const auto& ins : report.insertions)
  {
    EXPECT_EQ(ins.muscle, it->first);
    EXPECT_EQ(ins.subject, Bend(atlas.nodes[static_cast<std::size_t>(it->second.nodes.front())]));
    ++it;
  }
}

TEST(MuscleInference, DisplacementFieldGivesTheSamePointsWithinInterpolationError)
{
  const auto& atlas = Atlas();
  const auto field = SampleDisplacementField(Bend, atlas.nodes, 10.0, 1.0);
  const auto map = DisplacementFieldMap(field);
  FEMesh exact = Moved(atlas), sampled = Moved(atlas);
  InferMuscles(atlas, Bend, exact);
  InferMuscles(atlas, map, sampled);
  double worst = 0;
  for (const auto& [name, track] : atlas.muscles)
    for (auto n : track.nodes)
      worst =
        std::max(worst, (exact.nodes[static_cast<std::size_t>(n)] - sampled.nodes[static_cast<std::size_t>(n)]).norm());
  // Linear interpolation of a field whose second derivatives are below 1.5/40² mm⁻¹, 1 mm voxels,
  // stored in float: well under 0.01 mm.
  EXPECT_LT(worst, 0.01);
  EXPECT_THROW(map(Point3(1e4, 0, 0)), std::out_of_range);
}

TEST(MuscleInference, RejectsOtherTopologiesAndAtlasesWithoutMuscles)
{
  const auto& atlas = Atlas();
  FEMesh other = atlas;
  other.nodes.pop_back();
  EXPECT_THROW(InferMuscles(atlas, Bend, other), std::invalid_argument);
  FEMesh bare = atlas;
  bare.muscles.clear();
  FEMesh subject = atlas;
  EXPECT_THROW(InferMuscles(bare, Bend, subject), std::invalid_argument);
}
