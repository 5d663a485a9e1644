// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFieldOfView.h"

#include "mmrepSimilarityTransform.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace mmrep
{

namespace
{
// The similarity taking the atlas landmarks to the control points; false when they place nothing.
bool PlaceAtlas(const FEMesh& atlas, const std::vector<Point3>& targets, SimilarityTransform& toCT)
{
  std::vector<Eigen::Vector3d> source, target;
  for (std::size_t i = 0; i < atlas.landmarks.size() && i < targets.size(); ++i)
  {
    source.push_back(atlas.landmarks[i].position);
    target.push_back(targets[i]);
  }
  try
  {
    toCT = EstimateSimilarity(source, target);
  }
  catch (const std::invalid_argument&)
  {
    return false; // control points that place nothing (coincident, collinear): the pipeline reports them itself
  }
  return true;
}

const std::vector<std::int32_t>& FaceSet(const FEMesh& atlas, const std::string& faceSet)
{
  const auto set = atlas.nodeSets.find(faceSet);
  if (set == atlas.nodeSets.end())
    throw std::invalid_argument("atlas: node set '" + faceSet + "' is missing");
  return set->second;
}
} // namespace

bool FaceRegionBounds(const FEMesh& atlas, const std::string& faceSet, const std::vector<Point3>& targets,
                      std::array<double, 6>& box)
{
  SimilarityTransform toCT;
  if (!PlaceAtlas(atlas, targets, toCT))
    return false;
  box = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  for (const auto node : FaceSet(atlas, faceSet))
  {
    const Eigen::Vector3d x = toCT.Apply(atlas.nodes[static_cast<std::size_t>(node)]);
    for (unsigned a = 0; a < 3; ++a)
    {
      box[2 * a] = std::min(box[2 * a], x[a]);
      box[2 * a + 1] = std::max(box[2 * a + 1], x[a]);
    }
  }
  return true;
}

std::string MissingFieldOfView(const CTImage* ct, const FEMesh& atlas, const std::string& faceSet,
                               const std::vector<Point3>& targets, double margin)
{
  SimilarityTransform toCT;
  if (!PlaceAtlas(atlas, targets, toCT))
    return {};
  const auto& set = FaceSet(atlas, faceSet);

  // How far (mm) the face goes past each end of each CT axis, margin included.
  const auto region = ct->GetLargestPossibleRegion();
  double beyond[3][2] = {{0, 0}, {0, 0}, {0, 0}};
  for (const auto node : set)
  {
    const Eigen::Vector3d x = toCT.Apply(atlas.nodes[static_cast<std::size_t>(node)]);
    CTImage::PointType p;
    for (unsigned a = 0; a < 3; ++a)
      p[a] = x[a];
    const auto index = ct->TransformPhysicalPointToContinuousIndex<double>(p);
    for (unsigned a = 0; a < 3; ++a)
    {
      const double h = ct->GetSpacing()[a];
      const double first = static_cast<double>(region.GetIndex(a)) - 0.5;
      const double last = first + static_cast<double>(region.GetSize(a));
      beyond[a][0] = std::max(beyond[a][0], (first - index[a]) * h + margin);
      beyond[a][1] = std::max(beyond[a][1], (index[a] - last) * h + margin);
    }
  }

  // Name each short side by the anatomical direction its CT axis points to in LPS.
  static const char* const names[3][2] = {
    {"right cheek", "left cheek"}, {"front of the face", "back of the face"}, {"chin", "brow"}};
  std::string missing;
  for (unsigned a = 0; a < 3; ++a)
  {
    unsigned lps = 0;
    for (unsigned k = 1; k < 3; ++k)
      if (std::abs(ct->GetDirection()[k][a]) > std::abs(ct->GetDirection()[lps][a]))
        lps = k;
    const bool flipped = ct->GetDirection()[lps][a] < 0;
    for (unsigned end = 0; end < 2; ++end)
      if (beyond[a][end] > 0)
      {
        char text[160];
        std::snprintf(text, sizeof text, "%s%s by %.0f mm", missing.empty() ? "" : ", ",
                      names[lps][flipped ? 1 - end : end], std::ceil(beyond[a][end]));
        missing += text;
      }
  }
  return missing;
}

void CheckFieldOfView(const CTImage* ct, const FEMesh& atlas, const std::string& faceSet,
                      const std::vector<Point3>& targets, double margin)
{
  if (const std::string missing = MissingFieldOfView(ct, atlas, faceSet, targets, margin); !missing.empty())
  {
    char text[120];
    std::snprintf(text, sizeof text, " (the face region, placed by the control points, needs a %.0f mm margin)",
                  margin);
    throw std::runtime_error("the CT does not cover the face: it misses the " + missing + text +
                             "; --allowPartialFieldOfView builds a partial model");
  }
}

} // namespace mmrep
