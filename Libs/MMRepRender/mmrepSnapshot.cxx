// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepSnapshot.h"

#include "mmrepPictureText.h"

#include "mmrepDiskSpace.h"
#include "mmrepFatalError.h"
#include "mmrepSilencedCStandardError.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include <X11/Xlib.h> // last: its macros (None, Status, Bool) clash with other headers

namespace mmrep
{

namespace
{
// Camera direction (from focal point to camera) and up vector, in LPS.
void ViewVectors(View v, double dir[3], double up[3])
{
  up[0] = 0, up[1] = 0, up[2] = 1; // superior
  dir[0] = dir[1] = dir[2] = 0;
  switch (v)
  {
    case View::Anterior:
      dir[1] = -1;
      break; // anterior is -P
    case View::Posterior:
      dir[1] = 1;
      break;
    case View::Left:
      dir[0] = 1;
      break; // left is +L
    case View::Right:
      dir[0] = -1;
      break;
    case View::Superior:
      dir[2] = 1, up[1] = -1, up[2] = 0; // nose up in the picture
      break;
    case View::Inferior:
      dir[2] = -1, up[1] = -1, up[2] = 0;
      break;
  }
}

const char* ViewName(View v)
{
  switch (v)
  {
    case View::Anterior:
      return "anterior";
    case View::Posterior:
      return "posterior";
    case View::Left:
      return "left";
    case View::Right:
      return "right";
    case View::Superior:
      return "superior";
    case View::Inferior:
      return "inferior";
  }
  return "";
}
} // namespace

namespace
{
constexpr int kDisplayAttempts = 20;
constexpr int kDisplayRetryMilliseconds = 250; // 5 s in all
} // namespace

namespace
{
// Xlib calls this when the connection to the X server is lost (the server ended) and ends the
// process if it returns: the run is ended through FatalError, which removes what it staged.
extern "C" int DisplayLost(Display*)
{
  const char* display = std::getenv("DISPLAY");
  mmrep::FatalError(std::string("the X display '") + (display ? display : "") +
                    "' closed while the pictures were rendered (its X server ended); nothing written");
}
} // namespace

void RequireDisplay(const std::string& pngPath)
{
  XSetIOErrorHandler(DisplayLost); // again each time: a library may have set its own
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0')
    throw std::runtime_error("no X display for rendering " + pngPath + ": run under xvfb-run -a");
  // VTK aborts the process when it cannot connect to the X server (vtkXOpenGLRenderWindow), with its
  // message silenced: connect here first, a few times (a server just started may not accept yet),
  // and fail with one line instead. The connection stays open for the life of the process: an X
  // server started without -noreset (xvfb-run's default) resets when its last client leaves, and a
  // window opened during the reset cannot connect.
  static Display* held = nullptr;
  for (int attempt = 0; attempt < kDisplayAttempts && held == nullptr; ++attempt)
  {
    held = XOpenDisplay(nullptr);
    if (held == nullptr)
      std::this_thread::sleep_for(std::chrono::milliseconds(kDisplayRetryMilliseconds));
  }
  if (held == nullptr)
    throw std::runtime_error(std::string("cannot connect to the X display '") + display + "' for rendering " + pngPath);
  // The server may have ended since (VTK aborts when a new window cannot connect): a fresh connection
  // each time tells, and the run then unwinds with one line.
  Display* probe = XOpenDisplay(nullptr);
  if (probe == nullptr)
    throw std::runtime_error(std::string("the X display '") + display + "' closed (its X server ended) before " +
                             pngPath + " was rendered");
  XCloseDisplay(probe);
}

void WriteWindowPNG(vtkRenderWindow* window, const std::string& pngPath)
{
  RequireDisplay(pngPath);
  window->SetOffScreenRendering(1);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> png;
  png->SetFileName(pngPath.c_str());
  png->SetInputConnection(grab->GetOutputPort());
  {
    mmrep::SilencedCStandardError libpng; // "libpng error: Write Error"
    png->Write();
  }
  if (png->GetErrorCode() != 0)
    throw std::runtime_error("cannot write " + pngPath + mmrep::WriteFailureReason(pngPath));
}

void WriteSnapshot(const std::vector<SnapshotLayer>& layers, const SnapshotOptions& o, const std::string& pngPath)
{
  RequireDisplay(pngPath);
  if (o.views.empty())
    throw std::runtime_error("no view requested for " + pngPath);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  const int n = static_cast<int>(o.views.size());
  window->SetSize(o.viewWidth * n, o.viewHeight);

  for (int i = 0; i < n; ++i)
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(double(i) / n, 0, double(i + 1) / n, 1);
    renderer->SetBackground(1, 1, 1);
    for (const auto& layer : layers)
    {
      if (layer.surface == nullptr)
        continue;
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(layer.surface);
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->SetColor(layer.color[0], layer.color[1], layer.color[2]);
      actor->GetProperty()->SetOpacity(layer.opacity);
      actor->GetProperty()->SetLineWidth(layer.lineWidth);
      if (layer.wireframe)
        actor->GetProperty()->SetRepresentationToWireframe();
      if (layer.pointSize > 0)
      {
        actor->GetProperty()->SetRepresentationToPoints();
        actor->GetProperty()->SetPointSize(layer.pointSize);
        actor->GetProperty()->RenderPointsAsSpheresOn();
      }
      if (!layer.scalars.empty() && layer.surface->GetPointData()->GetArray(layer.scalars.c_str()))
      {
        vtkNew<vtkLookupTable> lut; // blue (good) to red (bad)
        lut->SetHueRange(0.667, 0.0);
        lut->SetTableRange(layer.range[0], layer.range[1]);
        lut->Build();
        mapper->SetLookupTable(lut);
        mapper->SetScalarModeToUsePointFieldData();
        mapper->SelectColorArray(layer.scalars.c_str());
        mapper->SetScalarRange(layer.range[0], layer.range[1]);
        mapper->ScalarVisibilityOn();
        if (i == n - 1)
        {
          vtkNew<vtkScalarBarActor> bar;
          bar->SetLookupTable(lut);
          bar->SetTitle(layer.scalarTitle.empty() ? layer.scalars.c_str() : layer.scalarTitle.c_str());
          bar->SetNumberOfLabels(5);
          bar->SetWidth(0.12);
          bar->SetHeight(0.5);
          bar->SetPosition(0.86, 0.1);
          bar->GetTitleTextProperty()->SetColor(0, 0, 0);
          bar->GetLabelTextProperty()->SetColor(0, 0, 0);
          renderer->AddActor2D(bar);
        }
      }
      else
      {
        mapper->ScalarVisibilityOff();
      }
      renderer->AddActor(actor);
    }
    double dir[3], up[3];
    ViewVectors(o.views[i], dir, up);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0, 0, 0);
    camera->SetPosition(dir);
    camera->SetViewUp(up);
    camera->ParallelProjectionOn();
    const auto& f = o.focus;
    if (f[0] <= f[1] && f[2] <= f[3] && f[4] <= f[5])
      renderer->ResetCamera(const_cast<double*>(f.data()));
    else
      renderer->ResetCamera();

    const std::string label =
      (i == 0 && !o.title.empty() ? o.title + " - " : std::string()).append(ViewName(o.views[i]));
    renderer->AddActor2D(MakeViewTitle(label, o.viewWidth, o.viewHeight));
    window->AddRenderer(renderer);
  }
  WriteWindowPNG(window, pngPath);
}

} // namespace mmrep
