// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Per-mesh quality evaluation and summary, see mmrepMeshQuality.h.
#include "mmrepMeshQuality.h"
#include "mmrepWorkerThreads.h"

#include "mmrepHexQuality.h"
#include "mmrepTetQuality.h"
#include "mmrepWedgeQuality.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <stdexcept>
#include <thread>

namespace mmrep::quality
{
namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <std::size_t N> std::array<Point3, N> Nodes(const FEMesh& mesh, const Element& e)
{
  std::array<Point3, N> p;
  for (std::size_t i = 0; i < N; ++i)
    p[i] = mesh.nodes[static_cast<std::size_t>(e.nodes[i])];
  return p;
}

double Hex(const HexNodes& p, Measure m)
{
  switch (m)
  {
    case Measure::Jacobian:
      return HexJacobian(p);
    case Measure::ScaledJacobian:
      return HexScaledJacobian(p);
    case Measure::Shape:
      return HexShape(p);
    case Measure::EdgeRatio:
      return HexEdgeRatio(p);
    case Measure::MaxAspectFrobenius:
      return HexMaxAspectFrobenius(p);
    case Measure::MedAspectFrobenius:
      return HexMedAspectFrobenius(p);
    case Measure::MaxEdgeRatio:
      return HexMaxEdgeRatio(p);
    case Measure::Skew:
      return HexSkew(p);
    case Measure::Taper:
      return HexTaper(p);
    case Measure::Stretch:
      return HexStretch(p);
    case Measure::Diagonal:
      return HexDiagonal(p);
    case Measure::Shear:
      return HexShear(p);
    case Measure::Oddy:
      return HexOddy(p);
    case Measure::Condition:
      return HexCondition(p);
    case Measure::Volume:
      return HexVolume(p);
    default:
      return kNaN;
  }
}

double Tet(const TetNodes& p, Measure m)
{
  switch (m)
  {
    case Measure::Jacobian:
      return TetJacobian(p);
    case Measure::ScaledJacobian:
      return TetScaledJacobian(p);
    case Measure::Shape:
      return TetShape(p);
    case Measure::EdgeRatio:
      return TetEdgeRatio(p);
    case Measure::Condition:
      return TetCondition(p);
    case Measure::AspectRatio:
      return TetAspectRatio(p);
    case Measure::AspectFrobenius:
      return TetAspectFrobenius(p);
    case Measure::AspectBeta:
      return TetAspectBeta(p);
    case Measure::AspectGamma:
      return TetAspectGamma(p);
    case Measure::RadiusRatio:
      return TetRadiusRatio(p);
    case Measure::MinAngle:
      return TetMinAngle(p);
    case Measure::CollapseRatio:
      return TetCollapseRatio(p);
    case Measure::Volume:
      return TetVolume(p);
    default:
      return kNaN;
  }
}

double Wedge(const WedgeNodes& p, Measure m)
{
  switch (m)
  {
    case Measure::Jacobian:
      return WedgeJacobian(p);
    case Measure::ScaledJacobian:
      return WedgeScaledJacobian(p);
    case Measure::Shape:
      return WedgeShape(p);
    case Measure::EdgeRatio:
      return WedgeEdgeRatio(p);
    default:
      return kNaN;
  }
}

void CheckNodes(const FEMesh& mesh)
{
  const auto n = static_cast<std::int64_t>(mesh.nodes.size());
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
  {
    const Element& element = mesh.elements[e];
    for (int i = 0; i < NodeCount(element.type); ++i)
      if (element.nodes[i] < 0 || element.nodes[i] >= n)
        throw std::invalid_argument("element " + std::to_string(e) + " (" + ElementTypeName(element.type) +
                                    ") refers to node " + std::to_string(element.nodes[i]) + ", but the mesh has " +
                                    std::to_string(n) + " nodes");
  }
}
} // namespace

const std::vector<Measure>& AllMeasures()
{
  static const std::vector<Measure> all = [] {
    std::vector<Measure> v;
    for (int m = 0; m <= static_cast<int>(Measure::Volume); ++m)
      v.push_back(static_cast<Measure>(m));
    return v;
  }();
  return all;
}

const char* MeasureName(Measure measure)
{
  switch (measure)
  {
    case Measure::Jacobian:
      return "Jacobian";
    case Measure::ScaledJacobian:
      return "ScaledJacobian";
    case Measure::Shape:
      return "Shape";
    case Measure::EdgeRatio:
      return "EdgeRatio";
    case Measure::MaxAspectFrobenius:
      return "MaxAspectFrobenius";
    case Measure::MedAspectFrobenius:
      return "MedAspectFrobenius";
    case Measure::MaxEdgeRatio:
      return "MaxEdgeRatio";
    case Measure::Skew:
      return "Skew";
    case Measure::Taper:
      return "Taper";
    case Measure::Stretch:
      return "Stretch";
    case Measure::Diagonal:
      return "Diagonal";
    case Measure::Shear:
      return "Shear";
    case Measure::Oddy:
      return "Oddy";
    case Measure::Condition:
      return "Condition";
    case Measure::AspectRatio:
      return "AspectRatio";
    case Measure::AspectFrobenius:
      return "AspectFrobenius";
    case Measure::AspectBeta:
      return "AspectBeta";
    case Measure::AspectGamma:
      return "AspectGamma";
    case Measure::RadiusRatio:
      return "RadiusRatio";
    case Measure::MinAngle:
      return "MinAngle";
    case Measure::CollapseRatio:
      return "CollapseRatio";
    case Measure::Volume:
      return "Volume";
  }
  return "Unknown";
}

bool IsDefined(Measure measure, ElementType type)
{
  // Evaluating on a unit element tells whether the dispatch knows the measure: keeps one table.
  switch (type)
  {
    case ElementType::Hexahedron:
      return !std::isnan(Hex(HexNodes{Point3(0, 0, 0), Point3(1, 0, 0), Point3(1, 1, 0), Point3(0, 1, 0),
                                      Point3(0, 0, 1), Point3(1, 0, 1), Point3(1, 1, 1), Point3(0, 1, 1)},
                             measure));
    case ElementType::Tetrahedron:
      return !std::isnan(Tet(TetNodes{Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1)}, measure));
    case ElementType::Wedge:
      return !std::isnan(Wedge(WedgeNodes{Point3(0, 0, 0), Point3(0, 1, 0), Point3(1, 0, 0), Point3(0, 0, 1),
                                          Point3(0, 1, 1), Point3(1, 0, 1)},
                               measure));
    default:
      return false;
  }
}

double ElementQuality(const FEMesh& mesh, std::size_t element, Measure measure)
{
  const Element& e = mesh.elements.at(element);
  switch (e.type)
  {
    case ElementType::Hexahedron:
      return Hex(Nodes<8>(mesh, e), measure);
    case ElementType::Tetrahedron:
      return Tet(Nodes<4>(mesh, e), measure);
    case ElementType::Wedge:
      return Wedge(Nodes<6>(mesh, e), measure);
    default:
      return kNaN;
  }
}

std::vector<double> CornerJacobians(const FEMesh& mesh, std::size_t element)
{
  const Element& e = mesh.elements.at(element);
  switch (e.type)
  {
    case ElementType::Hexahedron:
    {
      const auto j = HexCornerJacobians(Nodes<8>(mesh, e));
      return {j.begin(), j.end()};
    }
    case ElementType::Wedge:
    {
      const auto j = WedgeCornerJacobians(Nodes<6>(mesh, e));
      return {j.begin(), j.end()};
    }
    case ElementType::Tetrahedron:
      return std::vector<double>(4, TetJacobian(Nodes<4>(mesh, e)));
    default:
      return {};
  }
}

std::vector<std::vector<double>> ComputeQuality(const FEMesh& mesh, const std::vector<Measure>& measures,
                                                const QualityOptions& options)
{
  CheckNodes(mesh);
  const std::size_t n = mesh.elements.size();
  std::vector<std::vector<double>> values(measures.size(), std::vector<double>(n, kNaN));
  if (n == 0 || measures.empty())
  {
    if (options.progress)
      options.progress(1.0);
    return values;
  }

  // Elements are handed out in fixed-size chunks; each value depends only on its element.
  constexpr std::size_t kChunk = 1024;
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::atomic<std::size_t> next{0}, done{0};
  auto work = [&](bool reportProgress) {
    for (std::size_t c = next++; c < chunks; c = next++)
    {
      const std::size_t end = std::min(n, (c + 1) * kChunk);
      for (std::size_t e = c * kChunk; e < end; ++e)
        for (std::size_t m = 0; m < measures.size(); ++m)
          values[m][e] = ElementQuality(mesh, e, measures[m]);
      const std::size_t finished = ++done;
      if (reportProgress && options.progress)
        options.progress(static_cast<double>(finished) / static_cast<double>(chunks));
    }
  };

  unsigned threads = options.threads > 0 ? static_cast<unsigned>(options.threads) : WorkerThreads();
  threads = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(chunks)));
  std::vector<std::thread> workers;
  for (unsigned t = 1; t < threads; ++t)
    workers.emplace_back(work, false);
  try
  {
    work(true);
  }
  catch (...) // the progress callback may abort the run: stop the workers before unwinding
  {
    next = chunks;
    for (std::thread& w : workers)
      w.join();
    throw;
  }
  for (std::thread& w : workers)
    w.join();
  if (options.progress)
    options.progress(1.0);
  return values;
}

std::vector<double> ComputeQuality(const FEMesh& mesh, Measure measure, const QualityOptions& options)
{
  return std::move(ComputeQuality(mesh, std::vector<Measure>{measure}, options).front());
}

QualitySummary Summarize(const std::vector<double>& values, const std::vector<double>& jacobians, double threshold)
{
  if (values.size() != jacobians.size())
    throw std::invalid_argument("quality summary: " + std::to_string(values.size()) + " values but " +
                                std::to_string(jacobians.size()) + " Jacobians");
  QualitySummary s;
  s.min = std::numeric_limits<double>::infinity();
  s.max = -std::numeric_limits<double>::infinity();
  double sum = 0;
  std::size_t finite = 0;
  for (std::size_t e = 0; e < values.size(); ++e)
  {
    const double v = values[e];
    if (std::isnan(v))
      continue;
    ++s.count;
    if (jacobians[e] < 0)
      ++s.inverted;
    if (IsVerdictFlag(v))
    {
      ++s.degenerate;
      ++s.belowThreshold;
      continue;
    }
    if (v < threshold)
      ++s.belowThreshold;
    s.min = std::min(s.min, v);
    s.max = std::max(s.max, v);
    sum += v;
    ++finite;
  }
  if (finite == 0)
    s.min = s.max = s.mean = kNaN;
  else
    s.mean = sum / static_cast<double>(finite);
  return s;
}

QualitySummary SummarizeScaledJacobian(const FEMesh& mesh, double threshold, const QualityOptions& options)
{
  const auto values = ComputeQuality(mesh, {Measure::ScaledJacobian, Measure::Jacobian}, options);
  return Summarize(values[0], values[1], threshold);
}

} // namespace mmrep::quality
