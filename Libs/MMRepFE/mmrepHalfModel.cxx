// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepHalfModel.h"

#include "mmrepBoundaryFaces.h"
#include "mmrepElementLocation.h"

#include <Eigen/Geometry>

#include <vtkNew.h>
#include <vtkPoints.h>

#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mmrep
{
namespace
{
enum class Side : std::int8_t
{
  Right = -1,
  Plane = 0,
  Left = 1
};

std::vector<std::int32_t> Restrict(const std::vector<std::int32_t>& ids, const std::vector<std::int32_t>& newIndex)
{
  std::vector<std::int32_t> out;
  for (auto id : ids)
    if (newIndex[static_cast<std::size_t>(id)] >= 0)
      out.push_back(newIndex[static_cast<std::size_t>(id)]);
  return out;
}

// A half model stands for both halves only when the model is symmetric: every solid node's mirror
// image must be a node (its stored mirror partner, else the nearest solid node) within `tolerance`.
void RequireSymmetry(const FEMesh& full, const Plane& plane, double tolerance)
{
  std::vector<std::size_t> solid;
  {
    std::vector<char> used(full.nodes.size(), 0);
    for (const auto& e : full.elements)
      if (e.type != ElementType::Cable)
        for (int k = 0; k < NodeCount(e.type); ++k)
          used[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])] = 1;
    for (std::size_t i = 0; i < used.size(); ++i)
      if (used[i])
        solid.push_back(i);
  }
  double worst = 0;
  std::size_t worstNode = 0;
  // Without a stored map: nearest solid node to each mirror image, on a grid of cells of 4 mm.
  std::map<std::array<long, 3>, std::vector<std::size_t>> cells;
  constexpr double cell = 4.0;
  const auto key = [&](const Eigen::Vector3d& x) {
    return std::array<long, 3>{static_cast<long>(std::floor(x.x() / cell)), static_cast<long>(std::floor(x.y() / cell)),
                               static_cast<long>(std::floor(x.z() / cell))};
  };
  if (!full.HasMirrorMap())
    for (auto i : solid)
      cells[key(full.nodes[i])].push_back(i);
  for (auto i : solid)
  {
    const Eigen::Vector3d image = plane.Mirror(full.nodes[i]);
    double d = std::numeric_limits<double>::infinity();
    if (full.HasMirrorMap())
      d = (full.nodes[static_cast<std::size_t>(full.mirror[i])] - image).norm();
    else
    {
      const auto c = key(image);
      for (long dx = -1; dx <= 1; ++dx)
        for (long dy = -1; dy <= 1; ++dy)
          for (long dz = -1; dz <= 1; ++dz)
            if (auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz}); it != cells.end())
              for (auto j : it->second)
                d = std::min(d, (full.nodes[j] - image).norm());
    }
    if (d > worst)
    {
      worst = d;
      worstNode = i;
    }
  }
  if (worst > tolerance)
  {
    std::ostringstream s;
    s.precision(3);
    s << "the model is not symmetric about its plane: the mirror image of node " << worstNode << " lies ";
    if (std::isinf(worst))
      s << "more than " << cell << " mm";
    else
      s << worst << " mm";
    s << " from " << (full.HasMirrorMap() ? "its mirror partner" : "every node") << " (at most " << tolerance
      << " mm); a half model stands for a symmetric model only (build it with --symmetry half-face or averaged)";
    throw std::invalid_argument(s.str());
  }
}

// Which side of the plane each node is on; the plane set's nodes must lie on it.
std::vector<Side> NodeSides(const FEMesh& full, const Plane& plane, const HalfModelOptions& options)
{
  const double tol = options.tolerance;
  std::vector<char> onPlaneSet(full.nodes.size(), 0);
  for (auto n : full.nodeSets.at(options.planeSet))
  {
    const double d = plane.SignedDistance(full.nodes[static_cast<std::size_t>(n)]);
    if (std::abs(d) > tol)
      throw std::invalid_argument("node " + std::to_string(n) + " of set '" + options.planeSet + "' lies " +
                                  std::to_string(d) + " mm off the set's plane: the model is not symmetric about it");
    onPlaneSet[static_cast<std::size_t>(n)] = 1;
  }
  std::vector<Side> side(full.nodes.size());
  for (std::size_t i = 0; i < full.nodes.size(); ++i)
  {
    const double d = plane.SignedDistance(full.nodes[i]);
    side[i] = onPlaneSet[i] || std::abs(d) <= tol ? Side::Plane : d > 0 ? Side::Left : Side::Right;
  }
  return side;
}

// Solid elements: centroid side; an element with nodes on both sides is not cut along the plane.
std::vector<char> LeftSolids(const FEMesh& full, const Plane& plane, const std::vector<Side>& side,
                             const HalfModelOptions& options)
{
  std::vector<char> keepElement(full.elements.size(), 0);
  for (std::size_t i = 0; i < full.elements.size(); ++i)
  {
    const Element& e = full.elements[i];
    if (e.type == ElementType::Cable)
      continue;
    bool left = false, right = false;
    Point3 centroid = Point3::Zero();
    for (int k = 0; k < NodeCount(e.type); ++k)
    {
      const auto n = static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)]);
      left = left || side[n] == Side::Left;
      right = right || side[n] == Side::Right;
      centroid += full.nodes[n] / NodeCount(e.type);
    }
    if (left && right)
      throw std::invalid_argument("solid element " + std::to_string(i) + " straddles the symmetry plane of set '" +
                                  options.planeSet + "': a half model needs a mesh cut along its plane nodes");
    if (!left && !right)
      throw std::invalid_argument("solid element " + std::to_string(i) + " lies flat on the symmetry plane");
    keepElement[i] = left && plane.SignedDistance(centroid) > 0;
  }
  return keepElement;
}

// A left piece of a muscle track: track points [begin, end).
struct Piece
{
  std::string name;
  std::size_t begin, end;
  const MuscleTrack* track;
};

// Muscle tracks: maximal runs of left/plane points that hold a left point.
std::vector<Piece> LeftTrackPieces(const FEMesh& full, const std::vector<Side>& side)
{
  std::vector<Piece> pieces;
  for (const auto& [name, track] : full.muscles)
  {
    int part = 0;
    std::size_t begin = 0;
    const std::size_t count = track.nodes.size();
    for (std::size_t k = 0; k <= count; ++k)
    {
      const bool rightPoint = k < count && side[static_cast<std::size_t>(track.nodes[k])] == Side::Right;
      if (k > 0 && k < count)
      {
        const Side a = side[static_cast<std::size_t>(track.nodes[k - 1])],
                   b = side[static_cast<std::size_t>(track.nodes[k])];
        if (static_cast<int>(a) * static_cast<int>(b) < 0)
          throw std::invalid_argument("muscle '" + name + "' crosses the symmetry plane between its points " +
                                      std::to_string(k - 1) + " and " + std::to_string(k) + " without a point on it");
      }
      if (k == count || rightPoint)
      {
        bool hasLeft = false;
        for (std::size_t j = begin; j < k; ++j)
          hasLeft = hasLeft || side[static_cast<std::size_t>(track.nodes[j])] == Side::Left;
        if (hasLeft && k - begin >= 2)
          pieces.push_back({part++ == 0 ? name : name + "_part" + std::to_string(part), begin, k, &track});
        begin = k + 1;
      }
    }
  }
  return pieces;
}

// Nodes: those of kept elements and tracks, and free nodes (in no element) on the left or the plane.
std::vector<char> KeptNodes(const FEMesh& full, const std::vector<char>& keepElement, const std::vector<Piece>& pieces,
                            const std::vector<Side>& side)
{
  std::vector<char> keepNode(full.nodes.size(), 0), referenced(full.nodes.size(), 0);
  for (std::size_t i = 0; i < full.elements.size(); ++i)
    for (int k = 0; k < NodeCount(full.elements[i].type); ++k)
    {
      const auto n = static_cast<std::size_t>(full.elements[i].nodes[static_cast<std::size_t>(k)]);
      referenced[n] = 1;
      keepNode[n] = keepNode[n] || keepElement[i];
    }
  for (const auto& [name, track] : full.muscles)
    for (auto n : track.nodes)
      referenced[static_cast<std::size_t>(n)] = 1;
  for (const auto& piece : pieces)
    for (std::size_t k = piece.begin; k < piece.end; ++k)
      keepNode[static_cast<std::size_t>(piece.track->nodes[k])] = 1;
  for (std::size_t i = 0; i < full.nodes.size(); ++i)
    keepNode[i] = keepNode[i] || (!referenced[i] && side[i] != Side::Right);
  return keepNode;
}

// A point on the plane embedded in a right element: the kept element nearest to it.
Embedding ReEmbed(const FEMesh& half, const Point3& x, const Piece& piece, std::size_t k, double tol)
{
  Embedding emb;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < half.elements.size(); ++e)
  {
    if (half.elements[e].type == ElementType::Cable)
      continue;
    const ElementLocation hit = LocateInElement(half, half.elements[e], x);
    const double d = hit.distance;
    if (d < best)
    {
      best = d;
      emb = {static_cast<std::int32_t>(e), hit.pcoords};
    }
    if (d == 0)
      break;
  }
  if (!(best <= tol))
    throw std::invalid_argument("muscle '" + piece.name + "': point " + std::to_string(k) +
                                " lies in no element of the left half");
  return emb;
}

// The track pieces in the half's numbering.
void AddTrackPieces(const FEMesh& full, const std::vector<Piece>& pieces, const std::vector<std::int32_t>& nodeIndex,
                    const std::vector<std::int32_t>& elementIndex, double tol, FEMesh& half)
{
  for (const auto& piece : pieces)
  {
    const MuscleTrack& track = *piece.track;
    MuscleTrack out;
    out.maximumForce = track.maximumForce;
    for (std::size_t k = piece.begin; k < piece.end; ++k)
    {
      const auto n = static_cast<std::size_t>(track.nodes[k]);
      out.nodes.push_back(nodeIndex[n]);
      if (k + 1 < piece.end)
        out.cables.push_back(elementIndex[static_cast<std::size_t>(track.cables[k])]);
      if (track.embedding.empty())
        continue;
      Embedding emb = track.embedding[k];
      if (elementIndex[static_cast<std::size_t>(emb.element)] >= 0)
        emb.element = elementIndex[static_cast<std::size_t>(emb.element)];
      else
        emb = ReEmbed(half, full.nodes[n], piece, k, tol);
      out.embedding.push_back(emb);
    }
    half.muscles[piece.name] = std::move(out);
  }
}
} // namespace

bool IsHalfModel(const FEMesh& mesh)
{
  const auto it = mesh.nodeSets.find(kSymmetryBoundarySet);
  return it != mesh.nodeSets.end() && !it->second.empty();
}

Plane SymmetryPlaneOf(const FEMesh& half)
{
  if (!IsHalfModel(half))
    throw std::invalid_argument("the model is not a half model (no node set '" + kSymmetryBoundarySet + "')");
  return FitPlaneToNodeSet(half, kSymmetryBoundarySet);
}

std::vector<std::vector<std::int32_t>> SymmetryBoundaryFaces(const FEMesh& half)
{
  std::vector<std::vector<std::int32_t>> out;
  const std::vector<char> onPlane = NodeSetMask(half, kSymmetryBoundarySet);
  for (const BoundaryFace& face : BoundaryFaces(half, &onPlane))
  {
    std::vector<std::int32_t> ids(face.nodes.begin(), face.nodes.begin() + face.NodeCount());
    // Newell normal of the face against the direction from the element's centroid to the face's.
    const Element& e = half.elements[static_cast<std::size_t>(face.element)];
    Point3 normal = Point3::Zero(), faceCentre = Point3::Zero(), centre = Point3::Zero();
    for (std::size_t k = 0; k < ids.size(); ++k)
    {
      const Point3& a = half.nodes[static_cast<std::size_t>(ids[k])];
      const Point3& b = half.nodes[static_cast<std::size_t>(ids[(k + 1) % ids.size()])];
      normal += a.cross(b);
      faceCentre += a / static_cast<double>(ids.size());
    }
    for (int k = 0; k < NodeCount(e.type); ++k)
      centre += half.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])] / NodeCount(e.type);
    if (normal.dot(faceCentre - centre) < 0)
      std::reverse(ids.begin(), ids.end());
    out.push_back(ids);
  }
  return out;
}

FEMesh LeftHalfModel(const FEMesh& full, const HalfModelOptions& options)
{
  full.Validate();
  if (IsHalfModel(full))
    throw std::invalid_argument("the model already is a half model (it has node set '" + kSymmetryBoundarySet + "')");
  const Plane plane = FitPlaneToNodeSet(full, options.planeSet);
  const double tol = options.tolerance;
  const std::vector<Side> side = NodeSides(full, plane, options);
  std::vector<char> keepElement = LeftSolids(full, plane, side, options);
  RequireSymmetry(full, plane, options.symmetryTolerance); // after the more specific plane checks
  const std::vector<Piece> pieces = LeftTrackPieces(full, side);
  for (const auto& piece : pieces)
    for (std::size_t c = piece.begin; c + 1 < piece.end; ++c)
      keepElement[static_cast<std::size_t>(piece.track->cables[c])] = 1;
  const std::vector<char> keepNode = KeptNodes(full, keepElement, pieces, side);

  FEMesh half;
  std::vector<std::int32_t> nodeIndex(full.nodes.size(), -1), elementIndex(full.elements.size(), -1);
  for (std::size_t i = 0; i < full.nodes.size(); ++i)
    if (keepNode[i])
    {
      nodeIndex[i] = static_cast<std::int32_t>(half.nodes.size());
      half.nodes.push_back(full.nodes[i]);
    }
  for (std::size_t i = 0; i < full.elements.size(); ++i)
    if (keepElement[i])
    {
      Element e = full.elements[i];
      for (int k = 0; k < NodeCount(e.type); ++k)
        e.nodes[static_cast<std::size_t>(k)] =
          nodeIndex[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])];
      elementIndex[i] = static_cast<std::int32_t>(half.elements.size());
      half.elements.push_back(e);
    }
  for (const auto& [name, ids] : full.nodeSets)
    if (auto kept = Restrict(ids, nodeIndex); !kept.empty())
      half.nodeSets[name] = std::move(kept);
  for (const auto& [name, ids] : full.elementSets)
    if (auto kept = Restrict(ids, elementIndex); !kept.empty())
      half.elementSets[name] = std::move(kept);
  AddTrackPieces(full, pieces, nodeIndex, elementIndex, tol, half);
  for (const auto& l : full.landmarks)
    if (plane.SignedDistance(l.position) >= -tol)
      half.landmarks.push_back(l);
  if (auto plan = half.nodeSets.find(options.planeSet); plan != half.nodeSets.end())
    half.nodeSets[kSymmetryBoundarySet] = plan->second;
  if (!IsHalfModel(half) || half.SolidElementCount() == 0)
    throw std::invalid_argument("the left half of the model is empty or has no node on the plane");
  half.Validate();
  return half;
}

} // namespace mmrep
