// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Titles fit their picture: each title is drawn in a window twice the view's size and the drawn
// pixels (not VTK's own measure) must lie inside the view, on more than one line where the text is
// wider than the view. Needs an X display (ctest runs it under xvfb-run).
#include "mmrepPictureText.h"

#include <gtest/gtest.h>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkStdString.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <set>
#include <string>

namespace
{
struct Ink
{
  int xmin = 1 << 30, xmax = -1, ymin = 1 << 30, ymax = -1;
  int rows = 0;  // rows holding ink
  int lines = 0; // runs of such rows
};

// Draws `title` alone in a white window of `width` × `height` pixels and finds its dark pixels.
Ink Draw(vtkTextActor* title, int width, int height)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);
  renderer->AddActor2D(title);
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  Ink ink;
  bool previousRow = false;
  for (int y = 0; y < dims[1]; ++y)
  {
    bool row = false;
    for (int x = 0; x < dims[0]; ++x)
    {
      const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      if (p[0] < 128 && p[1] < 128 && p[2] < 128)
      {
        row = true;
        ink.xmin = std::min(ink.xmin, x);
        ink.xmax = std::max(ink.xmax, x);
        ink.ymin = std::min(ink.ymin, y);
        ink.ymax = std::max(ink.ymax, y);
      }
    }
    ink.rows += row ? 1 : 0;
    ink.lines += (row && !previousRow) ? 1 : 0;
    previousRow = row;
  }
  return ink;
}

int UnwrappedWidth(const std::string& text, int fontSize)
{
  vtkNew<vtkTextProperty> property;
  property->SetFontSize(fontSize);
  int box[4];
  EXPECT_TRUE(vtkTextRenderer::GetInstance()->GetBoundingBox(property, vtkStdString(text), box, 72));
  return box[1] - box[0] + 1;
}

struct TitleCase
{
  std::string text;
  int width, height;
  bool centered;
};

// The longest titles the modules draw (FaceModelPipeline's skin and lips pictures at 600 px a view,
// MeshReparation's histogram panel at 560 px), and a word wider than any view.
const TitleCase kCases[] = {
  {"speaker model skin (coloured by distance to the speaker's skin, 0-1 mm) over the speaker's skin - Anterior", 600,
   600, false},
  {"lips close-up: model skin coloured by distance to the speaker's skin (0-1 mm), lips nodes blue - Anterior", 600,
   600, false},
  {"after repair (global untangling, then node by node): 11016 elements, 0 below 0.30", 560, 420, true},
  {"Orbicularis_oris_superior_L+Zygomaticus_major_L", 360, 300, false},
  {"Orbicularis_oris_superior_L+Orbicularis_oris_inferior_L+Orbicularis_oris_superior_R+Zygomaticus_major_L", 300, 300,
   false},
};
} // namespace

TEST(PictureTitles, LongTitlesWrapInsideTheView)
{
  for (const auto& c : kCases)
  {
    SCOPED_TRACE(c.text);
    ASSERT_GT(UnwrappedWidth(c.text, 16), c.width) << "the case must be wider than its view on one line";
    vtkSmartPointer<vtkTextActor> title = mmrep::MakeViewTitle(c.text, c.width, c.height, 16, c.centered);
    // A window twice the view's size, the view in its lower left quarter: ink beyond the view is seen.
    const Ink ink = Draw(title, 2 * c.width, 2 * c.height);
    ASSERT_GT(ink.rows, 0) << "nothing drawn";
    EXPECT_GE(ink.xmin, 0);
    EXPECT_LT(ink.xmax, c.width) << "the title runs past the view's right edge";
    EXPECT_LT(ink.ymax, c.height) << "the title runs past the view's top";
    EXPECT_GT(ink.ymin, c.height / 2) << "the title reaches into the lower half of the view";
    if (c.centered)
      EXPECT_LE(std::abs((ink.xmin + ink.xmax) / 2 - c.width / 2), 8) << "not centred";
    const std::string wrapped = title->GetInput();
    const int lines = 1 + static_cast<int>(std::count(wrapped.begin(), wrapped.end(), '\n'));
    // Drawn on as many lines as it was wrapped to: the ink is that many lines of the font tall.
    const int size = title->GetTextProperty()->GetFontSize(), inkHeight = ink.ymax - ink.ymin + 1;
    EXPECT_GE(inkHeight, (lines - 1) * size + size / 2);
    EXPECT_LE(inkHeight, lines * 2 * size);
    if (c.text.find(' ') == std::string::npos)
      EXPECT_LT(title->GetTextProperty()->GetFontSize(), 16) << "one word wider than the view: a smaller font";
    else
      EXPECT_GT(lines, 1);
  }
}

TEST(PictureTitles, ShortTitleKeptOnOneLineAtItsSize)
{
  const std::string text = "skin (translucent) and skull - Anterior";
  const mmrep::FittedText fitted = mmrep::FitTextToWidth(text, 16, 584);
  EXPECT_EQ(fitted.text, text);
  EXPECT_EQ(fitted.fontSize, 16);
  const Ink ink = Draw(mmrep::MakeViewTitle(text, 600, 600), 1200, 1200);
  EXPECT_EQ(ink.lines, 1);
  EXPECT_NEAR(ink.xmax - ink.xmin + 1, UnwrappedWidth(text, 16), 3);
}
