#include "mmrepSurfaceDistance.h"

#include "mmrepSurfaceProjector.h"

#include <algorithm>

namespace mmrep
{

SurfaceDistance MeasureSurfaceDistance(const FEMesh& mesh, const std::string& nodeSet, vtkPolyData* surface)
{
  const SurfaceProjector projector(surface);
  SurfaceDistance d;
  const auto it = mesh.nodeSets.find(nodeSet);
  if (it == mesh.nodeSets.end())
    return d;
  double sum = 0;
  for (const std::int32_t id : it->second)
  {
    const double distance = projector.Distance(mesh.nodes.at(static_cast<std::size_t>(id)));
    sum += distance; // in set order: deterministic
    d.max = std::max(d.max, distance);
    ++d.count;
  }
  d.mean = d.count > 0 ? sum / static_cast<double>(d.count) : 0;
  return d;
}

} // namespace mmrep
