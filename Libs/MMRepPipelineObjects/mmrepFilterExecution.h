// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// What every MMRep pipeline object does around the free function it wraps: the function's progress
// becomes the filter's ProgressEvents (vtkAlgorithm::UpdateProgress), the filter's AbortExecute flag
// is polled at every progress step (so an abort ends the run inside the long loops, as Slicer's
// Abort does for the modules), and an error becomes one line, sent as the filter's ErrorEvent.
#pragma once

#include <functional>
#include <string>

class vtkAlgorithm;
class vtkDataObject;

namespace mmrep
{

// How the filter's last execution ended.
struct FilterStatus
{
  bool aborted = false; // AbortExecute was seen: the outputs are empty
  std::string error;    // one line, empty on success: the outputs are empty
};

using FilterProgress = std::function<void(double)>; // fraction of the filter's work, in [0, 1]

// Runs `work` for `filter` (from its RequestData) and returns what RequestData returns: 1 on
// success and on abort, 0 after an error. On abort or error every output is emptied (no partial
// result flows downstream). The error goes to the filter's ErrorEvent observers (call data: the
// message), or to VTK's output window when there are none.
int ExecuteFilter(vtkAlgorithm* filter, FilterStatus& status, const std::function<void(const FilterProgress&)>& work);

// An input the filter needs: its data object, or std::invalid_argument naming the port.
vtkDataObject* RequiredInput(vtkAlgorithm* filter, int port, const char* what);

} // namespace mmrep

// Set/Get members over a field of the filter's options struct (Modified() when the value changes).
#define MMREP_FILTER_OPTION(Name, Type, field)                                                                         \
  void Set##Name(Type value)                                                                                           \
  {                                                                                                                    \
    if (!(field == value))                                                                                             \
    {                                                                                                                  \
      field = value;                                                                                                   \
      this->Modified();                                                                                                \
    }                                                                                                                  \
  }                                                                                                                    \
  Type Get##Name() const                                                                                               \
  {                                                                                                                    \
    return field;                                                                                                      \
  }
