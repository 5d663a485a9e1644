// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepPictureText.h"

#include <vtkNew.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace mmrep
{

namespace
{
// Width in pixels of one line as vtkTextActor draws it (72 dpi: VTK's default for off-screen windows).
int LineWidth(vtkTextRenderer* renderer, vtkTextProperty* property, const std::string& line)
{
  int box[4] = {0, 0, 0, 0};
  if (line.empty() || !renderer->GetBoundingBox(property, vtkStdString(line), box, 72))
    return 0;
  return box[1] - box[0] + 1;
}

std::vector<std::string> Words(const std::string& text)
{
  std::vector<std::string> words;
  std::istringstream in(text);
  for (std::string word; in >> word;)
    words.push_back(word);
  return words;
}
} // namespace

FittedText FitTextToWidth(const std::string& text, int fontSize, int maxWidth)
{
  vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
  if (renderer == nullptr)
    throw std::runtime_error("VTK has no text renderer (RenderingFreeType is not loaded)");
  vtkNew<vtkTextProperty> property;
  std::vector<std::string> words = Words(text);
  FittedText fitted;
  // A smaller font (not below 11, still legible) while one word is wider than the line.
  for (fitted.fontSize = fontSize;; --fitted.fontSize)
  {
    property->SetFontSize(fitted.fontSize);
    bool wordsFit = true;
    for (const auto& word : words)
      wordsFit = wordsFit && LineWidth(renderer, property, word) <= maxWidth;
    if (wordsFit || fitted.fontSize <= std::min(11, fontSize))
      break;
  }
  // A word still wider than the line (a long file name) is cut into pieces that fit.
  std::vector<std::string> pieces;
  for (const auto& word : words)
  {
    std::string piece;
    for (const char c : word)
    {
      if (!piece.empty() && LineWidth(renderer, property, piece + c) > maxWidth)
      {
        pieces.push_back(piece);
        piece.clear();
      }
      piece += c;
    }
    pieces.push_back(piece);
  }
  std::string line;
  for (const auto& piece : pieces)
  {
    const std::string longer = line.empty() ? piece : line + " " + piece;
    if (!line.empty() && LineWidth(renderer, property, longer) > maxWidth)
    {
      fitted.text += line + "\n";
      line = piece;
    }
    else
    {
      line = longer;
    }
  }
  fitted.text += line;
  return fitted;
}

vtkSmartPointer<vtkTextActor> MakeViewTitle(const std::string& text, int viewWidth, int viewHeight, int fontSize,
                                            bool centered, int margin)
{
  const FittedText fitted = FitTextToWidth(text, fontSize, viewWidth - 2 * margin);
  auto title = vtkSmartPointer<vtkTextActor>::New();
  title->SetInput(fitted.text.c_str());
  vtkTextProperty* property = title->GetTextProperty();
  property->SetColor(0, 0, 0);
  property->SetFontSize(fitted.fontSize);
  property->SetVerticalJustificationToTop();
  if (centered)
    property->SetJustificationToCentered();
  else
    property->SetJustificationToLeft();
  title->SetDisplayPosition(centered ? viewWidth / 2 : margin, viewHeight - margin);
  return title;
}

} // namespace mmrep
