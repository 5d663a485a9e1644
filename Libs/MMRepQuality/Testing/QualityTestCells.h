// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Test cells (unit, sheared, tapered, twisted, randomly perturbed, inverted, mirrored, degenerate)
// and helpers to evaluate the same cell with VTK.
#pragma once

#include "mmrepVerdictMath.h"

#include <Eigen/LU>
#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkHexahedron.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkTetra.h>
#include <vtkWedge.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace mmrep::quality::test
{

template <std::size_t N> struct NamedCell
{
  std::string name;
  std::array<Point3, N> nodes;
};

template <std::size_t N>
std::array<Point3, N> Transformed(std::array<Point3, N> p, const Eigen::Matrix3d& a, const Point3& t = Point3::Zero())
{
  for (Point3& x : p)
    x = a * x + t;
  return p;
}

inline Eigen::Matrix3d Mirror()
{
  return Eigen::Vector3d(-1, 1, 1).asDiagonal();
}

inline Eigen::Matrix3d Shear()
{
  Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
  a(0, 1) = 0.6;
  a(1, 2) = -0.3;
  return a;
}

// A generic rotation and anisotropic scale, so no measure sees axis-aligned data only.
inline Eigen::Matrix3d General()
{
  Eigen::Matrix3d a;
  a << 2.0, 0.3, -0.1, 0.2, 1.5, 0.4, -0.3, 0.1, 0.8;
  return a;
}

// Cells of one type: base shapes, deformed copies, random perturbations, inverted and mirrored ones.
template <std::size_t N>
std::vector<NamedCell<N>> MakeCells(const std::array<Point3, N>& unit, int randomCount, unsigned seed)
{
  std::vector<NamedCell<N>> cells;
  cells.push_back({"unit", unit});
  cells.push_back({"scaled", Transformed(unit, Eigen::Vector3d(3.0, 0.5, 1.7).asDiagonal(), Point3(10, -4, 2))});
  cells.push_back({"sheared", Transformed(unit, Shear())});
  cells.push_back({"general", Transformed(unit, General(), Point3(-1, 2, 3))});
  // Tapered: the top shrinks towards its centre.
  {
    auto p = unit;
    for (Point3& x : p)
      if (x.z() > 0.5)
        x = Point3(0.3 + 0.4 * x.x(), 0.3 + 0.4 * x.y(), x.z());
    cells.push_back({"tapered", p});
  }
  // Twisted: the top is rotated about the vertical axis.
  {
    auto p = unit;
    const double angle = 0.7;
    for (Point3& x : p)
      if (x.z() > 0.5)
      {
        const Point3 d = x - Point3(0.5, 0.5, 0);
        x = Point3(0.5 + std::cos(angle) * d.x() - std::sin(angle) * d.y(),
                   0.5 + std::sin(angle) * d.x() + std::cos(angle) * d.y(), x.z());
      }
    cells.push_back({"twisted", p});
  }
  // Inverted: node 0 pushed through the opposite side.
  {
    auto p = unit;
    Point3 centroid = Point3::Zero();
    for (const Point3& x : p)
      centroid += x;
    centroid /= static_cast<double>(N);
    p[0] = p[0] + 2.5 * (centroid - p[0]);
    cells.push_back({"inverted", p});
  }
  cells.push_back({"mirrored", Transformed(unit, Mirror())});
  cells.push_back({"mirroredGeneral", Transformed(unit, Mirror() * General())});
  // Degenerate: a collapsed edge (node 1 onto node 0), and a flattened cell.
  {
    auto p = unit;
    p[1] = p[0];
    cells.push_back({"collapsedEdge", p});
  }
  cells.push_back({"flat", Transformed(unit, Eigen::Vector3d(1, 1, 0).asDiagonal())});
  {
    std::array<Point3, N> p;
    p.fill(Point3(1, 2, 3));
    cells.push_back({"point", p});
  }
  // Randomly perturbed copies (fixed seed): mostly valid, some inverted by strong perturbations.
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> small(-0.25, 0.25), large(-0.7, 0.7);
  for (int i = 0; i < randomCount; ++i)
  {
    auto p = Transformed(unit, General());
    auto& d = i % 3 == 2 ? large : small;
    for (Point3& x : p)
      x += Point3(d(rng), d(rng), d(rng));
    cells.push_back({"random" + std::to_string(i), p});
  }
  return cells;
}

// VTK-ordered unit cells.
inline std::array<Point3, 8> UnitHex()
{
  return {Point3(0, 0, 0), Point3(1, 0, 0), Point3(1, 1, 0), Point3(0, 1, 0),
          Point3(0, 0, 1), Point3(1, 0, 1), Point3(1, 1, 1), Point3(0, 1, 1)};
}
inline std::array<Point3, 4> UnitTet()
{
  return {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1)};
}
// Right prism on the equilateral unit triangle, unit height, in VTK order (base normal points down).
inline std::array<Point3, 6> UnitWedge()
{
  const double h = std::sqrt(3.0) / 2;
  return {Point3(0, 0, 0), Point3(0.5, h, 0), Point3(1, 0, 0), Point3(0, 0, 1), Point3(0.5, h, 1), Point3(1, 0, 1)};
}

template <class CellType, std::size_t N> vtkSmartPointer<CellType> MakeVtkCell(const std::array<Point3, N>& p)
{
  auto cell = vtkSmartPointer<CellType>::New();
  for (std::size_t i = 0; i < N; ++i)
  {
    cell->GetPointIds()->SetId(static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
    cell->GetPoints()->SetPoint(static_cast<vtkIdType>(i), p[i].data());
  }
  return cell;
}

// Equal as Verdict values: both NaN, both the same flag, or within a relative 1e-9 (absolute near 0,
// relative to the cell's natural magnitude `scale`).
inline ::testing::AssertionResult SameQuality(double ours, double reference, double scale = 1.0)
{
  if (std::isnan(ours) && std::isnan(reference))
    return ::testing::AssertionSuccess();
  if (ours == reference)
    return ::testing::AssertionSuccess();
  const double tolerance = 1e-9 * std::max({std::abs(reference), std::abs(ours), scale * 1e-3});
  if (std::abs(ours - reference) <= tolerance)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "ours " << ours << " vs reference " << reference << " (difference "
                                       << ours - reference << ")";
}

} // namespace mmrep::quality::test
