// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Test stand-in for the face atlas and its registration defects: a 3-layer hexahedral shell cut
// from an ellipsoidal shell (the front of a head: epidermis, dermis, hypodermis), symmetric about
// x = 0, with node sets skin (outer), skull (inner), lips (a patch of outer nodes) and midsagittal
// (x = 0), and the exact outer/inner ellipsoids finely triangulated as skin/skull surfaces; plus
// perturbations that tangle it: random node noise, local folds (a node pushed through the next
// layer or past its neighbour) and extreme smooth warps. Perturbations act on the nodes'
// parametric coordinates (azimuth, elevation, depth), so skin and skull nodes stay on their
// ellipsoids as they would after a surface registration.
#pragma once

#include "mmrepFEMesh.h"

#include <Eigen/Core>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace mmrep::testing
{

// Uniform in [0, 1) and Gaussian numbers from mt19937 bits only, so every platform draws the same.
class Random
{
public:
  explicit Random(std::uint32_t seed) : engine_(seed) {}
  double Uniform() { return (engine_() >> 5) * (1.0 / 134217728.0); }
  double Gaussian()
  {
    const double u = 1.0 - Uniform(), v = Uniform();
    return std::sqrt(-2 * std::log(u)) * std::cos(2 * M_PI * v);
  }
  int Integer(int lo, int hi) { return lo + static_cast<int>(Uniform() * (hi - lo + 1)); } // [lo, hi]

private:
  std::mt19937 engine_;
};

struct ShellAtlasOptions
{
  int columns = 24;                       // elements left to right (even: x = 0 is a node column)
  int rows = 20;                          // elements bottom to top
  Eigen::Vector3d skinAxes{80, 100, 115}; // outer ellipsoid semi-axes (x, y, z), mm
  double thickness = 14;                  // inner ellipsoid axes = outer axes - thickness
  double halfWidth = 1.3;                 // azimuth range [-halfWidth, halfWidth], radians
  double halfHeight = 0.95;               // elevation range, radians
  int surfaceRefinement = 4;              // surface triangles per element edge (mesh nodes are vertices)
};

struct ShellAtlas
{
  ShellAtlasOptions options;
  FEMesh mesh;
  vtkSmartPointer<vtkPolyData> skin, skull;
  // Per node: (column, row, depth level) grid indices, column in [-columns/2, columns/2].
  std::vector<Eigen::Vector3i> grid;
};

// Depth of each of the 4 node levels, 0 (skin) to 1 (skull).
const std::array<double, 4>& LayerDepths();
// Point at azimuth theta, elevation phi and depth w; exactly mirrored (x negated) for -theta.
Point3 ShellPoint(const ShellAtlasOptions& options, double theta, double phi, double depth);
ShellAtlas MakeShellAtlas(const ShellAtlasOptions& options = {});

struct TangleOptions
{
  std::uint32_t seed = 1;
  bool symmetric = false; // mirror every perturbation (the result stays symmetric about x = 0)
  double noise = 0.2;     // Gaussian node noise, standard deviation in element sizes
  int folds = 2;          // nodes pushed through a neighbour
  double warp = 0;        // amplitude of the smooth warps, in element sizes
};

// The atlas with perturbed nodes (same sets and elements).
FEMesh Tangle(const ShellAtlas& atlas, const TangleOptions& options);
// A random mix of node noise (standard deviation uniform in [0.03, maximumNoise] element sizes),
// 0 to 4 folds and, in half the cases, a warp of 0.5 to 2 element sizes; symmetric for even seeds.
// The default noise is registration-like; 0.3 makes every surface visibly rough.
TangleOptions RandomTangle(std::uint32_t seed, double maximumNoise = 0.18);

} // namespace mmrep::testing
