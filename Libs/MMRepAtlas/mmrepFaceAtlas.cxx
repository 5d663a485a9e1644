#include "mmrepFaceAtlas.h"

#include "mmrepFaceMouth.h"

#include "mmrepFaceMuscles.h"
#include "mmrepMeshRepair.h"
#include "mmrepMeshQuality.h"

#include <vtkAppendPolyData.h>
#include <vtkBox.h>
#include <vtkCellData.h>
#include <vtkClipPolyData.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkReverseSense.h>
#include <vtkStaticCellLocator.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkTriangleFilter.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mmrep
{
namespace
{
constexpr double kDeg = M_PI / 180.0;

vtkSmartPointer<vtkPolyData> Transformed(vtkPolyData* surface, const double matrix[16])
{
  auto t = vtkSmartPointer<vtkTransform>::New();
  t->SetMatrix(matrix);
  auto f = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  f->SetInputData(surface);
  f->SetTransform(t);
  f->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  f->Update();
  vtkSmartPointer<vtkPolyData> out = f->GetOutput();
  return out;
}

// Sizes along an axis: positions from a to b with spacing h(x) (angles), rescaled to end at b.
std::vector<double> Graded(double a, double b, const std::function<double(double)>& h)
{
  std::vector<double> x{a};
  while (x.back() < b)
    x.push_back(x.back() + h(x.back()));
  // Drop the last step when it overshoots by more than half a step, then stretch to end at b.
  if (x.size() > 2 && x.back() - b > 0.5 * (x.back() - x[x.size() - 2]))
    x.pop_back();
  const double scale = (b - a) / (x.back() - a);
  for (auto& v : x)
    v = a + (v - a) * scale;
  x.back() = b;
  return x;
}

// Size h at position x: `fine` inside [lo, hi], `coarse` beyond `ramp` outside, linear in between.
double Size(double x, double lo, double hi, double ramp, double fine, double coarse)
{
  const double d = x < lo ? lo - x : x > hi ? x - hi : 0;
  return fine + (coarse - fine) * std::min(1.0, d / ramp);
}

// Left half + mirror image of a local-frame surface, within a local box, back in world coordinates.
vtkSmartPointer<vtkPolyData> Symmetrised(vtkPolyData* local, const FaceFrame& frame, const double box[6])
{
  auto boxFn = vtkSmartPointer<vtkBox>::New();
  boxFn->SetBounds(box);
  // Clipping keeps exact sub-triangles of the original ones (distances to them are unchanged).
  auto extract = vtkSmartPointer<vtkClipPolyData>::New();
  extract->SetInputData(local);
  extract->SetClipFunction(boxFn);
  extract->InsideOutOn();
  extract->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  auto plane = vtkSmartPointer<vtkPlane>::New();
  plane->SetOrigin(0, 0, 0);
  plane->SetNormal(1, 0, 0);
  auto clip = vtkSmartPointer<vtkClipPolyData>::New();
  clip->SetInputConnection(extract->GetOutputPort());
  clip->SetClipFunction(plane);
  clip->SetValue(0);
  clip->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  auto tri = vtkSmartPointer<vtkTriangleFilter>::New();
  tri->SetInputConnection(clip->GetOutputPort());
  tri->Update();
  vtkSmartPointer<vtkPolyData> left = tri->GetOutput();
  const double mirror[16] = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  auto right = Transformed(left, mirror);
  auto reverse = vtkSmartPointer<vtkReverseSense>::New();
  reverse->SetInputData(right);
  auto append = vtkSmartPointer<vtkAppendPolyData>::New();
  append->AddInputData(left);
  append->AddInputConnection(reverse->GetOutputPort());
  append->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  append->Update();
  double toWorld[16];
  frame.LocalToWorldMatrix(toWorld);
  auto world = Transformed(append->GetOutput(), toWorld);
  world->GetPointData()->Initialize();
  world->GetCellData()->Initialize();
  return world;
}

std::string Format(const char* fmt, double a, double b = 0, double c = 0)
{
  char buf[256];
  std::snprintf(buf, sizeof(buf), fmt, a, b, c);
  return buf;
}
} // namespace

const std::vector<std::string>& FaceAtlasLandmarkNames()
{
  static const std::vector<std::string> names{"LeftEyeInnerCorner", "LeftEyeOuterCorner", "LeftLipCorner",
                                              "UpperLipCenter", "LowerLipCenter"};
  return names;
}

FaceAtlas BuildFaceAtlas(vtkPolyData* skinWorld, vtkPolyData* skullWorld, const Plane& plane,
                         const FaceAtlasOptions& options, const std::function<void(double)>& progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::string> timings;
  auto report = [&](double f) {
    if (progress)
      progress(f);
    timings.push_back(Format("%.2f s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()));
  };
  if (!skinWorld || skinWorld->GetNumberOfPolys() == 0)
    throw std::runtime_error("face atlas: the skin surface has no triangles");
  if (!skullWorld || skullWorld->GetNumberOfPolys() == 0)
    throw std::runtime_error("face atlas: the skull surface has no triangles");
  const auto& r = options.layerRatios;
  if (r[0] <= 0 || r[1] <= 0 || r[2] <= 0)
    throw std::invalid_argument("face atlas: layer ratios must be positive");
  if (options.meshSize <= 0 || options.lipsMeshSize <= 0 || options.lipsMeshSize > options.meshSize)
    throw std::invalid_argument("face atlas: mesh sizes must be positive and the lips size at most the mesh size");

  FaceAtlas atlas;
  atlas.plane = plane;
  double b[6];
  skinWorld->GetBounds(b);
  atlas.frame = FaceFrame::FromPlane(plane, Eigen::Vector3d(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])));
  const FaceFrame& frame = atlas.frame;
  double toLocal[16];
  frame.WorldToLocalMatrix(toLocal);
  auto skinLocal = Transformed(skinWorld, toLocal);
  auto skullLocal = Transformed(skullWorld, toLocal);
  SurfaceRays skin(skinLocal), bone(skullLocal);
  report(0.1);

  // Face centre: on the plane, halfway through the head at the nose tip's level, 10 mm lower.
  Eigen::Vector3d tip(0, -1e300, 0);
  for (vtkIdType p = 0; p < skinLocal->GetNumberOfPoints(); ++p)
  {
    double q[3];
    skinLocal->GetPoint(p, q);
    if (std::abs(q[0]) < 10 && q[1] > tip.y())
      tip = Eigen::Vector3d(q[0], q[1], q[2]);
  }
  double back = tip.y();
  for (vtkIdType p = 0; p < skinLocal->GetNumberOfPoints(); ++p)
  {
    double q[3];
    skinLocal->GetPoint(p, q);
    if (std::abs(q[0]) < 10 && std::abs(q[2] - tip.z()) < 10)
      back = std::min(back, q[1]);
  }
  atlas.centre = Eigen::Vector3d(0, 0.5 * (tip.y() + back), tip.z() - 10);
  const Eigen::Vector3d& c = atlas.centre;
  atlas.log.push_back(Format("face centre (local): anterior %.2f, superior %.2f mm; head depth at the nose %.1f mm",
                             c.y(), c.z(), tip.y() - back));

  // Landmarks.
  atlas.landmarks = DetectFaceLandmarks(skin, bone, c);
  const FaceLandmarkSet& lm = atlas.landmarks;
  for (const auto& l : lm.log)
    atlas.log.push_back(l);
  report(0.3);

  // --- Grid angles.
  auto profileAngle = [&](double from, double stepDeg, const std::function<bool(const FacePoint&)>& stop) {
    for (double a = from;; a += stepDeg * kDeg)
    {
      if (std::abs(a) > 85 * kDeg)
        throw std::runtime_error("face atlas: the face region does not close within +-85 deg of the face centre");
      const FacePoint p = SkinHit(skin, c, 0, a);
      if (stop(p))
        return a;
    }
  };
  const double phiTop =
    profileAngle(lm.nasion.phi, 0.25, [&](const FacePoint& p) { return p.local.z() >= lm.nasion.local.z() + options.browMargin; });
  const double phiBottom = profileAngle(lm.pogonion.phi, -0.25,
                                        [&](const FacePoint& p) { return p.local.z() <= lm.pogonion.local.z() - options.chinMargin; });
  const double radius = (lm.stomion.local - c).norm(); // nominal radius: mm -> radians
  const double rho = std::hypot(lm.lipCorner.local.x(), lm.lipCorner.local.y() - c.y());
  const double thetaMax = options.lateralAngle * kDeg;
  const double mouthLo = lm.labiomental.phi, mouthHi = lm.subnasale.phi;
  const double mouthLateral = lm.lipCorner.theta + 6.0 / rho;
  FaceGrid& grid = atlas.grid;
  grid.phi = Graded(phiBottom, phiTop, [&](double x) {
    return Size(x * radius, mouthLo * radius, mouthHi * radius, options.gradingLength, options.lipsMeshSize,
                options.meshSize) / radius;
  });
  grid.theta = Graded(0, thetaMax, [&](double x) {
    return Size(x * rho, -1e9, mouthLateral * rho, options.gradingLength, options.lipsMeshSize, options.meshSize) / rho;
  });
  grid.levels = {0, r[0] / (r[0] + r[1] + r[2]), (r[0] + r[1]) / (r[0] + r[1] + r[2]), 1.0};
  const int rows = grid.Rows(), cols = grid.Cols();
  atlas.log.push_back(Format("grid: %.0f rows (phi) x %.0f columns (theta), left half", rows, cols));

  // --- Skin nodes.
  std::vector<Eigen::Vector3d> outer(rows * cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
      outer[i * cols + j] = SkinHit(skin, c, grid.theta[j], grid.phi[i]).local;
  report(0.4);
  auto at = [&](const std::vector<Eigen::Vector3d>& f, int i, int j) {
    // Column -1 is the mirror image of column 1.
    if (j < 0)
    {
      Eigen::Vector3d m = f[i * cols - j];
      m.x() = -m.x();
      return m;
    }
    return f[i * cols + j];
  };
  // Smoothed outward skin normal from the grid (central differences, then two 3x3 averages).
  std::vector<Eigen::Vector3d> normal(rows * cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
    {
      const Eigen::Vector3d dt = at(outer, i, std::min(j + 1, cols - 1)) - at(outer, i, j == cols - 1 ? j - 1 : j - 1);
      const Eigen::Vector3d dp = at(outer, std::min(i + 1, rows - 1), j) - at(outer, std::max(i - 1, 0), j);
      Eigen::Vector3d n = dt.cross(dp); // left x up = posterior... outward is anterior: flip
      n = -n.normalized();
      normal[i * cols + j] = n;
    }
  for (int pass = 0; pass < 2; ++pass)
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
            sum += at(normal, ii, jj);
          }
        s[i * cols + j] = sum.normalized();
      }
    normal = s;
  }
  std::vector<Eigen::Vector3d> dir(rows * cols); // inward through-thickness direction
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
    {
      const Eigen::Vector3d ray = RayDirection(grid.theta[j], grid.phi[i]);
      Eigen::Vector3d d = -(1 - options.normalBlend) * ray - options.normalBlend * normal[i * cols + j];
      if (j == 0)
        d.x() = 0;
      dir[i * cols + j] = d.normalized();
    }

  // --- Bone depth along the direction.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> depth(rows * cols, nan);
  std::vector<char> mouth(rows * cols, 0);
  int shallow = 0;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
    {
      const int q = i * cols + j;
      // Over the mouth: ellipse through the subnasale, the labiomental fold and 6 mm past the corner.
      const double y = (grid.phi[i] - 0.5 * (mouthLo + mouthHi)) / (0.5 * (mouthHi - mouthLo));
      const double x = grid.theta[j] / mouthLateral;
      mouth[q] = x * x + y * y <= 1.0 ? 1 : 0;
      if (mouth[q])
        continue;
      const auto hit = bone.First(outer[q], outer[q] + options.maxBoneDepth * dir[q]);
      if (hit)
        depth[q] = (*hit - outer[q]).norm();
      if (depth[q] < options.minThickness)
        ++shallow; // depth stays a measurement for the outlier medians; rejected below
    }
  // Outliers: depths far from the median of their 5x5 neighbourhood.
  std::vector<double> accepted = depth;
  int outliers = 0;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
    {
      const int q = i * cols + j;
      if (std::isnan(depth[q]))
        continue;
      std::vector<double> n;
      for (int di = -2; di <= 2; ++di)
        for (int dj = -2; dj <= 2; ++dj)
        {
          const int ii = i + di, jj = std::abs(j + dj);
          if (ii >= 0 && ii < rows && jj < cols && !std::isnan(depth[ii * cols + jj]))
            n.push_back(depth[ii * cols + jj]);
        }
      std::nth_element(n.begin(), n.begin() + n.size() / 2, n.end());
      if (n.size() < 9 || std::abs(depth[q] - n[n.size() / 2]) > options.outlierDepth ||
          depth[q] < options.minThickness)
      {
        accepted[q] = nan;
        ++outliers;
      }
    }
  // Harmonic fill of the thickness where bone is not followed (Gauss-Seidel, fixed order).
  std::vector<double> thickness(rows * cols);
  double mean = 0;
  int boneCount = 0;
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
  for (int it = 0; it < 4000; ++it)
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
  atlas.log.push_back(Format("bone followed at %.0f of %.0f inner nodes (left half); %.0f depth outliers ignored",
                             boneCount, rows * cols, outliers));
  atlas.log.push_back(Format("%.0f bone crossings shallower than %.1f mm ignored; columns at least %.1f mm thick",
                             shallow, options.minThickness, options.minThickness));
  report(0.5);

  // --- Left-half nodes.
  grid.local.assign(grid.LeftNodeCount(), Eigen::Vector3d::Zero());
  std::vector<char> onBone(rows * cols, 0);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
    {
      const int q = i * cols + j;
      onBone[q] = std::isnan(accepted[q]) ? 0 : 1;
      for (int k = 0; k < 4; ++k)
      {
        Eigen::Vector3d p = outer[q] + grid.levels[k] * thickness[q] * dir[q];
        if (j == 0)
          p.x() = 0;
        grid.local[grid.LeftNode(i, j, k)] = p;
      }
    }

  // --- Mesh (world): left nodes, right mirrored nodes, left hexahedra, mirrored hexahedra.
  FEMesh& mesh = atlas.mesh;
  // World nodes from the left half's local positions: the left half as is, the right half its
  // exact mirror image (nodes on the plane, column 0, are shared).
  auto writeNodesFromLeftHalf = [&]() {
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < rows; ++i)
        for (int j = side; j < cols; ++j)
          for (int k = 0; k < 4; ++k)
          {
            Eigen::Vector3d p = grid.local[grid.LeftNode(i, j, k)];
            if (side == 1)
              p.x() = -p.x();
            mesh.nodes[grid.Node(i, j, k, side)] = frame.ToWorld(p);
          }
  };
  auto buildMesh = [&]() {
    mesh = FEMesh();
    mesh.nodes.resize(grid.LeftNodeCount() + rows * (cols - 1) * 4);
    writeNodesFromLeftHalf();
    mesh.mirror = grid.MirrorMap();
    mesh.elements.resize(2 * grid.LeftElementCount());
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i + 1 < rows; ++i)
        for (int j = 0; j + 1 < cols; ++j)
          for (int layer = 0; layer < 3; ++layer)
          {
            Element& e = mesh.elements[grid.Element(i, j, layer, side)];
            e.type = ElementType::Hexahedron;
            e.layer = static_cast<TissueLayer>(layer + 1);
            e.nodes = grid.Hexahedron(i, j, layer, side);
          }
  };
  buildMesh();
  {
    quality::QualityOptions qo;
    qo.threads = 1;
    const auto s = quality::SummarizeScaledJacobian(mesh, options.qualityThreshold, qo);
    atlas.log.push_back(Format("before repair: scaled Jacobian min %.3f, mean %.3f; %.0f elements below the threshold",
                               s.min, s.mean, s.belowThreshold));
  }
  report(0.7);

  // --- Node sets.
  auto& skinSet = mesh.nodeSets["skin"];
  auto& skullSet = mesh.nodeSets["skull"];
  auto& innerSet = mesh.nodeSets["inner"];
  auto& midSet = mesh.nodeSets["midsagittal"];
  auto& lipsSet = mesh.nodeSets["lips"];
  // Lips: the skin between the subnasale and the labiomental fold, out to 5 mm past the corner
  // (an ellipse in the (theta, phi) parameterisation, so the set follows the mouth's outline).
  const double lipsLateral = lm.lipCorner.theta + 5.0 / rho;
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < rows; ++i)
      for (int j = side; j < cols; ++j)
      {
        const int q = i * cols + j;
        skinSet.push_back(grid.Node(i, j, 0, side));
        (onBone[q] ? skullSet : innerSet).push_back(grid.Node(i, j, 3, side));
        if (j == 0)
          for (int k = 0; k < 4; ++k)
            midSet.push_back(grid.Node(i, j, k, side));
        const double y = (grid.phi[i] - 0.5 * (mouthLo + mouthHi)) / (0.5 * (mouthHi - mouthLo));
        const double x = grid.theta[j] / lipsLateral;
        if (x * x + y * y <= 1.0 && grid.phi[i] <= mouthHi && grid.phi[i] >= mouthLo)
          lipsSet.push_back(grid.Node(i, j, 0, side));
      }
  for (auto* set : {&skinSet, &skullSet, &innerSet, &midSet, &lipsSet})
    std::sort(set->begin(), set->end());

  // --- Reference surfaces: left half + mirror, cut to the atlas region.
  double box[6] = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  for (const auto& p : grid.local)
    for (int a = 0; a < 3; ++a)
    {
      box[2 * a] = std::min(box[2 * a], p(a) - 15);
      box[2 * a + 1] = std::max(box[2 * a + 1], p(a) + 15);
    }
  box[0] = -box[1];
  atlas.skinSurface = Symmetrised(skinLocal, frame, box);
  atlas.skullSurface = Symmetrised(skullLocal, frame, box);
  // --- Quality: repair (skin nodes slide on the skin, skull nodes on the bone, mid-sagittal
  // nodes on the plane), then exact re-symmetrisation from the left half.
  // Up to three rounds: the exact re-symmetrisation can push an element slightly back under.
  for (int round = 0; round < 3; ++round)
  {
    quality::QualityOptions qo;
    qo.threads = 1;
    if (quality::SummarizeScaledJacobian(mesh, options.qualityThreshold, qo).belowThreshold == 0)
      break;
    RepairOptions ro;
    ro.scaledJacobianThreshold = options.qualityThreshold + 0.05; // margin for the re-symmetrisation
    ro.skinSurface = atlas.skinSurface;
    ro.skullSurface = atlas.skullSurface;
    ro.hasSymmetryPlane = true;
    ro.symmetryPlane = plane;
    const RepairReport rep = RepairMesh(mesh, ro);
    atlas.repairedNodes += rep.movedNodes;
    atlas.log.push_back(Format("repair: %.0f nodes moved; scaled Jacobian min %.3f -> %.3f", rep.movedNodes,
                               rep.minScaledJacobianBefore, rep.minScaledJacobianAfter));
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j)
        for (int k = 0; k < 4; ++k)
        {
          Eigen::Vector3d p = frame.ToLocal(mesh.nodes[grid.LeftNode(i, j, k)]);
          if (j == 0)
            p.x() = 0;
          grid.local[grid.LeftNode(i, j, k)] = p;
        }
    writeNodesFromLeftHalf();
    const auto q = quality::SummarizeScaledJacobian(mesh, options.qualityThreshold, qo);
    atlas.log.push_back(Format("after repair and symmetrisation: scaled Jacobian min %.3f, mean %.3f; %.0f below the threshold",
                               q.min, q.mean, q.belowThreshold));
  }

  // Surface nodes exactly back onto their surfaces (the repair's sliding leaves them within a
  // fraction of a millimetre): closest points on the triangles, left half, then mirrored.
  {
    auto skinLoc = vtkSmartPointer<vtkStaticCellLocator>::New();
    skinLoc->SetDataSet(atlas.skinSurface);
    skinLoc->BuildLocator();
    auto skullLoc = vtkSmartPointer<vtkStaticCellLocator>::New();
    skullLoc->SetDataSet(atlas.skullSurface);
    skullLoc->BuildLocator();
    double worst = 0;
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j)
        for (int k : {0, 3})
        {
          if (k == 3 && !onBone[i * cols + j])
            continue;
          const int n = grid.LeftNode(i, j, k);
          double x[3] = {mesh.nodes[n].x(), mesh.nodes[n].y(), mesh.nodes[n].z()}, closest[3], d2;
          vtkIdType cell;
          int sub;
          (k == 0 ? skinLoc : skullLoc)->FindClosestPoint(x, closest, cell, sub, d2);
          worst = std::max(worst, std::sqrt(d2));
          Eigen::Vector3d p = frame.ToLocal(Eigen::Vector3d(closest[0], closest[1], closest[2]));
          if (j == 0)
            p.x() = 0;
          grid.local[n] = p;
        }
    writeNodesFromLeftHalf();
    quality::QualityOptions qo;
    qo.threads = 1;
    const auto q = quality::SummarizeScaledJacobian(mesh, options.qualityThreshold, qo);
    atlas.log.push_back(Format("surface nodes projected (largest move %.3f mm): scaled Jacobian min %.3f, mean %.3f", worst,
                               q.min, q.mean));
    // A mid-sagittal inner node is the closest bone point pushed back onto the plane: where the
    // bone meets the plane obliquely that leaves the bone. Such a node is not on the skull but
    // on the offset part of the inner surface (set `inner`), so `skull` means "on the bone".
    int demoted = 0;
    for (int i = 0; i < rows; ++i)
    {
      if (!onBone[i * cols])
        continue;
      const auto n = static_cast<std::int32_t>(grid.Node(i, 0, 3, 0));
      double x[3] = {mesh.nodes[n].x(), mesh.nodes[n].y(), mesh.nodes[n].z()}, closest[3], d2;
      vtkIdType cell;
      int sub;
      skullLoc->FindClosestPoint(x, closest, cell, sub, d2);
      if (std::sqrt(d2) <= 0.1)
        continue;
      onBone[i * cols] = 0;
      skullSet.erase(std::find(skullSet.begin(), skullSet.end(), n));
      innerSet.insert(std::upper_bound(innerSet.begin(), innerSet.end(), n), n);
      ++demoted;
    }
    atlas.log.push_back(Format("%.0f mid-sagittal inner nodes farther than 0.1 mm from the bone moved from set skull to inner",
                               demoted));
  }

  // --- Mouth slit and jaw (mmrepFaceMouth.h).
  const MouthSlitCells slit = MouthSlitCellsOf(grid, lm);
  const std::size_t twins = CutMouthSlit(mesh, grid, slit);
  atlas.log.push_back(Format("mouth slit: row %.0f, corner column %.0f, %.0f nodes doubled", slit.slitRow, slit.cornerColumn,
                             static_cast<double>(twins)));
  atlas.log.push_back(AddJaw(mesh, skullLocal, frame, lm));

  // --- Landmarks (world), muscles.
  const FacePoint* points[] = {&lm.eyeInner, &lm.eyeOuter, &lm.lipCorner, &lm.upperLip, &lm.lowerLip};
  for (std::size_t n = 0; n < 5; ++n)
    mesh.landmarks.push_back({FaceAtlasLandmarkNames()[n], frame.ToWorld(points[n]->local)});
  AddFaceMuscles(mesh, grid, frame, FaceMuscleRules(lm, c), options.muscleSpacing);
  std::sort(midSet.begin(), midSet.end());
  mesh.UpdateLayerSets();
  mesh.Validate();
  report(0.9);

  report(1.0);
  std::string t = "timings at 0.1 0.3 0.4 0.5 0.7 0.9 1.0:";
  for (const auto& x : timings)
    t += " " + x;
  atlas.log.push_back(t);
  return atlas;
}

} // namespace mmrep
