// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepHistogramPicture.h"

#include "mmrepPictureText.h"
#include "mmrepSnapshot.h"

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace mmrep
{

std::vector<std::size_t> HistogramCounts(const std::vector<double>& values, int bins)
{
  std::vector<std::size_t> counts(static_cast<std::size_t>(bins), 0);
  for (const double v : values)
  {
    if (std::isnan(v))
      continue;
    const double clamped = std::min(std::max(v, -1.0), 1.0);
    const int bin = std::min(bins - 1, static_cast<int>(std::floor((clamped + 1) / 2 * bins)));
    ++counts[static_cast<std::size_t>(bin)];
  }
  return counts;
}

namespace
{
// Frame of one panel in normalized viewport coordinates.
constexpr double kLeft = 0.12, kRight = 0.96, kBottom = 0.14, kTop = 0.86;
constexpr int kPanelWidth = 560, kPanelHeight = 420; // pixels

void AddText(vtkRenderer* renderer, const std::string& text, double x, double y, int size, int justification)
{
  vtkNew<vtkTextActor> label;
  label->SetInput(text.c_str());
  label->GetTextProperty()->SetColor(0, 0, 0);
  label->GetTextProperty()->SetFontSize(size);
  label->GetTextProperty()->SetJustification(justification);
  label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  label->GetPositionCoordinate()->SetValue(x, y);
  renderer->AddActor2D(label);
}

void AddPanel(vtkRenderer* renderer, const HistogramPanel& panel, double threshold, int bins, std::size_t maxCount)
{
  const std::vector<std::size_t> counts = HistogramCounts(panel.values, bins);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads, lines;
  std::vector<std::array<unsigned char, 3>> quadColors, lineColors;
  auto X = [&](double value) { return kLeft + (value + 1) / 2 * (kRight - kLeft); };
  auto Y = [&](double count) {
    return kBottom + count / double(std::max<std::size_t>(maxCount, 1)) * (kTop - kBottom);
  };
  auto point = [&](double x, double y) { return points->InsertNextPoint(x, y, 0); };
  for (int b = 0; b < bins; ++b)
  {
    if (counts[b] == 0)
      continue;
    const double lo = -1 + 2.0 * b / bins, hi = -1 + 2.0 * (b + 1) / bins;
    const vtkIdType q[4] = {point(X(lo), Y(0)), point(X(hi), Y(0)), point(X(hi), Y(double(counts[b]))),
                            point(X(lo), Y(double(counts[b])))};
    quads->InsertNextCell(4, q);
    const bool below = lo < threshold;
    quadColors.push_back(below ? std::array<unsigned char, 3>{215, 60, 50}
                               : std::array<unsigned char, 3>{60, 110, 200});
  }
  // Axes, ticks and the threshold line, black; the threshold line grey.
  const auto line = [&](double x0, double y0, double x1, double y1, unsigned char grey) {
    const vtkIdType l[2] = {point(x0, y0), point(x1, y1)};
    lines->InsertNextCell(2, l);
    lineColors.push_back({grey, grey, grey});
  };
  line(X(-1), Y(0), X(1), Y(0), 0);
  line(X(-1), Y(0), X(-1), kTop, 0);
  for (int t = 0; t <= 4; ++t)
    line(X(-1 + 0.5 * t), Y(0), X(-1 + 0.5 * t), Y(0) - 0.02, 0);
  line(X(threshold), Y(0), X(threshold), kTop, 120);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(quads);
  poly->SetLines(lines);
  // vtkPolyData numbers lines before polygons: colours in that order.
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  for (const auto* list : {&lineColors, &quadColors})
    for (const auto& c : *list)
      colors->InsertNextTypedTuple(c.data());
  poly->GetCellData()->SetScalars(colors);
  vtkNew<vtkCoordinate> coordinate;
  coordinate->SetCoordinateSystemToNormalizedViewport();
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(poly);
  mapper->SetTransformCoordinate(coordinate);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  vtkNew<vtkActor2D> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(2);
  renderer->AddActor2D(actor);

  for (int t = 0; t <= 4; ++t)
  {
    char text[16];
    std::snprintf(text, sizeof text, "%.1f", -1 + 0.5 * t);
    AddText(renderer, text, X(-1 + 0.5 * t), Y(0) - 0.08, 14, VTK_TEXT_CENTERED);
  }
  AddText(renderer, "0", kLeft - 0.02, Y(0), 14, VTK_TEXT_RIGHT);
  AddText(renderer, std::to_string(maxCount), kLeft - 0.02, kTop - 0.03, 14, VTK_TEXT_RIGHT);
  std::size_t below = 0;
  for (const double v : panel.values)
    below += (!std::isnan(v) && v < threshold) ? 1 : 0;
  char title[256];
  std::snprintf(title, sizeof title, "%s: %zu elements, %zu below %.2f", panel.title.c_str(), panel.values.size(),
                below, threshold);
  renderer->AddActor2D(MakeViewTitle(title, kPanelWidth, kPanelHeight, 16, true));
  AddText(renderer, "scaled Jacobian", 0.5, 0.01, 14, VTK_TEXT_CENTERED);
}
} // namespace

void WriteHistogramPNG(const std::vector<HistogramPanel>& panels, double threshold, const std::string& pngPath,
                       int bins)
{
  RequireDisplay(pngPath);
  if (panels.empty())
    throw std::runtime_error("no histogram to draw in " + pngPath);
  std::size_t maxCount = 1;
  for (const auto& panel : panels)
  {
    const auto counts = HistogramCounts(panel.values, bins);
    maxCount = std::max(maxCount, *std::max_element(counts.begin(), counts.end()));
  }
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  const int n = static_cast<int>(panels.size());
  window->SetSize(kPanelWidth * n, kPanelHeight);
  for (int i = 0; i < n; ++i)
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(double(i) / n, 0, double(i + 1) / n, 1);
    renderer->SetBackground(1, 1, 1);
    AddPanel(renderer, panels[static_cast<std::size_t>(i)], threshold, bins, maxCount);
    window->AddRenderer(renderer);
  }
  WriteWindowPNG(window, pngPath);
}

} // namespace mmrep
