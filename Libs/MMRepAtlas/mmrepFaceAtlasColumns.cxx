// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Steps 3-4 of the atlas: the skin node of each grid ray, its inward through-thickness direction,
// the bone depth along it (outliers rejected) and the harmonic fill of the thickness elsewhere.
#include "mmrepFaceAtlasStages.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mmrep
{
namespace
{
// Gauss-Seidel sweeps of the harmonic fill: enough for the fill to settle on the atlas's grids.
constexpr int kHarmonicSweeps = 4000;
// Outliers: a depth is compared with the median of its (2r+1)^2 neighbourhood, with at least
// kMinimumNeighbours depths in it (fewer: too little bone around to trust it).
constexpr int kMedianRadius = 2;
constexpr std::size_t kMinimumNeighbours = 9;
// Smoothing passes (3x3 averages) of the grid's skin normals.
constexpr int kNormalSmoothingPasses = 2;

// Field value at (i, j); column -1 is the mirror image of column 1.
Eigen::Vector3d At(const std::vector<Eigen::Vector3d>& f, int cols, int i, int j)
{
  if (j < 0)
  {
    Eigen::Vector3d m = f[i * cols - j];
    m.x() = -m.x();
    return m;
  }
  return f[i * cols + j];
}

// Smoothed outward skin normal from the grid (central differences, then 3x3 averages).
std::vector<Eigen::Vector3d> SkinNormals(const std::vector<Eigen::Vector3d>& outer, int rows, int cols)
{
  std::vector<Eigen::Vector3d> normal(rows * cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
    {
      const Eigen::Vector3d dt = At(outer, cols, i, std::min(j + 1, cols - 1)) - At(outer, cols, i, j - 1);
      const Eigen::Vector3d dp = At(outer, cols, std::min(i + 1, rows - 1), j) - At(outer, cols, std::max(i - 1, 0), j);
      Eigen::Vector3d n = dt.cross(dp); // left x up = posterior... outward is anterior: flip
      n = -n.normalized();
      normal[i * cols + j] = n;
    }
  for (int pass = 0; pass < kNormalSmoothingPasses; ++pass)
  {
    std::vector<Eigen::Vector3d> s(rows * cols);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j)
      {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
          {
            const int ii = std::clamp(i + di, 0, rows - 1), jj = std::min(j + dj, cols - 1);
            sum += At(normal, cols, ii, jj);
          }
        s[i * cols + j] = sum.normalized();
      }
    normal = s;
  }
  return normal;
}

// Depths far from the median of their neighbourhood, or below the minimum thickness, become NaN.
std::vector<double> RejectOutliers(const std::vector<double>& depth, int rows, int cols,
                                   const FaceAtlasOptions& options, int& outliers)
{
  std::vector<double> accepted = depth;
  outliers = 0;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
    {
      const int q = i * cols + j;
      if (std::isnan(depth[q]))
        continue;
      std::vector<double> n;
      for (int di = -kMedianRadius; di <= kMedianRadius; ++di)
        for (int dj = -kMedianRadius; dj <= kMedianRadius; ++dj)
        {
          const int ii = i + di, jj = std::abs(j + dj);
          if (ii >= 0 && ii < rows && jj < cols && !std::isnan(depth[ii * cols + jj]))
            n.push_back(depth[ii * cols + jj]);
        }
      std::nth_element(n.begin(), n.begin() + n.size() / 2, n.end());
      if (n.size() < kMinimumNeighbours || std::abs(depth[q] - n[n.size() / 2]) > options.outlierDepth ||
          depth[q] < options.minThickness)
      {
        accepted[q] = std::numeric_limits<double>::quiet_NaN();
        ++outliers;
      }
    }
  return accepted;
}

// Harmonic fill of the thickness where bone is not followed (Gauss-Seidel, fixed order), at least
// the minimum thickness everywhere.
std::vector<double> HarmonicThickness(const std::vector<double>& accepted, int rows, int cols,
                                      const FaceAtlasOptions& options, int& boneCount)
{
  std::vector<double> thickness(rows * cols);
  double mean = 0;
  boneCount = 0;
  for (double d : accepted)
    if (!std::isnan(d))
    {
      mean += d;
      ++boneCount;
    }
  if (boneCount == 0)
    throw std::runtime_error("face atlas: no bone found under the face skin within the maximum depth");
  mean /= boneCount;
  for (int q = 0; q < rows * cols; ++q)
    thickness[q] = std::isnan(accepted[q]) ? mean : accepted[q];
  for (int it = 0; it < kHarmonicSweeps; ++it)
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j)
      {
        const int q = i * cols + j;
        if (!std::isnan(accepted[q]))
          continue;
        double sum = 0;
        int n = 0;
        const int nb[4][2] = {{i - 1, j}, {i + 1, j}, {i, std::abs(j - 1)}, {i, j + 1}};
        for (const auto& p : nb)
          if (p[0] >= 0 && p[0] < rows && p[1] < cols)
          {
            sum += thickness[p[0] * cols + p[1]];
            ++n;
          }
        thickness[q] = sum / n;
      }
  for (double& t : thickness)
    t = std::max(t, options.minThickness);
  return thickness;
}
} // namespace

std::vector<Eigen::Vector3d> FaceSkinNodes(const SurfaceRays& skin, const Eigen::Vector3d& c, const FaceGrid& grid)
{
  const int rows = grid.Rows(), cols = grid.Cols();
  std::vector<Eigen::Vector3d> outer(rows * cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
      outer[i * cols + j] = SkinHit(skin, c, grid.theta[j], grid.phi[i]).local;
  return outer;
}

FaceColumns FaceThroughThickness(std::vector<Eigen::Vector3d> outer, const SurfaceRays& bone, const FaceGrid& grid,
                                 const FaceMouthRegion& mouth, const FaceAtlasOptions& options,
                                 std::vector<std::string>& log)
{
  const int rows = grid.Rows(), cols = grid.Cols();
  FaceColumns columns;
  const std::vector<Eigen::Vector3d> normal = SkinNormals(outer, rows, cols);
  columns.dir.resize(rows * cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
    {
      const Eigen::Vector3d ray = RayDirection(grid.theta[j], grid.phi[i]);
      Eigen::Vector3d d = -(1 - options.normalBlend) * ray - options.normalBlend * normal[i * cols + j];
      if (j == 0)
        d.x() = 0; // kept in the plane
      columns.dir[i * cols + j] = d.normalized();
    }
  // Bone depth along the direction, except over the mouth (teeth, metal streaks, lips not on bone).
  std::vector<double> depth(rows * cols, std::numeric_limits<double>::quiet_NaN());
  int shallow = 0;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
    {
      const int q = i * cols + j;
      if (mouth.Ellipse(grid, i, j, mouth.lateral) <= 1.0)
        continue;
      const auto hit = bone.First(outer[q], outer[q] + options.maxBoneDepth * columns.dir[q]);
      if (hit)
        depth[q] = (*hit - outer[q]).norm();
      if (depth[q] < options.minThickness)
        ++shallow; // depth stays a measurement for the outlier medians; rejected below
    }
  int outliers = 0, boneCount = 0;
  const std::vector<double> accepted = RejectOutliers(depth, rows, cols, options, outliers);
  columns.thickness = HarmonicThickness(accepted, rows, cols, options, boneCount);
  columns.onBone.resize(rows * cols);
  for (int q = 0; q < rows * cols; ++q)
    columns.onBone[q] = std::isnan(accepted[q]) ? 0 : 1;
  columns.outer = std::move(outer);
  log.push_back(FaceAtlasLogLine("bone followed at %.0f of %.0f inner nodes (left half); %.0f depth outliers ignored",
                                 boneCount, rows * cols, outliers));
  log.push_back(FaceAtlasLogLine("%.0f bone crossings shallower than %.1f mm ignored; columns at least %.1f mm thick",
                                 shallow, options.minThickness, options.minThickness));
  return columns;
}

} // namespace mmrep
