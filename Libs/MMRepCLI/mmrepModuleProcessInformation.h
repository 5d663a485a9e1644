// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Slicer's in-process progress block. Slicer passes its address to a shared-library module with
// --processinformationaddress (written with printf's %p); the layout must match Slicer's own
// declaration (SlicerExecutionModel, ModuleDescriptionParser/ModuleProcessInformation.h) field for
// field. Declared here so that modules and tests need no Slicer headers.
#pragma once

extern "C"
{
  struct ModuleProcessInformation
  {
    unsigned char Abort;                     // in: the caller sets it to cancel the run
    float Progress;                          // out: overall progress, 0..1
    float StageProgress;                     // out: progress of the current stage, 0..1
    char ProgressMessage[1024];              // out: the current stage's name
    void (*ProgressCallbackFunction)(void*); // called after every change, with ProgressCallbackClientData
    void* ProgressCallbackClientData;
    double ElapsedTime; // out: seconds since the module started
  };
}
