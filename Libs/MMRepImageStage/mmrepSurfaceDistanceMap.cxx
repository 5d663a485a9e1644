// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepSurfaceDistanceMap.h"

#include "itkSaitoToriwakiDistanceMapImageFilter.h"
#include "mmrepPointTriangleDistance.h"

#include <Eigen/Geometry>

#include <itkMultiThreaderBase.h>
#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <vector>

namespace mmrep
{

namespace
{
struct Triangle
{
  Eigen::Vector3d a, b, c;
  vtkIdType ids[3];
};
// Pseudo-normals of a triangle's features (signed mode): vertices A, B, C, edges AB, AC, BC, face.
using FeatureNormals = std::array<Eigen::Vector3d, 7>;

// Angle-weighted vertex normals, edge normals (sum of the two faces) and face normals: with them,
// the sign of (p - closest) · normal of the closest feature tells inside from outside exactly on
// a closed manifold (Bærentzen & Aanæs, IEEE TVCG 11(3), 2005).
std::vector<FeatureNormals> ComputePseudoNormals(const std::vector<Triangle>& triangles, vtkIdType pointCount)
{
  std::vector<FeatureNormals> normals(triangles.size());
  std::vector<Eigen::Vector3d> vertex(pointCount, Eigen::Vector3d::Zero());
  std::map<std::pair<vtkIdType, vtkIdType>, std::pair<Eigen::Vector3d, int>> edge;
  auto key = [](vtkIdType u, vtkIdType v) { return std::make_pair(std::min(u, v), std::max(u, v)); };
  double volume6 = 0;
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    const auto& t = triangles[i];
    const Eigen::Vector3d* p[3] = {&t.a, &t.b, &t.c};
    Eigen::Vector3d n = (t.b - t.a).cross(t.c - t.a);
    volume6 += t.a.dot((t.b).cross(t.c));
    const double len = n.norm();
    n = len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
    normals[i][6] = n;
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d e1 = *p[(k + 1) % 3] - *p[k], e2 = *p[(k + 2) % 3] - *p[k];
      const double l1 = e1.norm(), l2 = e2.norm();
      const double angle = l1 > 0 && l2 > 0 ? std::acos(std::max(-1.0, std::min(1.0, e1.dot(e2) / (l1 * l2)))) : 0;
      vertex[t.ids[k]] += angle * n;
    }
    for (auto [u, v] : {std::make_pair(0, 1), std::make_pair(0, 2), std::make_pair(1, 2)})
    {
      // Eigen vectors are not zero-initialised: start each new edge's sum explicitly.
      auto& e = edge.try_emplace(key(t.ids[u], t.ids[v]), Eigen::Vector3d::Zero(), 0).first->second;
      e.first += n;
      e.second += 1;
    }
  }
  std::size_t open = 0;
  for (const auto& [k, e] : edge)
    open += e.second != 2;
  if (open > 0)
    throw std::runtime_error("distance map: a signed distance needs a closed surface, this one has " +
                             std::to_string(open) + " open or non-manifold edges");
  const double orientation = volume6 < 0 ? -1.0 : 1.0; // normals must point outward
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    const auto& t = triangles[i];
    for (int k = 0; k < 3; ++k)
      normals[i][k] = orientation * vertex[t.ids[k]];
    normals[i][3] = orientation * edge[key(t.ids[0], t.ids[1])].first;
    normals[i][4] = orientation * edge[key(t.ids[0], t.ids[2])].first;
    normals[i][5] = orientation * edge[key(t.ids[1], t.ids[2])].first;
    normals[i][6] *= orientation;
  }
  return normals;
}

std::vector<Triangle> Triangles(vtkPolyData* surface, std::vector<FeatureNormals>* normals)
{
  vtkNew<vtkTriangleFilter> tri; // polygons and strips become triangles; lines and vertices dropped
  tri->SetInputData(surface);
  tri->PassLinesOff();
  tri->PassVertsOff();
  tri->Update();
  vtkPolyData* t = tri->GetOutput();
  std::vector<Triangle> out;
  out.reserve(t->GetNumberOfPolys());
  vtkNew<vtkIdList> ids;
  auto* polys = t->GetPolys();
  polys->InitTraversal();
  while (polys->GetNextCell(ids))
  {
    if (ids->GetNumberOfIds() != 3)
      continue;
    Triangle tr;
    for (int k = 0; k < 3; ++k)
      tr.ids[k] = ids->GetId(k);
    t->GetPoint(tr.ids[0], tr.a.data());
    t->GetPoint(tr.ids[1], tr.b.data());
    t->GetPoint(tr.ids[2], tr.c.data());
    out.push_back(tr);
  }
  if (normals)
    *normals = ComputePseudoNormals(out, t->GetNumberOfPoints());
  return out;
}
} // namespace

std::array<double, 3> CheckDistanceMapGrid(const std::array<double, 6>& box, double margin, double spacing,
                                           const std::string& parameter)
{
  constexpr double most = 512.0 * 512.0 * 512.0;
  std::array<double, 3> counts{};
  double voxels = 1;
  for (unsigned a = 0; a < 3; ++a)
  {
    counts[a] = std::ceil((box[2 * a + 1] - box[2 * a] + 2 * margin) / spacing) + 1;
    voxels *= counts[a];
  }
  if (!(voxels <= most))
  {
    char text[320];
    std::snprintf(text, sizeof text,
                  "%s %g: the distance map over %.0f x %.0f x %.0f mm would have %.0f million voxels, more than a map "
                  "may have (512^3 = 134 million); use a spacing of about %.2g mm or more",
                  parameter.c_str(), spacing, box[1] - box[0] + 2 * margin, box[3] - box[2] + 2 * margin,
                  box[5] - box[4] + 2 * margin, std::isfinite(voxels) ? voxels / 1e6 : 1e300,
                  std::max(spacing, std::cbrt((box[1] - box[0] + 2 * margin) * (box[3] - box[2] + 2 * margin) *
                                              (box[5] - box[4] + 2 * margin) / most)) *
                    1.01);
    throw std::runtime_error(text);
  }
  return counts;
}

namespace
{
// The map's grid: over the region (or the surface's bounds) plus the margin, aligned with LPS axes.
FloatImage::Pointer DistanceMapGrid(vtkPolyData* surface, const SurfaceDistanceMapOptions& o)
{
  std::array<double, 6> box = o.region;
  if (!(box[0] <= box[1] && box[2] <= box[3] && box[4] <= box[5]))
    surface->GetBounds(box.data());
  const auto counts = CheckDistanceMapGrid(box, o.margin, o.spacing, "distance map: spacing");
  FloatImage::SizeType size;
  FloatImage::PointType origin;
  FloatImage::SpacingType spacing;
  for (unsigned a = 0; a < 3; ++a)
  {
    origin[a] = box[2 * a] - o.margin;
    size[a] = static_cast<itk::SizeValueType>(counts[a]);
    spacing[a] = o.spacing;
  }

  auto map = FloatImage::New();
  FloatImage::RegionType region;
  region.SetSize(size);
  map->SetRegions(region);
  map->SetOrigin(origin);
  map->SetSpacing(spacing);
  map->Allocate();
  return map;
}

// Squared distances to the surface (and signs) of the voxels within `exactBand` voxels of it.
void ExactBand(const std::vector<Triangle>& triangles, const std::vector<FeatureNormals>& normals,
               const FloatImage* map, double exactBand, std::vector<double>& exact, std::vector<signed char>& sign)
{
  const auto size = map->GetLargestPossibleRegion().GetSize();
  const auto origin = map->GetOrigin();
  const std::size_t nx = size[0], ny = size[1], nz = size[2];
  const double h = map->GetSpacing()[0], band = exactBand * h;
  // Exact band: each triangle visits the voxels of its bounding box grown by the band. Work is
  // split into z-slabs owned by one thread each (no write conflicts); the minimum does not depend
  // on the order of triangles, so the result is the same for any number of threads.
  const Eigen::Vector3d o3(origin[0], origin[1], origin[2]);
  auto indexRange = [&](double lo, double hi, std::size_t count, std::size_t& i0, std::size_t& i1) {
    const double a = std::ceil((lo - band) / h), b = std::floor((hi + band) / h);
    i0 = static_cast<std::size_t>(std::max(0.0, a));
    i1 = static_cast<std::size_t>(std::max(-1.0, std::min(static_cast<double>(count) - 1, b)) + 1);
  };
  const std::size_t slabCount = std::min<std::size_t>(nz, 64);
  std::vector<std::vector<std::uint32_t>> slabTriangles(slabCount);
  auto slabOf = [&](std::size_t k) { return k * slabCount / nz; };
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const auto& tr = triangles[t];
    const double zlo = std::min({tr.a.z(), tr.b.z(), tr.c.z()}) - o3.z();
    const double zhi = std::max({tr.a.z(), tr.b.z(), tr.c.z()}) - o3.z();
    std::size_t k0, k1;
    indexRange(zlo, zhi, nz, k0, k1);
    if (k0 >= k1)
      continue;
    for (std::size_t s = slabOf(k0); s <= slabOf(k1 - 1); ++s)
      slabTriangles[s].push_back(static_cast<std::uint32_t>(t));
  }
  const double band2 = band * band;
  itk::MultiThreaderBase::New()->ParallelizeArray(
    0, slabCount,
    [&](itk::SizeValueType s) {
      // Voxel k-range of this slab: the k with slabOf(k) == s.
      const std::size_t kBegin = (s * nz + slabCount - 1) / slabCount;
      const std::size_t kEnd = ((s + 1) * nz + slabCount - 1) / slabCount;
      for (auto t : slabTriangles[s])
      {
        const auto& tr = triangles[t];
        const Eigen::Vector3d lo = tr.a.cwiseMin(tr.b).cwiseMin(tr.c) - o3,
                              hi = tr.a.cwiseMax(tr.b).cwiseMax(tr.c) - o3;
        std::size_t i0, i1, j0, j1, k0, k1;
        indexRange(lo.x(), hi.x(), nx, i0, i1);
        indexRange(lo.y(), hi.y(), ny, j0, j1);
        indexRange(lo.z(), hi.z(), nz, k0, k1);
        k0 = std::max(k0, kBegin);
        k1 = std::min(k1, kEnd);
        for (std::size_t k = k0; k < k1; ++k)
          for (std::size_t j = j0; j < j1; ++j)
            for (std::size_t i = i0; i < i1; ++i)
            {
              const Eigen::Vector3d p = o3 + Eigen::Vector3d(i * h, j * h, k * h);
              TriangleFeature feature;
              const Eigen::Vector3d closest = ClosestPointOnTriangle(p, tr.a, tr.b, tr.c, &feature);
              const double d2 = (closest - p).squaredNorm();
              const std::size_t v = i + nx * (j + ny * k);
              if (d2 < exact[v] && d2 <= band2)
              {
                exact[v] = d2;
                if (!sign.empty())
                  sign[v] = (p - closest).dot(normals[t][static_cast<int>(feature)]) < 0 ? -1 : 1;
              }
            }
      }
    },
    nullptr);
}
} // namespace

FloatImage::Pointer ComputeSurfaceDistanceMap(vtkPolyData* surface, const SurfaceDistanceMapOptions& o,
                                              const std::function<void(double)>& progress)
{
  auto report = [&](double f) {
    if (progress)
      progress(f);
  };
  if (!(o.spacing > 0) || !(o.margin >= 0) || !(o.exactBand >= 1))
    throw std::runtime_error("distance map: spacing must be > 0, margin >= 0 and the exact band >= 1 voxel");
  if (surface == nullptr || surface->GetNumberOfPolys() + surface->GetNumberOfStrips() == 0)
    throw std::runtime_error("distance map: the surface has no triangles");
  std::vector<FeatureNormals> normals;
  const auto triangles = Triangles(surface, o.signedDistance ? &normals : nullptr);
  if (triangles.empty())
    throw std::runtime_error("distance map: the surface has no triangles");

  auto map = DistanceMapGrid(surface, o);
  const auto size = map->GetLargestPossibleRegion().GetSize();
  const FloatImage::RegionType region = map->GetLargestPossibleRegion();
  const std::size_t nx = size[0], ny = size[1], nz = size[2], n = nx * ny * nz;
  const double h = o.spacing;
  std::vector<double> exact(n, std::numeric_limits<double>::infinity());
  std::vector<signed char> sign(o.signedDistance ? n : 0, 1); // -1 inside

  ExactBand(triangles, normals, map, o.exactBand, exact, sign);
  report(0.6);

  // Far field through the nearest band voxel given by the Saito–Toriwaki transform.
  auto bandMask = MaskImage::New();
  bandMask->CopyInformation(map);
  bandMask->SetRegions(region);
  bandMask->Allocate();
  std::size_t bandVoxels = 0;
  for (std::size_t v = 0; v < n; ++v)
  {
    const bool in = std::isfinite(exact[v]);
    bandMask->GetBufferPointer()[v] = in;
    bandVoxels += in;
  }
  if (bandVoxels == 0)
    throw std::runtime_error("distance map: no voxel lies near the surface (is the region away from it?)");
  float* out = map->GetBufferPointer();
  if (bandVoxels == n)
  {
    for (std::size_t v = 0; v < n; ++v)
      out[v] = static_cast<float>((sign.empty() ? 1 : sign[v]) * std::sqrt(exact[v]));
    report(1.0);
    return map;
  }
  using EDT = itk::SaitoToriwakiDistanceMapImageFilter<MaskImage, FloatImage>;
  auto edt = EDT::New();
  edt->SetInput(bandMask);
  edt->SetComputeNearestVector(true);
  edt->Update();
  const auto* vec = edt->GetNearestVectorOutput()->GetBufferPointer();
  report(0.9);
  for (std::size_t k = 0, v = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i, ++v)
      {
        if (std::isfinite(exact[v]))
        {
          out[v] = static_cast<float>((sign.empty() ? 1 : sign[v]) * std::sqrt(exact[v]));
          continue;
        }
        const auto& d = vec[v];
        // Grid axes are LPS axes with isotropic spacing, so the offset in voxels is d / h.
        const long qi = static_cast<long>(i) + std::lround(d[0] / h);
        const long qj = static_cast<long>(j) + std::lround(d[1] / h);
        const long qk = static_cast<long>(k) + std::lround(d[2] / h);
        const std::size_t q =
          static_cast<std::size_t>(qi) + nx * (static_cast<std::size_t>(qj) + ny * static_cast<std::size_t>(qk));
        // The straight path to q does not cross the surface (q is the nearest band voxel), so p
        // lies on q's side.
        out[v] = static_cast<float>((sign.empty() ? 1 : sign[q]) *
                                    (std::sqrt(static_cast<double>(d.GetSquaredNorm())) + std::sqrt(exact[q])));
      }
  report(1.0);
  return map;
}

} // namespace mmrep
