#!/usr/bin/env bash
# MMRep demo on the bundled real CT: bash Utilities/demo.sh <build-dir> <output-dir>
# Runs the modules a user would chain and says where the results and pictures are.
set -euo pipefail
build="$1"
out="$2"
bin="$build/bin"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ct="$root/Resources/SampleData/cthead.nrrd"
mkdir -p "$out"

# Pictures need an X display; Debian's VTK renders through X11.
render=()
if [ -z "${DISPLAY:-}" ]; then render=(xvfb-run -a -s "-screen 0 2560x1600x24"); fi

step() { echo; echo "== $*"; }
# Runs a module and hides its Slicer progress lines; the module's exit status is kept (grep's "no
# line left" is not a failure).
run() { "$@" | { grep -v '^<' || true; }; }

step "SkinSkullSurfaces: CT -> skin and skull surfaces (+ picture)"
run "${render[@]}" "$bin/SkinSkullSurfaces" "$ct" "$out/skin.vtp" "$out/skull.vtp" \
  --skinMask "$out/skin-mask.nrrd" --snapshot "$out/skin-skull.png" \
  --returnparameterfile "$out/SkinSkullSurfaces.txt"

step "DistanceMap: skin and skull distance maps at 1.5 mm (the paper's resolution)"
run "$bin/DistanceMap" "$out/skin.vtp" "$out/skin-distance.nrrd" --spacing 1.5
run "$bin/DistanceMap" "$out/skull.vtp" "$out/skull-distance.nrrd" --spacing 1.5

atlas="$root/Resources/Atlas/FaceAtlas.vtu"
if [ -f "$atlas" ]; then
  step "MeshQuality and MeshConvert on the shipped face atlas"
  run "$bin/MeshQuality" "$atlas" --outputMesh "$out/atlas-quality.vtu"
  for ext in inp feb msh; do
    run "$bin/MeshConvert" "$atlas" "$out/atlas.$ext"
  done
fi

echo
echo "Results in $out:"
ls -1 "$out" | sed 's/^/  /'
echo "Picture: $out/skin-skull.png"
