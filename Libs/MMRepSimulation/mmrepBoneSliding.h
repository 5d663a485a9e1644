// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The face tissue slides on the maxilla instead of being glued to it, anchored only at the edge of
// the modelled region and at the muscles' bone origins (ArtiSynth's face model as updated by Flynn
// and Chiu: its inner surface is in contact with the skull, fixed only at the domain edges, the
// nose and the zygomatic ligaments; the face nodes over the mandible are attached to the jaw).
#pragma once

#include "mmrepLipSupport.h"

#include <cstdint>
#include <vector>

namespace mmrep::simulation
{

// The nodes of set `maxilla` that slide on the bone (n·u = 0 along the bone surface's normal,
// frictionless, bilateral, linearised at rest; `onBone` set), i.e. every maxilla node of a solid
// except the anchors: maxilla nodes on a side face of the model (a boundary face that is neither
// skin, nor inner surface, nor the mouth slit, nor a half model's symmetry plane) and the maxilla
// nodes of the solids that hold the end points of a muscle track. Empty when the model has no
// `maxilla` set.
std::vector<SlidingNode> BoneSlidingNodes(const FEMesh& mesh);

// The anchors of BoneSlidingNodes (sorted node ids), for reports and pictures.
std::vector<std::int32_t> BoneAnchorNodes(const FEMesh& mesh);

} // namespace mmrep::simulation
