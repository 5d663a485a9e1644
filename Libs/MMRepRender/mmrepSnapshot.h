// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Off-screen QC pictures with VTK: one PNG holding several views (anterior, left, …) of layered
// surfaces, optionally coloured by a point-data array with a scalar bar. Views are anatomical:
// LPS axes, superior up.
//
// Debian's VTK renders through X11: without a DISPLAY the call throws (run under `xvfb-run -a`;
// Utilities/mmrep.sh and the tests do).
#pragma once

#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

namespace mmrep
{

enum class View
{
  Anterior, // looking at the face
  Left,     // the patient's left side
  Right,
  Superior,
  Inferior,
  Posterior
};

struct SnapshotLayer
{
  vtkSmartPointer<vtkPolyData> surface; // held: a layer may be given a temporary
  std::array<double, 3> color{0.9, 0.75, 0.65};
  double opacity = 1.0;
  std::string scalars;               // point-data array to colour by (empty: plain colour)
  std::array<double, 2> range{0, 1}; // colour range for `scalars`
  std::string scalarTitle;           // scalar bar title
  bool wireframe = false;
  double pointSize = 0; // > 0: draw vertices as spheres of this size (pixels)
  double lineWidth = 1;
};

struct SnapshotOptions
{
  std::vector<View> views{View::Anterior, View::Left};
  int viewWidth = 600, viewHeight = 600; // pixels per view
  std::string title;                     // drawn at the top left
  // Zoom on a box (LPS mm: xmin,xmax,ymin,ymax,zmin,zmax) instead of the whole scene.
  std::array<double, 6> focus{1, 0, 1, 0, 1, 0};
};

// Throws std::runtime_error naming `pngPath` when there is no X display to render into.
void RequireDisplay(const std::string& pngPath);

// Renders `window` off screen and writes its pixels to a PNG; throws std::runtime_error when the
// file cannot be written. Building block for pictures other than WriteSnapshot's.
void WriteWindowPNG(vtkRenderWindow* window, const std::string& pngPath);

// Throws std::runtime_error when no X display is available or the PNG cannot be written.
void WriteSnapshot(const std::vector<SnapshotLayer>& layers, const SnapshotOptions& options,
                   const std::string& pngPath);

} // namespace mmrep
