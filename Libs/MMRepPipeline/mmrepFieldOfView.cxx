// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFieldOfView.h"

#include "mmrepControlPointPlausibility.h"
#include "mmrepPlane.h"
#include "mmrepSimilarityTransform.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
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

namespace
{
// The atlas's face, in its own frame: levels (superior coordinate) of the eyes and lips, the mouth
// corner's distance from the midline.
struct AtlasFaceLevels
{
  Eigen::Vector3d left, superior;
  Eigen::Vector3d origin;
  double eyes = 0, upperLip = 0, lowerLip = 0, mouthHalfWidth = 0;
};

bool FaceLevels(const FEMesh& atlas, AtlasFaceLevels& f)
{
  Eigen::Vector3d anterior;
  if (!AtlasFaceFrame(atlas, anterior, f.superior))
    return false;
  const Plane plane = FitPlaneToNodeSet(atlas, "midsagittal");
  f.left = plane.normal;
  f.origin = plane.point;
  int eyes = 0;
  bool upper = false, lower = false;
  for (const auto& l : atlas.landmarks)
  {
    const double level = f.superior.dot(l.position - f.origin);
    if (l.name.find("Eye") != std::string::npos)
      f.eyes += level, ++eyes;
    else if (l.name == "UpperLipCenter")
      f.upperLip = level, upper = true;
    else if (l.name == "LowerLipCenter")
      f.lowerLip = level, lower = true;
    else if (l.name.find("LipCorner") != std::string::npos)
      f.mouthHalfWidth = std::abs(f.left.dot(l.position - f.origin));
  }
  f.eyes /= std::max(1, eyes);
  return eyes > 0 && upper && lower && f.mouthHalfWidth > 0;
}

std::string RegionOf(const AtlasFaceLevels& f, const Eigen::Vector3d& atlasPoint)
{
  const double lateral = f.left.dot(atlasPoint - f.origin), level = f.superior.dot(atlasPoint - f.origin);
  const std::string side = lateral > 0 ? "left" : "right";
  const double noseSpan = f.eyes - f.upperLip; // eye level to the upper lip
  if (level > f.eyes + 12)
    return "forehead";
  if (std::abs(lateral) <= 18 && level > f.upperLip + 4)
    return level < f.eyes - 0.45 * noseSpan ? "nose tip" : "nose bridge";
  if (std::abs(level - f.eyes) <= 12)
    return side + " eye";
  if (level >= f.lowerLip - 6 && level <= f.upperLip + 4 && std::abs(lateral) <= 1.3 * f.mouthHalfWidth)
    return "lips";
  if (level < f.lowerLip - 6 && std::abs(lateral) <= 30)
    return "chin";
  return side + " cheek";
}
} // namespace

std::string NotImagedRegions(const FEMesh& atlas, const std::vector<Point3>& targets, const NotImagedTissue& notImaged)
{
  SimilarityTransform toCT;
  AtlasFaceLevels face;
  if (notImaged.cut.empty() || !PlaceAtlas(atlas, targets, toCT) || !FaceLevels(atlas, face))
    return {};
  const SimilarityTransform toAtlas = toCT.Inverse();
  std::map<std::string, std::size_t> count;
  for (const auto& p : notImaged.cut)
    ++count[RegionOf(face, toAtlas.Apply(p))];
  std::vector<std::pair<std::size_t, std::string>> regions;
  for (const auto& [name, n] : count)
    if (5 * n >= notImaged.cut.size())
      regions.emplace_back(n, name);
  std::sort(regions.begin(), regions.end(),
            [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
  std::string words;
  for (std::size_t i = 0; i < regions.size(); ++i)
    words += (i == 0 ? "the " : i + 1 == regions.size() ? " and the " : ", the ") + regions[i].second;
  return words;
}

std::string NotImagedMessage(const std::string& regions, const NotImagedTissue& notImaged)
{
  if (regions.empty())
    return {};
  const bool several = regions.find(" and ") != std::string::npos;
  char cut[160];
  std::snprintf(cut, sizeof cut, " (the skin there is a flat cut: %zu voxels touch the padding value %d)",
                notImaged.cut.size(), static_cast<int>(notImaged.paddingValue));
  return regions + (several ? " are" : " is") + " outside the scanner's field of view" + cut + ": the model's " +
         regions.substr(4) + " there " + (several ? "are" : "is") + " the atlas's";
}

std::vector<std::int32_t> NodesOnNotImagedSkin(const FEMesh& mesh, const std::string& skinSet,
                                               const NotImagedTissue& notImaged, double radius)
{
  std::vector<std::int32_t> nodes;
  const auto set = mesh.nodeSets.find(skinSet);
  if (set == mesh.nodeSets.end() || notImaged.cut.empty())
    return nodes;
  const double r2 = radius * radius;
  for (const auto id : set->second)
  {
    const Point3& x = mesh.nodes.at(static_cast<std::size_t>(id));
    for (const auto& c : notImaged.cut)
      if ((x - c).squaredNorm() <= r2)
      {
        nodes.push_back(id);
        break;
      }
  }
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

} // namespace mmrep
