// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// QC pictures of the face atlas (BuildFaceAtlas --pictures): its layers (left half and whole
// face), its skin mesh with the lips nodes and landmarks, and its muscle tracks.
#pragma once

#include "mmrepFaceAtlas.h"

#include <string>

namespace mmrep
{

// Writes FaceAtlasLayers.png, FaceAtlasLips.png and FaceAtlasMuscles.png into an existing folder.
void WriteFaceAtlasPictures(const FaceAtlas& atlas, const std::string& folder);

} // namespace mmrep
