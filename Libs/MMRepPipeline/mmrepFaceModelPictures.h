// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// QC pictures of a speaker model (PNG, VTK off-screen; need an X display, e.g. xvfb-run -a):
//   model-skin-error.png  front and left views of the model's skin over the speaker's skin, coloured
//                         by each node's distance to the speaker's skin triangles;
//   lips.png              the same around the lips (anterior and left close-up), lips nodes marked;
//   muscles.png           the inferred muscle tracks, one colour per muscle, in the translucent face.
#pragma once

#include "mmrepFaceModelPipeline.h"

#include <string>

namespace mmrep
{

// Distance of every node of `mesh` to the surface (0 for nodes not in `set`), for colouring.
std::vector<double> NodeSurfaceDistances(const FEMesh& mesh, const std::string& set, vtkPolyData* surface);

void WriteModelErrorPicture(const FaceModelResult& result, const std::string& pngPath);
void WriteLipsPicture(const FaceModelResult& result, const std::string& pngPath);
void WriteMusclesPicture(const FEMesh& model, vtkPolyData* skin, const std::string& pngPath, const std::string& title);

} // namespace mmrep
