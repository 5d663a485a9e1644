// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Progress, abort and errors of the pipeline objects (see the header).
#include "mmrepFilterExecution.h"

#include <itkMacro.h>
#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkDataObject.h>
#include <vtkExecutive.h>

#include <stdexcept>

namespace mmrep
{
namespace
{
// Thrown from the progress function when the filter's AbortExecute is set; not a std::exception,
// so the wrapped library code's `catch (const std::exception&)` never swallows it.
struct AbortRequested
{
};

std::string OneLine(const std::string& text)
{
  std::string line;
  for (char c : text)
    if (line.empty() && (c == ' ' || c == '\n' || c == '\r'))
      continue;
    else if (c == '\n' || c == '\r')
    {
      if (!line.empty() && line.back() != ' ')
        line += ' ';
    }
    else
      line += c;
  while (!line.empty() && line.back() == ' ')
    line.pop_back();
  return line;
}

void EmptyOutputs(vtkAlgorithm* filter)
{
  for (int i = 0; i < filter->GetNumberOfOutputPorts(); ++i)
    if (vtkDataObject* out = filter->GetOutputDataObject(i))
      out->Initialize();
}
} // namespace

int ExecuteFilter(vtkAlgorithm* filter, FilterStatus& status, const std::function<void(const FilterProgress&)>& work)
{
  status = {};
  // The executive sends progress 0 before RequestData and 1 after it (unless aborted).
  const FilterProgress progress = [filter](double f) {
    if (filter->GetAbortExecute())
      throw AbortRequested{};
    if (f > 0)
      filter->UpdateProgress(f > 1 ? 1 : f);
  };
  try
  {
    progress(0.0);
    work(progress);
    return 1;
  }
  catch (const AbortRequested&)
  {
    status.aborted = true;
    EmptyOutputs(filter);
    return 1;
  }
  catch (const itk::ExceptionObject& e) // a reader upstream: its description, without the source line
  {
    status.error = std::string(filter->GetClassName()) + ": " + OneLine(e.GetDescription());
  }
  catch (const std::exception& e)
  {
    status.error = std::string(filter->GetClassName()) + ": " + OneLine(e.what());
  }
  EmptyOutputs(filter);
  if (filter->HasObserver(vtkCommand::ErrorEvent))
    filter->InvokeEvent(vtkCommand::ErrorEvent, const_cast<char*>(status.error.c_str()));
  else
    vtkErrorWithObjectMacro(filter, << status.error);
  return 0;
}

vtkDataObject* RequiredInput(vtkAlgorithm* filter, int port, const char* what)
{
  vtkDataObject* input =
    filter->GetNumberOfInputConnections(port) > 0 ? filter->GetExecutive()->GetInputData(port, 0) : nullptr;
  if (input == nullptr || input->GetNumberOfElements(vtkDataObject::POINT) == 0)
    throw std::invalid_argument(std::string(what) + " (input " + std::to_string(port) +
                                ") is missing or empty (an upstream filter failed or was aborted)");
  return input;
}

} // namespace mmrep
