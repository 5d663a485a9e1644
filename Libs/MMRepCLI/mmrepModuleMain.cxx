// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Executable wrapper of a CLI module: the science lives in the module's shared library (Slicer loads it too).
// Only the executable turns SIGINT/SIGTERM into a clean abort (never inside Slicer's process).
extern "C" int ModuleEntryPoint(int argc, char* argv[]);
namespace mmrep::cli
{
void InstallInterruptHandlers(); // mmrepCLI.h, linked into the module's library
}

int main(int argc, char* argv[])
{
  mmrep::cli::InstallInterruptHandlers();
  return ModuleEntryPoint(argc, argv);
}
