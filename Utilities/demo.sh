#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# MMRep demo on the bundled real CT: bash Utilities/demo.sh <build-dir> <output-dir>
# The README's main command: CT + five control points -> speaker FE face model with muscles, its
# exports, report and pictures (FaceModelPipeline), then a smile simulated with CalculiX
# (SimulateMuscleActivation, zygomaticus major left).
set -euo pipefail
build="$1"
out="$2"
bin="$build/bin"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ct="$root/Resources/SampleData/cthead.nrrd"
points="$root/Resources/SampleData/cthead.ControlPoints.mrk.json"
mkdir -p "$(dirname "$out")"

# Pictures need an X display; Debian's VTK renders through X11.
render=()
if [ -z "${DISPLAY:-}" ]; then render=(xvfb-run -a -n $((100 + $$ % 20000)) -s "-screen 0 2560x1600x24 -noreset"); fi

step() { echo; echo "== $*"; }
# Runs a module and hides its Slicer progress lines; the module's exit status is kept (grep's "no
# line left" is not a failure).
run() { "$@" | { grep -v '^<' || true; }; }

step "FaceModelPipeline: CT + control points -> speaker FE face model (surfaces, plane, R, Q, repair, muscles)"
run "${render[@]}" "$bin/FaceModelPipeline" "$ct" "$points" --outputDirectory "$out"

step "SimulateMuscleActivation: zygomaticus major (left) contracted, solved with CalculiX"
run "${render[@]}" "$bin/SimulateMuscleActivation" "$out/model.vtu" "$out/smile.vtu" \
  --muscles ZygomaticusMajor_L --picture "$out/smile.png" --lipsPicture "$out/smile-lips.png"

echo
echo "Results in $out:"
ls -1 "$out" | sed 's/^/  /'
echo "Report: $out/report.md"
echo "Pictures: $out/model-skin-error.png $out/lips.png $out/muscles.png $out/smile.png $out/smile-lips.png"
