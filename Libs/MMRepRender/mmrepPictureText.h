// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Text that fits the picture: titles wrapped at word boundaries to the width they are given (measured
// with VTK's own text renderer, as vtkTextActor draws them), in a smaller font only when one word is
// wider than the line, and that word cut into pieces when even the smaller font is too wide.
#pragma once

#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <string>

namespace mmrep
{

struct FittedText
{
  std::string text; // with '\n' where it wraps
  int fontSize = 16;
};

// `text` in lines no wider than `maxWidth` pixels at `fontSize` (or less, down to 11).
FittedText FitTextToWidth(const std::string& text, int fontSize, int maxWidth);

// A title for a view of `viewWidth` × `viewHeight` pixels: black, wrapped to the view's width less the
// margins, its top line `margin` pixels below the view's top; at the left (`centered` false) or centred.
vtkSmartPointer<vtkTextActor> MakeViewTitle(const std::string& text, int viewWidth, int viewHeight, int fontSize = 16,
                                            bool centered = false, int margin = 8);

} // namespace mmrep
