// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Element quality over a whole FE mesh: every measure of mmrepHex/Tet/WedgeQuality.h evaluated per
// element (in parallel, with results independent of the thread count), corner Jacobians for the
// repair stage, and a summary (min / mean / max, count below a threshold, inverted elements).
#pragma once

#include "mmrepFEMesh.h"
#include "mmrepVerdictMath.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace mmrep::quality
{

// Measures, named as in vtkMeshQuality. A measure not defined for an element type (or any measure
// on a cable element) evaluates to NaN.
enum class Measure
{
  Jacobian,           // hex, tet, wedge: minimum corner Jacobian determinant (hex: and centre)
  ScaledJacobian,     // hex, tet, wedge
  Shape,              // hex, tet, wedge
  EdgeRatio,          // hex, tet, wedge
  MaxAspectFrobenius, // hex
  MedAspectFrobenius, // hex
  MaxEdgeRatio,       // hex
  Skew,               // hex
  Taper,              // hex
  Stretch,            // hex
  Diagonal,           // hex
  Shear,              // hex
  Oddy,               // hex
  Condition,          // hex, tet
  AspectRatio,        // tet
  AspectFrobenius,    // tet
  AspectBeta,         // tet
  AspectGamma,        // tet
  RadiusRatio,        // tet
  MinAngle,           // tet
  CollapseRatio,      // tet
  Volume              // hex (VTK 9.1: centre Jacobian), tet
};

const std::vector<Measure>& AllMeasures(); // in enum order
const char* MeasureName(Measure measure);  // "ScaledJacobian", …
bool IsDefined(Measure measure, ElementType type);

// One element's measure; NaN when undefined for its type. Node indices must be valid.
double ElementQuality(const FEMesh& mesh, std::size_t element, Measure measure);
// Corner Jacobian determinants of one solid element, entry i at the element's i-th node (8 for a
// hex, 6 for a wedge, 4 equal values for a tet); empty for a cable. Positive for a valid element.
std::vector<double> CornerJacobians(const FEMesh& mesh, std::size_t element);

struct QualityOptions
{
  int threads = 0; // 0: hardware concurrency
  // Called from the calling thread with the fraction of elements done, never decreasing.
  std::function<void(double)> progress;
};

// values[m][e] = measures[m] of element e. Each element is computed independently by exactly one
// thread, so the result is bitwise identical for any thread count. Throws std::invalid_argument
// naming the element when a node index is out of range.
std::vector<std::vector<double>> ComputeQuality(const FEMesh& mesh, const std::vector<Measure>& measures,
                                                const QualityOptions& options = {});
std::vector<double> ComputeQuality(const FEMesh& mesh, Measure measure, const QualityOptions& options = {});

struct QualitySummary
{
  std::size_t count = 0;             // elements where the measure is defined (solid elements)
  std::size_t degenerate = 0;        // of which flagged ±kVerdictMax by Verdict (e.g. a zero-length edge)
  double min = 0, mean = 0, max = 0; // over the defined, non-flagged values; NaN when there are none
  std::size_t belowThreshold = 0;    // value < threshold, degenerate elements included
  std::size_t inverted = 0;          // elements whose Jacobian measure is negative
};

// Summary of per-element values (one per element, NaN = undefined) given the per-element Jacobian
// measure for the inverted count. Sums in element order: deterministic.
QualitySummary Summarize(const std::vector<double>& values, const std::vector<double>& jacobians, double threshold);
// Summary of the scaled Jacobian (the threshold applies to it) over the mesh's solid elements.
QualitySummary SummarizeScaledJacobian(const FEMesh& mesh, double threshold, const QualityOptions& options = {});

} // namespace mmrep::quality
