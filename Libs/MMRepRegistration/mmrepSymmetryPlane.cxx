// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Mid-sagittal plane by mirror-and-register (Chang & Park 2008), see mmrepSymmetryPlane.h.
//
// The mirrored samples M(p) are rigidly registered onto the surface by minimising the squared
// signed distances d(T(M p))² read from the surface's distance map, with the worst pairs dropped
// at each iteration (asymmetric parts and the flat caps where the CT cuts the neck must not pull).
// Gauss-Newton on the rigid parameters about the samples' centroid: the map's gradient is the
// surface normal, so each iteration is a point-to-plane step (Chen & Medioni 1992) without any
// closest-point search. A head tilted by θ needs a correction of 2θ after mirroring by the
// axis-aligned initial plane, so the registration starts from a small grid of rotations about the
// AP and SI axes (on a quarter of the samples) and keeps the start with the lowest trimmed residual.
#include "mmrepSymmetryPlane.h"

#include "mmrepDistanceMapSampler.h"
#include "mmrepSimilarityTransform.h"
#include "mmrepSurfaceDistanceMap.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace mmrep
{
namespace
{

constexpr double kPi = 3.14159265358979323846;
constexpr int kExactIterations = 10; // after the map's: it starts within a fraction of a voxel

// One vertex per occupied cell of a regular grid over the bounding box, the one nearest the cell's
// centre (ties: lexicographic coordinates), cells in index order: the same samples whatever the
// vertex order. The cell size gives about `target` occupied cells on a closed head-like surface.
std::vector<Eigen::Vector3d> GridSamples(vtkPolyData* skin, std::size_t target)
{
  double b[6];
  skin->GetBounds(b);
  const double area =
    2 * ((b[1] - b[0]) * (b[3] - b[2]) + (b[1] - b[0]) * (b[5] - b[4]) + (b[3] - b[2]) * (b[5] - b[4]));
  const double cell = std::max(1e-6, std::sqrt(area / static_cast<double>(std::max<std::size_t>(target, 1))));
  using Key = std::tuple<long, long, long>;
  std::map<Key, std::pair<double, Eigen::Vector3d>> best; // key -> (distance² to the centre, vertex)
  for (vtkIdType i = 0; i < skin->GetNumberOfPoints(); ++i)
  {
    double q[3];
    skin->GetPoint(i, q);
    const Eigen::Vector3d p(q[0], q[1], q[2]);
    if (!p.allFinite())
      throw std::runtime_error("symmetry plane: the skin surface has a non-finite point");
    const Key key{static_cast<long>(std::floor((p.x() - b[0]) / cell)),
                  static_cast<long>(std::floor((p.y() - b[2]) / cell)),
                  static_cast<long>(std::floor((p.z() - b[4]) / cell))};
    const Eigen::Vector3d centre(b[0] + (std::get<0>(key) + 0.5) * cell, b[2] + (std::get<1>(key) + 0.5) * cell,
                                 b[4] + (std::get<2>(key) + 0.5) * cell);
    const double d2 = (p - centre).squaredNorm();
    const auto it = best.find(key);
    auto lexLess = [](const Eigen::Vector3d& a, const Eigen::Vector3d& c) {
      return std::tie(a.x(), a.y(), a.z()) < std::tie(c.x(), c.y(), c.z());
    };
    if (it == best.end())
      best.emplace(key, std::make_pair(d2, p));
    else if (d2 < it->second.first || (d2 == it->second.first && lexLess(p, it->second.second)))
      it->second = {d2, p};
  }
  std::vector<Eigen::Vector3d> samples;
  samples.reserve(best.size());
  for (const auto& [key, entry] : best)
    samples.push_back(entry.second);
  return samples;
}

struct RegistrationState
{
  SimilarityTransform transform;
  double rms = 0;
  int iterations = 0;
  std::vector<std::size_t> kept; // indices into the sample list, kept at the last evaluation
};

// Rigid registration of the moving points onto the zero level of a distance (map or exact).
template <class Distance> class MirrorRegistration
{
public:
  MirrorRegistration(const Distance& map, std::vector<Eigen::Vector3d> moving, double trim)
      : map_(map), moving_(std::move(moving)), trim_(trim)
  {
  }

  // Signed distances of T(moving[k]) for k in subset, the kept (best 1 − trim) fraction (sorted
  // subset positions) and their RMS.
  double Evaluate(const SimilarityTransform& t, const std::vector<std::size_t>& subset, std::vector<double>& d,
                  std::vector<Eigen::Vector3d>& normals, std::vector<std::size_t>& kept) const
  {
    const std::size_t n = subset.size();
    d.resize(n);
    normals.resize(n);
    for (std::size_t k = 0; k < n; ++k)
      d[k] = map_.Value(t.Apply(moving_[subset[k]]), &normals[k]);
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return std::abs(d[a]) < std::abs(d[b]) || (std::abs(d[a]) == std::abs(d[b]) && a < b);
    });
    const std::size_t keep = std::max<std::size_t>(3, static_cast<std::size_t>(std::ceil((1.0 - trim_) * n)));
    order.resize(std::min(keep, n));
    std::sort(order.begin(), order.end());
    kept = order;
    double sum = 0;
    for (std::size_t k : kept)
      sum += d[k] * d[k];
    return std::sqrt(sum / static_cast<double>(kept.size()));
  }

  RegistrationState Run(const SimilarityTransform& start, const std::vector<std::size_t>& subset, int maxIterations,
                        double tolerance, const Eigen::Vector3d& centre) const
  {
    RegistrationState s;
    s.transform = start;
    std::vector<double> d;
    std::vector<Eigen::Vector3d> normals;
    std::vector<std::size_t> kept;
    for (s.iterations = 1; s.iterations <= maxIterations; ++s.iterations)
    {
      Evaluate(s.transform, subset, d, normals, kept);
      SimilarityTransform next;
      if (!Step(s.transform, subset, d, normals, kept, centre, next))
        break;
      const double turn = Eigen::AngleAxisd(next.rotation * s.transform.rotation.transpose()).angle();
      const double shift = (next.Apply(centre) - s.transform.Apply(centre)).norm();
      s.transform = next;
      if (turn < tolerance && shift < tolerance)
        break;
    }
    s.iterations = std::min(s.iterations, maxIterations);
    s.rms = Evaluate(s.transform, subset, d, normals, kept);
    s.kept.clear();
    for (std::size_t k : kept)
      s.kept.push_back(subset[k]);
    return s;
  }

private:
  // One Gauss-Newton step of Σ d(x_k + ω×(x_k − c) + v)² over the kept points, about the centre c
  // for conditioning (∂d/∂ω = (x − c) × ∇d, ∂d/∂v = ∇d). False when the system is singular.
  bool Step(const SimilarityTransform& t, const std::vector<std::size_t>& subset, const std::vector<double>& d,
            const std::vector<Eigen::Vector3d>& normals, const std::vector<std::size_t>& kept,
            const Eigen::Vector3d& centre, SimilarityTransform& next) const
  {
    Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
    for (std::size_t k : kept)
    {
      const Eigen::Vector3d x = t.Apply(moving_[subset[k]]);
      Eigen::Matrix<double, 6, 1> row;
      row << (x - centre).cross(normals[k]), normals[k];
      a += row * row.transpose();
      b -= row * d[k];
    }
    Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(a);
    if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12))
      return false;
    const Eigen::Matrix<double, 6, 1> delta = ldlt.solve(b);
    if (!delta.allFinite())
      return false;
    const Eigen::Vector3d omega = delta.head<3>();
    const double angle = omega.norm();
    const Eigen::Matrix3d r =
      angle > 0 ? Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
    SimilarityTransform step;
    step.rotation = r;
    step.translation = centre - r * centre + delta.tail<3>();
    next = step.Compose(t);
    return true;
  }

  const Distance& map_;
  std::vector<Eigen::Vector3d> moving_;
  double trim_;
};

// Exact distances for the last iterations: a map's trilinear interpolation rounds the surface (an
// unsigned map, of an open surface, by up to a quarter voxel), the triangles do not. The residual
// direction is the closest point's (x − y)/|x − y|, which does not depend on which of two triangles
// sharing the closest edge the locator reports: the same for any triangle order.
class ExactDistance
{
public:
  explicit ExactDistance(vtkPolyData* surface)
  {
    locator_->SetDataSet(surface);
    locator_->BuildLocator();
  }
  double Value(const Eigen::Vector3d& x, Eigen::Vector3d* gradient) const
  {
    double c[3], d2 = 0;
    vtkIdType cellId = -1;
    int subId = 0;
    locator_->FindClosestPoint(const_cast<double*>(x.data()), c, cell_, cellId, subId, d2);
    const Eigen::Vector3d y(c[0], c[1], c[2]);
    const double d = std::sqrt(d2);
    if (gradient)
      *gradient = d > 1e-12 ? Eigen::Vector3d((x - y) / d) : Eigen::Vector3d::Zero();
    return d;
  }

private:
  vtkNew<vtkStaticCellLocator> locator_;
  vtkNew<vtkGenericCell> cell_;
};

SimilarityTransform RotationAbout(const Eigen::Vector3d& centre, const Eigen::Matrix3d& r)
{
  SimilarityTransform t;
  t.rotation = r;
  t.translation = centre - r * centre;
  return t;
}

FloatImage::Pointer SkinMap(vtkPolyData* skin, double spacing)
{
  SurfaceDistanceMapOptions o;
  o.spacing = spacing;
  o.margin = 10.0;
  o.signedDistance = true; // zero at the surface; an open surface falls back to |d|
  try
  {
    return ComputeSurfaceDistanceMap(skin, o);
  }
  catch (const std::runtime_error&)
  {
    o.signedDistance = false;
    return ComputeSurfaceDistanceMap(skin, o);
  }
}

// Only the polygons take part (stray vertex or line cells are not skin), as triangles.
vtkSmartPointer<vtkPolyData> SkinTriangles(vtkPolyData* skin)
{
  vtkNew<vtkPolyData> polygons;
  polygons->SetPoints(skin->GetPoints());
  polygons->SetPolys(skin->GetPolys());
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(polygons);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkSmartPointer<vtkPolyData> surface = triangulate->GetOutput();
  if (surface->GetNumberOfPolys() == 0)
    throw std::runtime_error("symmetry plane: the skin surface has no triangles");
  return surface;
}

} // namespace

SymmetryPlaneResult EstimateSymmetryPlane(vtkPolyData* skin, const SymmetryPlaneOptions& options)
{
  if (skin == nullptr || skin->GetNumberOfPoints() == 0 || skin->GetNumberOfPolys() == 0)
    throw std::runtime_error("symmetry plane: the skin surface is empty (no points or no triangles)");
  if (options.maximumIterations < 1 || options.samplePoints < 3 || !(options.trimFraction >= 0) ||
      !(options.trimFraction < 0.9) || !(options.tolerance > 0) || !(options.mapSpacing > 0))
    throw std::invalid_argument("symmetry plane: invalid options (iterations >= 1, samples >= 3, "
                                "trim fraction in [0, 0.9), tolerance > 0, map spacing > 0)");

  const vtkSmartPointer<vtkPolyData> triangles = SkinTriangles(skin);
  vtkPolyData* surface = triangles;

  const std::vector<Eigen::Vector3d> samples = GridSamples(surface, options.samplePoints);
  if (samples.size() < 3)
    throw std::runtime_error("symmetry plane: the skin surface has fewer than 3 points");
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : samples)
    centroid += p;
  centroid /= static_cast<double>(samples.size());

  Plane initial = options.initialPlane;
  if (!options.hasInitialPlane)
  {
    double b[6];
    surface->GetBounds(b);
    initial.point = Eigen::Vector3d(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
    initial.normal = Eigen::Vector3d::UnitX();
  }
  if (!(initial.normal.norm() > 0) || !initial.point.allFinite() || !initial.normal.allFinite())
    throw std::invalid_argument("symmetry plane: the initial plane has a zero or non-finite normal");
  initial.normal.normalize();

  // M: reflection by the initial plane.
  const Eigen::Matrix3d mLinear = Eigen::Matrix3d::Identity() - 2.0 * initial.normal * initial.normal.transpose();
  const Eigen::Vector3d mShift = 2.0 * initial.normal.dot(initial.point) * initial.normal;
  std::vector<Eigen::Vector3d> mirrored;
  mirrored.reserve(samples.size());
  for (const auto& p : samples)
    mirrored.push_back(mLinear * p + mShift);

  const auto map = SkinMap(surface, options.mapSpacing);
  const DistanceMapSampler sampler(map);
  const MirrorRegistration<DistanceMapSampler> registration(sampler, mirrored, options.trimFraction);

  // Starting rotations about the AP and SI axes through the centroid, on a quarter of the samples;
  // ±30° covers a head tilted by up to ±15° about either axis.
  std::vector<std::size_t> all(samples.size()), coarse;
  std::iota(all.begin(), all.end(), 0);
  for (std::size_t i = 0; i < all.size(); i += 4)
    coarse.push_back(i);
  if (coarse.size() < 3)
    coarse = all;
  RegistrationState best;
  bool haveBest = false;
  for (double roll : {0.0, -30.0, 30.0})
    for (double yaw : {0.0, -30.0, 30.0})
    {
      const Eigen::Matrix3d r = (Eigen::AngleAxisd(yaw * kPi / 180, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(roll * kPi / 180, Eigen::Vector3d::UnitY()))
                                  .toRotationMatrix();
      RegistrationState s = registration.Run(RotationAbout(centroid, r), coarse, 15, 10 * options.tolerance, centroid);
      if (!haveBest || s.rms < best.rms)
      {
        best = s;
        haveBest = true;
      }
    }
  const RegistrationState onMap =
    registration.Run(best.transform, all, options.maximumIterations, options.tolerance, centroid);
  const ExactDistance exact(surface);
  const MirrorRegistration<ExactDistance> exactRegistration(exact, mirrored, options.trimFraction);
  const RegistrationState fine =
    exactRegistration.Run(onMap.transform, all, kExactIterations, options.tolerance, centroid);

  // S = T∘M, an improper rigid map. For S = rotation(φ, a)·reflection(a) the symmetric part of its
  // linear part has eigenvalues -1 (eigenvector a) and cos φ (twice); the -1 eigenvector is the
  // plane normal, and for a pure reflection (φ = 0) it equals the eigenvector of S itself.
  const Eigen::Matrix3d sLinear = fine.transform.rotation * mLinear;
  const Eigen::Vector3d sShift = fine.transform.rotation * mShift + fine.transform.translation;
  const Eigen::Matrix3d symmetric = 0.5 * (sLinear + sLinear.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(symmetric);
  const Eigen::Vector3d values = eig.eigenvalues(); // ascending
  // Residual rotation φ of the rotoreflection: a symmetric head gives φ near 0.
  const double cosPhi = 0.5 * (values(1) + values(2));
  if (std::abs(values(0) + 1.0) > 1e-6 || cosPhi < std::cos(20.0 * kPi / 180))
    throw std::runtime_error("symmetry plane: the registered mirror image is not a reflection (residual rotation " +
                             std::to_string(std::acos(std::clamp(cosPhi, -1.0, 1.0)) * 180 / kPi) +
                             " deg); the surface is not a roughly symmetric head");
  Eigen::Vector3d normal = eig.eigenvectors().col(0).normalized();
  if (normal.x() < 0)
    normal = -normal;

  // Midpoints of p and S(p) over the kept pairs; the reported point is the kept samples' centroid
  // projected on the plane, i.e. the plane's point nearest the head's centre.
  Eigen::Vector3d mid = Eigen::Vector3d::Zero(), keptCentroid = Eigen::Vector3d::Zero();
  for (std::size_t i : fine.kept)
  {
    mid += 0.5 * (samples[i] + sLinear * samples[i] + sShift);
    keptCentroid += samples[i];
  }
  mid /= static_cast<double>(fine.kept.size());
  keptCentroid /= static_cast<double>(fine.kept.size());

  SymmetryPlaneResult result;
  result.plane.normal = normal;
  result.plane.point = mid;
  result.plane.point = result.plane.Project(keptCentroid);
  result.rmsResidual = fine.rms;
  result.iterations = fine.iterations;
  return result;
}

} // namespace mmrep
