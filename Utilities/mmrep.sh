#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# MMRep driver: installs dependencies, builds into build/, then runs the demo or the tests.
#   bash Utilities/mmrep.sh demo   # the main job on bundled data
#   bash Utilities/mmrep.sh test   # the whole test suite (ctest)
#   bash Utilities/mmrep.sh build  # dependencies and build only
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
jobs="$(nproc 2>/dev/null || echo 2)"

deps_and_build() {
  bash "$root/Utilities/install-deps.sh"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j "$jobs"
}

case "${1:-}" in
  build) deps_and_build ;;
  test)
    deps_and_build
    cd "$build"
    ctest -j "$jobs" --output-on-failure --timeout 900
    ;;
  demo)
    deps_and_build
    bash "$root/Utilities/demo.sh" "$build" "${2:-$root/mmrep-demo-output}"
    ;;
  *)
    echo "usage: bash Utilities/mmrep.sh {demo [output-dir]|test|build}" >&2
    exit 2
    ;;
esac
