// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Runs CalculiX (ccx) on a deck in a private temporary directory and reads its nodal results back.
#pragma once

#include "mmrepFrdReader.h"

#include <functional>
#include <string>
#include <vector>

namespace mmrep::simulation
{

struct RunOptions
{
  std::string executable;               // empty: $MMREP_CCX, else `ccx` on PATH
  int threads = 1;                      // OMP_NUM_THREADS for ccx; 1 gives identical bytes on every run
  bool keepDirectory = false;           // leave the job folder (deck, log, .frd, .dat) for inspection
  std::function<void(double)> progress; // step time reached, in [0, 1]
};

// How a ccx run ended: only DidNotConverge says something about the model's mechanics.
enum class CalculiXOutcome
{
  Converged,      // exit code 0, "Job finished", the last result at step time 1
  DidNotConverge, // ccx cut the increment back until it gave up (or stopped before step time 1)
  DeckRefused,    // ccx stopped on an *ERROR in the deck before any increment
  Crashed,        // ccx was killed by a signal (a fault of the solver or of the machine)
  NoResults,      // ccx ended without an error message and without results
};

struct CalculiXRun
{
  bool converged = false; // outcome == Converged
  CalculiXOutcome outcome = CalculiXOutcome::NoResults;
  int exitCode = -1;
  int increments = 0;    // converged increments (result blocks written)
  int iterations = 0;    // Newton iterations over all attempts
  int cutbacks = 0;      // increments that were retried with a smaller size
  double stepTime = 0;   // step time of the last converged increment
  double seconds = 0;    // wall time of the ccx process
  std::string directory; // job folder when kept
  std::string log;       // ccx's stdout and stderr
  std::string message;   // why it did not converge (first *ERROR line or last log line)
  std::vector<FrdBlock> results;
};

// Path of the ccx executable to use; throws std::runtime_error with a clear message when there is
// none (names $MMREP_CCX or the Debian package calculix-ccx).
std::string FindCalculiX(const std::string& executable = "");

// Writes `deck` as job.inp in a fresh temporary folder, runs ccx there and parses job.frd.
// Throws std::runtime_error only when ccx cannot be started or its output is unreadable; a solve
// that does not converge returns converged == false with `message` set.
CalculiXRun RunCalculiX(const std::string& deck, const RunOptions& options);

// One line for a run that did not converge, naming what failed (the solve, the deck, the solver).
std::string DescribeFailure(const CalculiXRun& run);

} // namespace mmrep::simulation
