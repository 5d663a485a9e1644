// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepHeadReorientation.h"

#include "mmrepControlPointPlausibility.h"

#include <Eigen/Geometry>

#include <cmath>
#include <sstream>

namespace mmrep
{
namespace
{
// The signed coordinate axis nearest `v`, skipping axis `not` (-1: none).
Eigen::Vector3d NearestAxis(const Eigen::Vector3d& v, int skip)
{
  int axis = -1;
  for (int a = 0; a < 3; ++a)
    if (a != skip && (axis < 0 || std::abs(v[a]) > std::abs(v[axis])))
      axis = a;
  Eigen::Vector3d e = Eigen::Vector3d::Zero();
  e[axis] = v[axis] >= 0 ? 1.0 : -1.0;
  return e;
}

int AxisOf(const Eigen::Vector3d& e)
{
  return std::abs(e.x()) > 0.5 ? 0 : std::abs(e.y()) > 0.5 ? 1 : 2;
}

std::string InWords(const Eigen::Vector3d& e)
{
  static const char* words[3][2] = {
    {"the patient's right", "the patient's left"}, {"the front", "the back"}, {"the feet", "the top"}};
  const int a = AxisOf(e);
  return words[a][e[a] > 0 ? 1 : 0];
}
} // namespace

HeadReorientation FaceUprightRotation(const FEMesh& atlas, const std::vector<Point3>& targets, double maxTurn)
{
  HeadReorientation r;
  const ControlPointConfiguration c = AssessControlPoints(atlas, targets);
  if (!(c.turn > maxTurn || c.tilt > maxTurn))
    return r;
  // Stored frame: the face looks to A, its top to S (snapped to axes); the atlas's face looks to the
  // front (-y in LPS) with its top up (+z). The rotation takes A to -y and S to +z.
  const Eigen::Vector3d front = NearestAxis(c.anterior, -1);
  const Eigen::Vector3d top = NearestAxis(c.superior, AxisOf(front));
  Eigen::Matrix3d stored, upright;
  stored << front, top, front.cross(top);
  upright << -Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(),
    (-Eigen::Vector3d::UnitY()).cross(Eigen::Vector3d::UnitZ());
  r.rotation = upright * stored.transpose();
  r.applied = !r.rotation.isIdentity(1e-12);
  r.before = "looking to " + InWords(front) + ", its top to " + InWords(top);
  return r;
}

std::string ReorientationInWords(const HeadReorientation& r)
{
  std::ostringstream s;
  s << "the CT's orientation header was corrected (--reorientToFace): the face was " << r.before
    << "; the model is in the corrected LPS frame, corrected = R · stored with R = [";
  for (int i = 0; i < 3; ++i)
    s << (i ? "; " : "") << r.rotation(i, 0) << " " << r.rotation(i, 1) << " " << r.rotation(i, 2);
  s << "]";
  return s.str();
}

CTImage::Pointer ReorientedCT(const CTImage* ct, const Eigen::Matrix3d& rotation)
{
  auto turned = CTImage::New();
  turned->SetRegions(ct->GetLargestPossibleRegion());
  turned->SetSpacing(ct->GetSpacing());
  turned->SetPixelContainer(const_cast<CTImage*>(ct)->GetPixelContainer());
  CTImage::DirectionType direction;
  const auto& d = ct->GetDirection();
  CTImage::PointType origin;
  for (unsigned i = 0; i < 3; ++i)
  {
    origin[i] = 0;
    for (unsigned k = 0; k < 3; ++k)
      origin[i] += rotation(i, k) * ct->GetOrigin()[k];
    for (unsigned j = 0; j < 3; ++j)
    {
      direction(i, j) = 0;
      for (unsigned k = 0; k < 3; ++k)
        direction(i, j) += rotation(i, k) * d(k, j);
    }
  }
  turned->SetDirection(direction);
  turned->SetOrigin(origin);
  return turned;
}

} // namespace mmrep
