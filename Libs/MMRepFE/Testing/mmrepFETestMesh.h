// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Small FE model used by the FE I/O tests: a 2x1x3 hexahedral block in three tissue layers, a
// wedge and a tetrahedron glued to its sides, two cable muscles embedded in solids, node sets,
// element sets (one empty) and landmarks. Names contain spaces, dots, '%' and non-ASCII bytes on
// purpose. Coordinates are offset by irrational-looking values so every double uses all its bits.
#pragma once

#include "mmrepFEMesh.h"

namespace mmrep::testing
{

inline const Point3 kTestMeshOffset(1.0 / 3.0, 1.4142135623730951, -3.141592653589793);

// Node index of hex grid point (i, j, k), i in 0..2 (x, 10 mm), j in 0..1 (y, 8 mm), k in 0..3 (z, 3 mm).
inline std::int32_t GridNode(int i, int j, int k)
{
  return static_cast<std::int32_t>(i + 3 * (j + 2 * k));
}

inline FEMesh MakeTestMesh()
{
  FEMesh mesh;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        mesh.nodes.push_back(kTestMeshOffset + Point3(10.0 * i, 8.0 * j, 3.0 * k));
  const TissueLayer layerOfK[3] = {TissueLayer::Hypodermis, TissueLayer::Dermis, TissueLayer::Epidermis};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 2; ++i)
    {
      Element e;
      e.type = ElementType::Hexahedron;
      e.layer = layerOfK[k];
      e.nodes = {GridNode(i, 0, k),     GridNode(i + 1, 0, k),     GridNode(i + 1, 1, k),     GridNode(i, 1, k),
                 GridNode(i, 0, k + 1), GridNode(i + 1, 0, k + 1), GridNode(i + 1, 1, k + 1), GridNode(i, 1, k + 1)};
      mesh.elements.push_back(e); // elements 0..5: index = i + 2k
    }
  // Wedge on the x = 20 face of the epidermis, extruded along y. A valid VTK wedge has its first
  // triangle's normal pointing away from the second triangle (here towards -y).
  const auto tipY0 = static_cast<std::int32_t>(mesh.nodes.size());
  mesh.nodes.push_back(kTestMeshOffset + Point3(26.0, 0.0, 7.5));
  mesh.nodes.push_back(kTestMeshOffset + Point3(26.0, 8.0, 7.5));
  Element wedge;
  wedge.type = ElementType::Wedge;
  wedge.layer = TissueLayer::Epidermis;
  wedge.nodes = {GridNode(2, 0, 2), tipY0, GridNode(2, 0, 3), GridNode(2, 1, 2), tipY0 + 1, GridNode(2, 1, 3)};
  mesh.elements.push_back(wedge); // element 6
  // Tetrahedron on the x = 0 face of the hypodermis; VTK wants (p1-p0)x(p2-p0).(p3-p0) > 0.
  const auto apex = static_cast<std::int32_t>(mesh.nodes.size());
  mesh.nodes.push_back(kTestMeshOffset + Point3(-5.0, 2.0, 1.0));
  Element tet;
  tet.type = ElementType::Tetrahedron;
  tet.layer = TissueLayer::Hypodermis;
  tet.nodes = {GridNode(0, 0, 0), GridNode(0, 0, 1), GridNode(0, 1, 0), apex};
  mesh.elements.push_back(tet); // element 7

  // Muscle "orbicularis oris": three nodes inside the dermis hexes, two cables.
  auto addMuscleNode = [&](const Point3& local, std::int32_t element, std::array<double, 3> pcoords,
                           MuscleTrack& track) {
    track.nodes.push_back(static_cast<std::int32_t>(mesh.nodes.size()));
    mesh.nodes.push_back(kTestMeshOffset + local);
    track.embedding.push_back({element, pcoords});
  };
  MuscleTrack oris;
  addMuscleNode(Point3(3.0, 4.0, 4.5), 2, {0.3, 0.5, 0.5}, oris);
  addMuscleNode(Point3(12.0, 4.0, 4.2), 3, {0.2, 0.5, 0.4}, oris);
  addMuscleNode(Point3(17.0, 2.0, 5.0), 3, {0.7, 0.25, 2.0 / 3.0}, oris);
  for (std::size_t k = 0; k + 1 < oris.nodes.size(); ++k)
  {
    Element cable;
    cable.type = ElementType::Cable;
    cable.nodes[0] = oris.nodes[k];
    cable.nodes[1] = oris.nodes[k + 1];
    oris.cables.push_back(static_cast<std::int32_t>(mesh.elements.size()));
    mesh.elements.push_back(cable); // elements 8, 9
  }
  oris.maximumForce = 0.43; // N, not the default: the round trip must keep it
  mesh.muscles["orbicularis oris"] = oris;
  // Muscle with an awkward name, one cable from the wedge to the epidermis hex; the wedge point
  // is placed with VTK's wedge interpolation so its embedding is exact.
  MuscleTrack levator;
  {
    const double r = 0.2, s = 0.3, t = 0.5;
    const double w[6] = {(1 - r - s) * (1 - t), r * (1 - t), s * (1 - t), (1 - r - s) * t, r * t, s * t};
    Point3 p = Point3::Zero();
    for (int n = 0; n < 6; ++n)
      p += w[n] * mesh.nodes[wedge.nodes[n]];
    levator.nodes.push_back(static_cast<std::int32_t>(mesh.nodes.size()));
    mesh.nodes.push_back(p);
    levator.embedding.push_back({6, {r, s, t}});
    levator.nodes.push_back(static_cast<std::int32_t>(mesh.nodes.size()));
    mesh.nodes.push_back(kTestMeshOffset + Point3(15.0, 6.0, 7.0));
    levator.embedding.push_back({5, {0.5, 0.75, 1.0 / 3.0}});
    Element cable;
    cable.type = ElementType::Cable;
    cable.nodes[0] = levator.nodes[0];
    cable.nodes[1] = levator.nodes[1];
    levator.cables.push_back(static_cast<std::int32_t>(mesh.elements.size()));
    mesh.elements.push_back(cable); // element 10
  }
  mesh.muscles["levator.labii 50%"] = levator;

  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i)
    {
      mesh.nodeSets["skin"].push_back(GridNode(i, j, 3));
      mesh.nodeSets["skull"].push_back(GridNode(i, j, 0));
    }
  mesh.nodeSets["skin"].push_back(tipY0);
  mesh.nodeSets["skin"].push_back(tipY0 + 1);
  mesh.nodeSets["lips (upper)"] = {GridNode(2, 1, 3), GridNode(0, 0, 3), GridNode(1, 0, 3)}; // unsorted on purpose
  mesh.nodeSets["empty"] = {};
  mesh.UpdateLayerSets();
  mesh.elementSets["orbicularis oris"] = oris.cables;
  mesh.elementSets["mixed\xC3\xA9"] = {7, 9, 0}; // a tet, a cable and a hex, unsorted; "mixedé"
  mesh.elementSets["none yet"] = {};

  mesh.landmarks.push_back({"subnasale", kTestMeshOffset + Point3(5.0, 1.0, 9.0)});
  mesh.landmarks.push_back({"stomion", kTestMeshOffset + Point3(10.0, 0.5, 9.0)});
  mesh.landmarks.push_back({"soft pogonion (\xC3\xA9)", Point3(0.1, 0.2, 0.3)});
  return mesh;
}

} // namespace mmrep::testing
