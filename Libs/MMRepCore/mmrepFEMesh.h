// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The FE face model: nodes, solid elements in tissue layers, cable elements, named sets,
// muscle tracks and landmarks. Coordinates are millimetres in LPS (ITK and Slicer convention).
//
// Node order inside each element is VTK's (vtkHexahedron, vtkWedge, vtkTetra, vtkLine), so a
// mesh maps one-to-one to a vtkUnstructuredGrid; writers for other formats reorder as needed.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace mmrep
{

using Point3 = Eigen::Vector3d;

// Values equal VTK's cell type ids.
enum class ElementType : std::uint8_t
{
  Cable = 3,        // VTK_LINE, two nodes: muscle fibre segment (tension only)
  Tetrahedron = 10, // VTK_TETRA
  Hexahedron = 12,  // VTK_HEXAHEDRON
  Wedge = 13        // VTK_WEDGE
};
int NodeCount(ElementType type); // 2, 4, 8, 6
const char* ElementTypeName(ElementType type);

// Soft-tissue layer of a solid element, outer to inner. Cables have None.
enum class TissueLayer : std::uint8_t
{
  None = 0,
  Epidermis = 1,
  Dermis = 2,
  Hypodermis = 3
};
const char* TissueLayerName(TissueLayer layer); // "none", "epidermis", "dermis", "hypodermis"

struct Element
{
  ElementType type = ElementType::Hexahedron;
  std::array<std::int32_t, 8> nodes{}; // first NodeCount(type) entries are used
  TissueLayer layer = TissueLayer::None;
};

// Where a point sits inside a solid element: element index and parametric coordinates in
// VTK's convention for that cell type (so vtkCell::EvaluateLocation gives the point back).
struct Embedding
{
  std::int32_t element = -1;
  std::array<double, 3> pcoords{};
};

// A muscle fibre track: an ordered chain of mesh nodes linked by cable elements.
struct MuscleTrack
{
  std::vector<std::int32_t> nodes;  // polyline points, in order (first = insertion)
  std::vector<std::int32_t> cables; // indices of the Cable elements, cables[i] joins nodes[i], nodes[i+1]
  std::vector<Embedding> embedding; // one per node: the solid element it lies in
  // Maximum active force of the fibre in N (the tension every cable of the track carries at full
  // activation and optimal length). Files written before it was stored read kDefaultMaximumForce.
  double maximumForce = kDefaultMaximumForce;
  // ArtiSynth's face model gives each muscle fibre 1 N when nothing better is known
  // (AnsysFaceMuscleFiberReader.setDefaultMuscleFibreProperties, artisynth_models).
  static constexpr double kDefaultMaximumForce = 1.0;
};

struct Landmark
{
  std::string name;
  Point3 position = Point3::Zero();
};

class FEMesh
{
public:
  std::vector<Point3> nodes;
  std::vector<Element> elements;
  // Named sets, kept sorted by name so that every output is deterministic.
  std::map<std::string, std::vector<std::int32_t>> nodeSets;    // skin, skull, lips, midsagittal, …
  std::map<std::string, std::vector<std::int32_t>> elementSets; // epidermis, …, muscle names
  std::map<std::string, MuscleTrack> muscles;
  std::vector<Landmark> landmarks; // ordered as given (control points keep their order)
  // Mirror map about the mid-sagittal plane, known when a symmetric atlas is built: mirror[i] is the
  // node at the mirror image of node i (i itself on the plane); an involution. Empty: not known
  // (plain VTK meshes, half models, files written before the map existed).
  std::vector<std::int32_t> mirror;

  std::size_t SolidElementCount() const;
  // Indices of the solid (non-cable) elements of a layer, in element order.
  std::vector<std::int32_t> SolidElementsOfLayer(TissueLayer layer) const;
  bool Empty() const { return nodes.empty() || elements.empty(); }
  bool HasMirrorMap() const { return !mirror.empty(); }
  // Records nodes a and b as each other's mirror image (a == b: a node on the plane); nodes added
  // since the map was last extended map to themselves until set. Does nothing without a map.
  void SetMirrorPartners(std::int32_t a, std::int32_t b);
  // Throws std::invalid_argument naming the first problem (node index out of range, set entry
  // out of range, cable/muscle mismatch, non-finite coordinate, a mirror map that is not an
  // involution over every node).
  void Validate() const;
  // Rebuilds the per-layer element sets (epidermis, dermis, hypodermis) from element layers.
  void UpdateLayerSets();
};

} // namespace mmrep
