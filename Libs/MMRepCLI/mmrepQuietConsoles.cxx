// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// ITK and VTK print their own warnings and errors on stderr (for instance a VTK reader meeting a
// corrupt file). A module reports every problem as one line itself, from the exceptions our
// libraries throw, so during a module run those consoles are silenced.
#include "mmrepCLIInternal.h"

#include <itkObjectFactory.h>
#include <itkOutputWindow.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

namespace
{
class QuietVTKWindow : public vtkOutputWindow
{
public:
  static QuietVTKWindow* New();
  vtkTypeMacro(QuietVTKWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
};
vtkStandardNewMacro(QuietVTKWindow);

class QuietITKWindow : public itk::OutputWindow
{
public:
  using Self = QuietITKWindow;
  using Pointer = itk::SmartPointer<Self>;
  itkNewMacro(Self);
  void DisplayText(const char*) override {}
};
} // namespace

namespace mmrep::cli::detail
{
void SilenceToolkitConsoles()
{
  vtkNew<QuietVTKWindow> vtkWindow;
  vtkOutputWindow::SetInstance(vtkWindow);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  itk::OutputWindow::SetInstance(QuietITKWindow::New());
}
} // namespace mmrep::cli::detail
