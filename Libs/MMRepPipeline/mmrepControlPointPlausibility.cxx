// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepControlPointPlausibility.h"

#include "mmrepPlane.h"
#include "mmrepSimilarityTransform.h"
#include "mmrepSurfaceDistance.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace mmrep
{
namespace
{
constexpr double kDegrees = 180.0 / 3.14159265358979323846;

std::string Mm(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", v);
  return text;
}

double AngleDegrees(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::acos(std::max(-1.0, std::min(1.0, a.normalized().dot(b.normalized())))) * kDegrees;
}

} // namespace

bool AtlasFaceFrame(const FEMesh& atlas, Eigen::Vector3d& anterior, Eigen::Vector3d& superior)
{
  Eigen::Vector3d eyes = Eigen::Vector3d::Zero(), lips = Eigen::Vector3d::Zero();
  int nEyes = 0, nLips = 0;
  for (const auto& l : atlas.landmarks)
    if (l.name.find("Eye") != std::string::npos)
      eyes += l.position, ++nEyes;
    else if (l.name.find("Lip") != std::string::npos)
      lips += l.position, ++nLips;
  if (nEyes == 0 || nLips == 0 || !atlas.nodeSets.count("midsagittal"))
    return false;
  const Eigen::Vector3d left = FitPlaneToNodeSet(atlas, "midsagittal").normal;
  Eigen::Vector3d up = eyes / nEyes - lips / nLips;
  up -= up.dot(left) * left;
  if (up.norm() < 1e-6)
    return false;
  superior = up.normalized();
  anterior = left.cross(superior).normalized(); // L x S = A in LPS (x L, y P, z S)
  return true;
}

std::string DirectionInWords(const Eigen::Vector3d& d)
{
  static const char* const words[3][2] = {
    {"the patient's right", "the patient's left"}, {"the front", "the back"}, {"the feet", "the top (superior)"}};
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(d[a]) > std::abs(d[axis]))
      axis = a;
  return words[axis][d[axis] > 0 ? 1 : 0];
}

ControlPointConfiguration AssessControlPoints(const FEMesh& atlas, const std::vector<Point3>& targets)
{
  std::vector<Eigen::Vector3d> source;
  for (std::size_t i = 0; i < targets.size(); ++i)
    source.push_back(atlas.landmarks.at(i).position);
  ControlPointConfiguration c;
  const SimilarityTransform all =
    EstimateSimilarity(source, std::vector<Eigen::Vector3d>(targets.begin(), targets.end()));
  c.scale = all.scale;
  for (std::size_t i = 0; i < targets.size(); ++i)
  {
    std::vector<Eigen::Vector3d> s, t;
    for (std::size_t j = 0; j < targets.size(); ++j)
      if (j != i)
      {
        s.push_back(source[j]);
        t.push_back(targets[j]);
      }
    double residual = std::numeric_limits<double>::quiet_NaN();
    try
    {
      residual = (EstimateSimilarity(s, t).Apply(source[i]) - targets[i]).norm();
    }
    catch (const std::invalid_argument&)
    {
      // the other points are collinear: this point is needed to place the face at all
    }
    c.leaveOneOut.push_back(residual);
  }
  Eigen::Vector3d anterior, superior;
  if (AtlasFaceFrame(atlas, anterior, superior))
  {
    c.anterior = (all.rotation * anterior).normalized();
    c.superior = (all.rotation * superior).normalized();
    c.turn = AngleDegrees(c.anterior, anterior);
    c.tilt = AngleDegrees(c.superior, superior);
  }
  return c;
}

void CheckControlPointConfiguration(const FEMesh& atlas, const std::vector<std::string>& names,
                                    const std::vector<Point3>& targets, const ControlPointBounds& bounds)
{
  ControlPointConfiguration c;
  try
  {
    c = AssessControlPoints(atlas, targets);
  }
  catch (const std::invalid_argument& e)
  {
    throw std::invalid_argument(std::string("control points: they place no face (coincident or collinear): ") +
                                e.what());
  }
  if (c.turn > bounds.maxTurn || c.tilt > bounds.maxTurn)
    throw std::invalid_argument(
      "the CT's orientation header looks wrong: the control points have the face looking to " +
      DirectionInWords(c.anterior) + " and its top pointing to " + DirectionInWords(c.superior) +
      " (an upright face in LPS looks to the front; turned " + Mm(std::max(c.turn, c.tilt)) +
      " degrees): fix the CT's space directions, pass --reorientToFace to turn it upright, or --trustControlPoints");
  if (c.scale < bounds.minScale || c.scale > bounds.maxScale)
    throw std::invalid_argument("control points: they span " + Mm(c.scale) +
                                " times the atlas's face (check coordinateUnits; a face is 0.6 to 1.6 times the "
                                "atlas's), or pass --trustControlPoints");
  std::size_t worst = 0;
  double worstResidual = 0; // NaN (a point the others cannot place without) never counts
  for (std::size_t i = 0; i < c.leaveOneOut.size(); ++i)
    if (c.leaveOneOut[i] > worstResidual)
    {
      worst = i;
      worstResidual = c.leaveOneOut[i];
    }
  if (worstResidual > bounds.leaveOneOut)
    throw std::invalid_argument("control points: '" + names.at(worst) + "' lies " + Mm(worstResidual) +
                                " mm from where the other points place it on the atlas's face (at most " +
                                Mm(bounds.leaveOneOut) +
                                "): is it mislabelled, swapped or on another feature? (--trustControlPoints)");
}

void CheckControlPointsOnSkin(vtkPolyData* skin, const std::vector<std::string>& names,
                              const std::vector<Point3>& targets, const ControlPointBounds& bounds)
{
  std::vector<std::int32_t> ids;
  for (std::size_t i = 0; i < targets.size(); ++i)
    ids.push_back(static_cast<std::int32_t>(i));
  const std::vector<double> d = NodeSurfaceDistances(targets, ids, skin);
  std::size_t worst = 0;
  for (std::size_t i = 1; i < d.size(); ++i)
    if (d[i] > d[worst])
      worst = i;
  if (!d.empty() && d[worst] > bounds.maxSkinDistance)
    throw std::invalid_argument("control points: '" + names.at(worst) + "' lies " + Mm(d[worst]) +
                                " mm from the skin (at most " + Mm(bounds.maxSkinDistance) +
                                "): control points are placed on the skin; check their coordinates (LPS vs RAS, "
                                "units) and the CT's orientation, or pass --trustControlPoints");
}

} // namespace mmrep
