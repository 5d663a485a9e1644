// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// One thread count for the project's own worker pools, set as ITK's is: by the environment variable
// ITK_GLOBAL_DEFAULT_NUMBER_OF_THREADS, else one per processor. So one variable runs a whole module
// (ITK filters and our loops alike) on 1 or N threads, which the determinism tests compare.
#pragma once

namespace mmrep
{

// ITK_GLOBAL_DEFAULT_NUMBER_OF_THREADS when set to a positive integer, else the processor count;
// at least 1, at most `most`.
unsigned WorkerThreads(unsigned most = 128);

} // namespace mmrep
