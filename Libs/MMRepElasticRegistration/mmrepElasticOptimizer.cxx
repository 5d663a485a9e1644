// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepElasticOptimizer.h"

#include "mmrepElasticEngine.h"

namespace mmrep
{

using elastic::Engine;
using elastic::kHeld;

ElasticOptimizerStats OptimizeElastic(ElasticTransform& transform, ElasticProblem& problem,
                                      const ElasticOptimizerOptions& options)
{
  if (problem.pointMap.size() != problem.points.size())
    throw std::invalid_argument("elastic registration: one map index per point is required");
  for (int m : problem.pointMap)
    if (m < kHeld || (m >= 0 && static_cast<std::size_t>(m) >= problem.maps.size()))
      throw std::invalid_argument("elastic registration: a point refers to a missing distance map");
  for (const auto& h : problem.hexahedra)
    for (int v : h)
      if (v < 0 || static_cast<std::size_t>(v) >= problem.points.size())
        throw std::invalid_argument("elastic registration: a guarded hexahedron refers to a missing point");
  if (problem.controlTargets.size() != problem.controlSources.size() ||
      problem.controlWeights.size() != problem.controlSources.size())
    throw std::invalid_argument("elastic registration: control sources, targets and weights differ in number");
  if (options.symmetric && std::abs(problem.boxMin.x() + problem.boxMax.x()) > 1e-9 * problem.boxMax.x())
    throw std::invalid_argument("elastic registration: a symmetric grid box must be centred on frame x = 0");
  Engine engine(transform, problem, options);
  return engine.Run();
}

double ElasticEnergy(const ElasticTransform& transform, const ElasticProblem& problem)
{
  double e = 0;
  for (std::size_t k = 0; k < problem.points.size(); ++k)
    if (problem.pointMap[k] >= 0)
      e += std::abs(
        problem.maps[static_cast<std::size_t>(problem.pointMap[k])].Value(transform.ToWorld(problem.points[k])));
  for (std::size_t i = 0; i < problem.controlSources.size(); ++i)
    e += problem.controlWeights[i] * (problem.controlSources[i] - problem.controlTargets[i]).norm();
  return e;
}

} // namespace mmrep
