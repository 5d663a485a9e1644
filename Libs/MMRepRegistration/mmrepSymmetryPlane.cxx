// Mid-sagittal plane by mirror-and-register (Chang & Park 2008), see mmrepSymmetryPlane.h.
//
// The mirrored samples M(p) are rigidly registered onto the surface by trimmed ICP (closest points
// on the triangles, the worst pairs dropped so that asymmetric parts and the flat caps where the CT
// cuts the neck do not pull). A head tilted by θ needs a correction of 2θ after mirroring by the
// axis-aligned initial plane, so a coarse point-to-point ICP (rigid Umeyama updates: robust far
// from the solution) starts from a small grid of rotations about the AP and SI axes and keeps the
// start with the lowest trimmed residual. The refinement minimises point-to-plane distances
// (linearised, Chen & Medioni 1992): point-to-point ICP slides only slowly along a smooth head
// (hundreds of iterations for 0.1°), point-to-plane converges in a few.
#include "mmrepSymmetryPlane.h"

#include "mmrepPointTriangleDistance.h"
#include "mmrepSimilarityTransform.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace mmrep
{
namespace
{

constexpr double kPi = 3.14159265358979323846;

// Rigid transform with its linear part as a rotation about `centre`.
SimilarityTransform RotationAbout(const Eigen::Vector3d& centre, const Eigen::Matrix3d& r)
{
  SimilarityTransform t;
  t.rotation = r;
  t.translation = centre - r * centre;
  return t;
}

struct IcpState
{
  SimilarityTransform transform;
  double rms = 0;
  int iterations = 0;
  std::vector<std::size_t> kept; // indices into the sample list, kept at the last matching
};

class TrimmedIcp
{
public:
  TrimmedIcp(vtkPolyData* surface, std::vector<Eigen::Vector3d> moving, double trimFraction)
    : moving_(std::move(moving)), trim_(trimFraction)
  {
    locator_->SetDataSet(surface);
    locator_->BuildLocator();
    // Triangle corners and unit normals, indexed like the locator's cell ids.
    vtkCellArray* polys = surface->GetPolys();
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    {
      std::array<Eigen::Vector3d, 3> t;
      for (int k = 0; k < 3; ++k)
        surface->GetPoint(ids[k], t[static_cast<std::size_t>(k)].data());
      const Eigen::Vector3d normal = (t[1] - t[0]).cross(t[2] - t[0]);
      const double len = normal.norm();
      triangles_.push_back(t);
      normals_.push_back(len > 0 ? Eigen::Vector3d(normal / len) : Eigen::Vector3d::Zero());
    }
  }

  // Closest point on the surface, deterministic: VTK's static locator is built in parallel, so
  // among triangles at equal distance (a shared edge or vertex) the one it reports may change from
  // run to run, and with it the normal. The candidates touching VTK's answer are re-evaluated
  // here and ties go to the lowest triangle id.
  double Closest(const Eigen::Vector3d& x, Eigen::Vector3d& closest, Eigen::Vector3d& normal)
  {
    double c[3], d2 = 0;
    vtkIdType cellId = -1;
    int subId = 0;
    locator_->FindClosestPoint(x.data(), c, cell_, cellId, subId, d2);
    const double eps = 1e-6 * (1.0 + std::sqrt(d2));
    double bounds[6] = {c[0] - eps, c[0] + eps, c[1] - eps, c[1] + eps, c[2] - eps, c[2] + eps};
    candidates_->Reset();
    locator_->FindCellsWithinBounds(bounds, candidates_);
    std::vector<vtkIdType> ids(candidates_->GetPointer(0), candidates_->GetPointer(0) + candidates_->GetNumberOfIds());
    if (cellId >= 0)
      ids.push_back(cellId);
    std::sort(ids.begin(), ids.end());
    double best = std::numeric_limits<double>::infinity();
    for (vtkIdType id : ids)
    {
      const auto& t = triangles_[static_cast<std::size_t>(id)];
      const Eigen::Vector3d y = ClosestPointOnTriangle(x, t[0], t[1], t[2]);
      const double e2 = (y - x).squaredNorm();
      if (e2 < best)
      {
        best = e2;
        closest = y;
        normal = normals_[static_cast<std::size_t>(id)];
      }
    }
    return best;
  }

  // Matches T(moving[i]) for i in `subset` to the surface; keeps the best (1 - trim) fraction.
  // Returns the RMS distance of the kept pairs; fills targets and kept.
  double Match(const SimilarityTransform& t, const std::vector<std::size_t>& subset,
               std::vector<Eigen::Vector3d>& targets, std::vector<Eigen::Vector3d>& normals,
               std::vector<std::size_t>& kept)
  {
    const std::size_t n = subset.size();
    targets.resize(n);
    normals.resize(n);
    std::vector<double> d2(n);
    for (std::size_t k = 0; k < n; ++k)
    {
      d2[k] = Closest(t.Apply(moving_[subset[k]]), targets[k], normals[k]);
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    // Ties broken by index: the same input gives the same pairs.
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return d2[a] < d2[b] || (d2[a] == d2[b] && a < b); });
    const std::size_t keep = std::max<std::size_t>(3, static_cast<std::size_t>(std::ceil((1.0 - trim_) * n)));
    order.resize(std::min(keep, n));
    std::sort(order.begin(), order.end());
    kept = order;
    double sum = 0;
    for (std::size_t k : kept)
      sum += d2[k];
    return std::sqrt(sum / static_cast<double>(kept.size()));
  }

  // pointToPlane: linearised point-to-plane updates; otherwise rigid Umeyama (point-to-point).
  IcpState Run(const SimilarityTransform& start, const std::vector<std::size_t>& subset, int maxIterations,
               double tolerance, const Eigen::Vector3d& centre, bool pointToPlane)
  {
    IcpState s;
    s.transform = start;
    std::vector<Eigen::Vector3d> targets, normals;
    std::vector<std::size_t> kept;
    for (s.iterations = 1; s.iterations <= maxIterations; ++s.iterations)
    {
      Match(s.transform, subset, targets, normals, kept);
      SimilarityTransform next;
      if (!(pointToPlane && PointToPlaneStep(s.transform, subset, targets, normals, kept, centre, next)))
      {
        std::vector<Eigen::Vector3d> src, dst;
        src.reserve(kept.size());
        dst.reserve(kept.size());
        for (std::size_t k : kept)
        {
          src.push_back(moving_[subset[k]]);
          dst.push_back(targets[k]);
        }
        next = EstimateRigid(src, dst);
      }
      const double turn = Eigen::AngleAxisd(next.rotation * s.transform.rotation.transpose()).angle();
      const double shift = (next.Apply(centre) - s.transform.Apply(centre)).norm();
      s.transform = next;
      if (turn < tolerance && shift < tolerance)
        break;
    }
    s.iterations = std::min(s.iterations, maxIterations);
    s.rms = Match(s.transform, subset, targets, normals, kept);
    s.kept.clear();
    for (std::size_t k : kept)
      s.kept.push_back(subset[k]);
    return s;
  }

  // One Gauss-Newton step of Σ ((x_k + ω×(x_k - c) + v - y_k)·n_k)² over the kept pairs, about the
  // centre c for conditioning. Returns false when the system is singular (e.g. a flat patch).
  bool PointToPlaneStep(const SimilarityTransform& t, const std::vector<std::size_t>& subset,
                        const std::vector<Eigen::Vector3d>& targets, const std::vector<Eigen::Vector3d>& normals,
                        const std::vector<std::size_t>& kept, const Eigen::Vector3d& centre, SimilarityTransform& next)
  {
    Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
    for (std::size_t k : kept)
    {
      const Eigen::Vector3d x = t.Apply(moving_[subset[k]]);
      const Eigen::Vector3d& n = normals[k];
      Eigen::Matrix<double, 6, 1> row;
      row << (x - centre).cross(n), n;
      a += row * row.transpose();
      b -= row * (x - targets[k]).dot(n);
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

private:
  std::vector<Eigen::Vector3d> moving_;
  double trim_;
  vtkNew<vtkStaticCellLocator> locator_;
  vtkNew<vtkGenericCell> cell_;
  vtkNew<vtkIdList> candidates_;
  std::vector<std::array<Eigen::Vector3d, 3>> triangles_;
  std::vector<Eigen::Vector3d> normals_;
};

} // namespace

SymmetryPlaneResult EstimateSymmetryPlane(vtkPolyData* skin, const SymmetryPlaneOptions& options)
{
  if (skin == nullptr || skin->GetNumberOfPoints() == 0 || skin->GetNumberOfPolys() == 0)
    throw std::runtime_error("symmetry plane: the skin surface is empty (no points or no triangles)");
  if (options.maximumIterations < 1 || options.samplePoints < 3 || !(options.trimFraction >= 0) ||
      !(options.trimFraction < 0.9) || !(options.tolerance > 0))
    throw std::invalid_argument("symmetry plane: invalid options (iterations >= 1, samples >= 3, "
                                "trim fraction in [0, 0.9), tolerance > 0)");

  // Only the polygons take part (stray vertex or line cells are not skin), as triangles.
  vtkNew<vtkPolyData> polygons;
  polygons->SetPoints(skin->GetPoints());
  polygons->SetPolys(skin->GetPolys());
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(polygons);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkPolyData* surface = triangulate->GetOutput();
  if (surface->GetNumberOfPolys() == 0)
    throw std::runtime_error("symmetry plane: the skin surface has no triangles");

  // Deterministic subsample: every stride-th vertex.
  const vtkIdType nPoints = skin->GetNumberOfPoints();
  const vtkIdType stride = std::max<vtkIdType>(1, nPoints / static_cast<vtkIdType>(options.samplePoints));
  std::vector<Eigen::Vector3d> samples;
  for (vtkIdType i = 0; i < nPoints && samples.size() < options.samplePoints; i += stride)
  {
    double p[3];
    skin->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw std::runtime_error("symmetry plane: the skin surface has a non-finite point");
    samples.emplace_back(p[0], p[1], p[2]);
  }
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
    skin->GetBounds(b);
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

  TrimmedIcp icp(surface, mirrored, options.trimFraction);

  // Coarse search over starting rotations (about the AP and SI axes through the centroid) on a
  // quarter of the samples; ±30° covers a head tilted by up to ±15° about either axis.
  std::vector<std::size_t> all(samples.size()), coarse;
  std::iota(all.begin(), all.end(), 0);
  for (std::size_t i = 0; i < all.size(); i += 4)
    coarse.push_back(i);
  if (coarse.size() < 3)
    coarse = all;
  IcpState best;
  bool haveBest = false;
  for (double roll : {0.0, -30.0, 30.0})
    for (double yaw : {0.0, -30.0, 30.0})
    {
      const Eigen::Matrix3d r = (Eigen::AngleAxisd(yaw * kPi / 180, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(roll * kPi / 180, Eigen::Vector3d::UnitY()))
                                  .toRotationMatrix();
      IcpState s = icp.Run(RotationAbout(centroid, r), coarse, 15, 10 * options.tolerance, centroid, false);
      if (!haveBest || s.rms < best.rms)
      {
        best = s;
        haveBest = true;
      }
    }
  const IcpState fine = icp.Run(best.transform, all, options.maximumIterations, options.tolerance, centroid, true);

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
