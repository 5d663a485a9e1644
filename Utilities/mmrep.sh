#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# MMRep driver: installs dependencies, builds into build/, then runs the demo or the tests.
#   bash Utilities/mmrep.sh demo   # the main job on bundled data: builds only the two modules it runs
#   bash Utilities/mmrep.sh test   # everything (tests, benchmarks, examples), then the whole test suite (ctest)
#   bash Utilities/mmrep.sh build  # dependencies and the whole build only
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
jobs="$(nproc 2>/dev/null || echo 2)"

deps_and_build() {
  bash "$root/Utilities/install-deps.sh"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON >/dev/null
  cmake --build "$build" -j "$jobs"
}

# The demo's modules and the libraries they link, nothing else; a build/ made by the demo has no tests
# (no GoogleTest needed), a build/ made by `test` or `build` keeps them.
demo_build() {
  bash "$root/Utilities/install-deps.sh" --demo
  local testing=()
  [ -f "$build/CMakeCache.txt" ] || testing=(-DBUILD_TESTING=OFF)
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "${testing[@]}" >/dev/null
  cmake --build "$build" -j "$jobs" --target FaceModelPipeline SimulateMuscleActivation
}

case "${1:-}" in
  build) deps_and_build ;;
  test)
    deps_and_build
    cd "$build"
    ctest -j "$jobs" --output-on-failure --timeout 900
    ;;
  demo)
    demo_build
    bash "$root/Utilities/demo.sh" "$build" "${2:-$root/mmrep-demo-output}"
    ;;
  *)
    echo "usage: bash Utilities/mmrep.sh {demo [output-dir]|test|build}" >&2
    exit 2
    ;;
esac
