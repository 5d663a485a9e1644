#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# BuildStandAlone.sh CMAKE CTEST MODULE_SOURCE SCRATCH ITK_DIR [LAUNCHER]
# Configures MODULE_SOURCE alone in a fresh SCRATCH folder against ITK_DIR, builds it and runs its
# Saito-Toriwaki brute-force test there. Fails if the configure, the build or the test fails, or if the
# scratch build found no test (i.e. it did not build the module's test/ folder).
set -euo pipefail
cmake=$1 ctest=$2 source=$3 scratch=$4 itk=$5 launcher=${6:-}
rm -rf "$scratch"
mkdir -p "$scratch"
args=(-S "$source" -B "$scratch" -DITK_DIR="$itk" -DCMAKE_BUILD_TYPE=Release)
if [ -n "$launcher" ]; then
  args+=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher")
fi
"$cmake" "${args[@]}" > "$scratch/configure.log" || { cat "$scratch/configure.log"; exit 1; }
grep -q "^CMAKE_PROJECT_NAME:STATIC=MMRepImage$" "$scratch/CMakeCache.txt" ||
  { echo "the scratch build is not the MMRepImage project" >&2; exit 1; }
nice -n 10 "$cmake" --build "$scratch" -j2 > "$scratch/build.log" || { tail -40 "$scratch/build.log"; exit 1; }
cd "$scratch"
listed=$("$ctest" -N -R 'SaitoToriwaki.*BruteForce' | sed -n 's/^Total Tests: //p')
if [ "${listed:-0}" -lt 1 ]; then
  echo "no Saito-Toriwaki brute-force test in the stand-alone build" >&2
  "$ctest" -N >&2
  exit 1
fi
"$ctest" -R 'SaitoToriwaki.*BruteForce' --output-on-failure
