// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Jacobian frames, see mmrepJacobianFrames.h.
#include "mmrepJacobianFrames.h"

#include <Eigen/LU>

#include <cmath>

namespace mmrep
{
namespace
{
// Corner frames (origin; three neighbours) oriented like the quality library's corner Jacobians.
constexpr int kHexCorners[8][4] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                                   {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};
constexpr int kWedgeCorners[6][4] = {{0, 2, 1, 3}, {1, 0, 2, 4}, {2, 1, 0, 5},
                                     {3, 0, 4, 5}, {4, 1, 5, 3}, {5, 4, 2, 3}};
constexpr int kTetCorner[4] = {0, 1, 2, 3};
// Node k of the reference box sits at parametric corner (sx, sy, sz) in {0, 1}^3.
constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

JacobianFrame PointFrame(const Element& element, std::size_t e, const Eigen::Vector3d& p, const Eigen::Vector3d& size,
                         double weight);

// The reference box's edge lengths along the three parametric axes: the element's mean edges.
Eigen::Vector3d BoxSize(const FEMesh& mesh, const Element& element);

double MeanLength(const FEMesh& mesh, const Element& element, std::initializer_list<std::pair<int, int>> edges)
{
  double sum = 0;
  for (const auto& [a, b] : edges)
    sum += (mesh.nodes[element.nodes[a]] - mesh.nodes[element.nodes[b]]).norm();
  const double mean = sum / double(edges.size());
  return mean > 0 ? mean : 1.0; // a collapsed element still gets a usable reference
}

// The frame at `corner` of an element whose ideal shape has nodes `reference`.
void AppendCorner(const Element& element, std::size_t e, const int corner[4], const Point3* reference, double weight,
                  std::vector<JacobianFrame>& frames)
{
  Eigen::Matrix3d s;
  for (int j = 0; j < 3; ++j)
    s.col(j) = reference[corner[j + 1]] - reference[corner[0]];
  const Eigen::Matrix3d inverse = s.inverse();
  JacobianFrame frame;
  frame.element = static_cast<std::uint32_t>(e);
  frame.count = 4;
  frame.weight = weight;
  frame.nodes[0] = element.nodes[corner[0]];
  frame.w[0] = Eigen::Vector3d::Zero();
  for (int j = 0; j < 3; ++j)
  {
    frame.nodes[j + 1] = element.nodes[corner[j + 1]];
    frame.w[j + 1] = inverse.row(j).transpose();
    frame.w[0] -= frame.w[j + 1];
  }
  frames.push_back(frame);
}

void AppendHexahedron(const FEMesh& mesh, std::size_t e, std::vector<JacobianFrame>& frames)
{
  const Element& element = mesh.elements[e];
  const Eigen::Vector3d size = BoxSize(mesh, element);
  const double a = size.x(), b = size.y(), c = size.z();
  Point3 reference[8];
  for (int k = 0; k < 8; ++k)
    reference[k] = Point3(a * kCorner[k][0], b * kCorner[k][1], c * kCorner[k][2]);
  const double weight = a * b * c / 9.0;
  for (const auto& corner : kHexCorners)
    AppendCorner(element, e, corner, reference, weight, frames);
  frames.push_back(PointFrame(element, e, Eigen::Vector3d::Constant(0.5), size, weight));
}

// The trilinear map's derivative at the parametric point p in [0, 1]^3, divided by the box's.
JacobianFrame PointFrame(const Element& element, std::size_t e, const Eigen::Vector3d& p, const Eigen::Vector3d& size,
                         double weight)
{
  JacobianFrame frame;
  frame.element = static_cast<std::uint32_t>(e);
  frame.count = 8;
  frame.weight = weight;
  frame.corner = false;
  for (int n = 0; n < 8; ++n)
  {
    double value[3], slope[3]; // the shape function's factor along each axis and its derivative
    for (int axis = 0; axis < 3; ++axis)
    {
      const bool one = kCorner[n][axis] != 0;
      value[axis] = one ? p[axis] : 1 - p[axis];
      slope[axis] = one ? 1 : -1;
    }
    frame.nodes[n] = element.nodes[n];
    frame.w[n] =
      Eigen::Vector3d(slope[0] * value[1] * value[2], value[0] * slope[1] * value[2], value[0] * value[1] * slope[2])
        .cwiseQuotient(size);
  }
  return frame;
}

Eigen::Vector3d BoxSize(const FEMesh& mesh, const Element& element)
{
  return {MeanLength(mesh, element, {{0, 1}, {3, 2}, {4, 5}, {7, 6}}),
          MeanLength(mesh, element, {{0, 3}, {1, 2}, {4, 7}, {5, 6}}),
          MeanLength(mesh, element, {{0, 4}, {1, 5}, {2, 6}, {3, 7}})};
}

void AppendWedge(const FEMesh& mesh, std::size_t e, std::vector<JacobianFrame>& frames)
{
  const Element& element = mesh.elements[e];
  const double s = MeanLength(mesh, element, {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}});
  const double h = MeanLength(mesh, element, {{0, 3}, {1, 4}, {2, 5}});
  // VTK's wedge: the triangle 0-1-2 turns clockwise seen from the triangle 3-4-5.
  const Point3 base[3] = {Point3(0, 0, 0), Point3(s / 2, s * std::sqrt(3.0) / 2, 0), Point3(s, 0, 0)};
  Point3 reference[6];
  for (int k = 0; k < 3; ++k)
  {
    reference[k] = base[k];
    reference[k + 3] = base[k] + Point3(0, 0, h);
  }
  const double weight = std::sqrt(3.0) / 4 * s * s * h / 6.0;
  for (const auto& corner : kWedgeCorners)
    AppendCorner(element, e, corner, reference, weight, frames);
}

void AppendTetrahedron(const FEMesh& mesh, std::size_t e, std::vector<JacobianFrame>& frames)
{
  const Element& element = mesh.elements[e];
  const double s = MeanLength(mesh, element, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}});
  const Point3 reference[4] = {Point3(0, 0, 0), Point3(s, 0, 0), Point3(s / 2, s * std::sqrt(3.0) / 2, 0),
                               Point3(s / 2, s * std::sqrt(3.0) / 6, s * std::sqrt(2.0 / 3.0))};
  AppendCorner(element, e, kTetCorner, reference, s * s * s / (6 * std::sqrt(2.0)), frames);
}
} // namespace

void AppendJacobianFrames(const FEMesh& mesh, std::size_t e, std::vector<JacobianFrame>& frames)
{
  switch (mesh.elements[e].type)
  {
    case ElementType::Hexahedron:
      AppendHexahedron(mesh, e, frames);
      break;
    case ElementType::Wedge:
      AppendWedge(mesh, e, frames);
      break;
    case ElementType::Tetrahedron:
      AppendTetrahedron(mesh, e, frames);
      break;
    case ElementType::Cable:
      break;
  }
}

Eigen::Matrix3d FrameJacobian(const JacobianFrame& frame, const std::vector<Point3>& nodes)
{
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  for (int k = 0; k < frame.count; ++k)
    j.noalias() += nodes[frame.nodes[k]] * frame.w[k].transpose();
  return j;
}

} // namespace mmrep
