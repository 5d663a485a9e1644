// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepControlPointMatch.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace mmrep
{

std::vector<Point3> MatchControlPointsByName(const std::vector<Landmark>& landmarks,
                                             const std::vector<Landmark>& points)
{
  if (points.empty())
    throw std::invalid_argument("control points: none given (the atlas needs " + std::to_string(landmarks.size()) +
                                ")");
  if (landmarks.empty())
    throw std::invalid_argument("atlas: it has no landmarks to match control points with");
  std::map<std::string, Point3> byName;
  for (const auto& p : points)
  {
    if (p.name.empty())
      throw std::invalid_argument("control points: a point has no name");
    if (!byName.emplace(p.name, p.position).second)
      throw std::invalid_argument("control points: '" + p.name + "' is given twice");
  }
  std::vector<Point3> targets;
  for (const auto& l : landmarks)
  {
    const auto it = byName.find(l.name);
    if (it == byName.end())
    {
      std::string names;
      for (const auto& a : landmarks)
        names += " " + a.name;
      throw std::invalid_argument("control points: '" + l.name + "' is missing (the atlas landmarks are named" + names +
                                  ")");
    }
    targets.push_back(it->second);
  }
  for (const auto& p : points)
    if (std::none_of(landmarks.begin(), landmarks.end(), [&](const Landmark& l) { return l.name == p.name; }))
      throw std::invalid_argument("control points: '" + p.name + "' is not an atlas landmark");
  return targets;
}

} // namespace mmrep
