#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# InstallAndRelocate.sh cmake build-dir source-dir bin-dir cli-lib-dir data-dir "modules"
set -euo pipefail
cmake=$1 build=$2 src=$3 bindir=$4 libdir=$5 datadir=$6 modules=$7
fail() { echo "FAIL: $*" >&2; exit 1; }
work=$(mktemp -d /tmp/mmrep-install-XXXXXX) # outside the source tree, which is hidden below
trap 'rm -rf "$work"' EXIT

"$cmake" --install "$build" --prefix "$work/prefix" > "$work/install.log" || fail "cmake --install failed"
mv "$work/prefix" "$work/moved" # relocated: nothing may point at the prefix it was installed to
P=$work/moved
for m in $modules; do
  [ -x "$P/$bindir/$m" ] || fail "$m not installed in $bindir"
  [ -f "$P/$libdir/lib${m}Lib.so" ] || fail "lib${m}Lib.so not installed in $libdir"
done
for f in Atlas/FaceAtlas.vtu SampleData/cthead.nrrd SampleData/cthead.ControlPoints.mrk.json; do
  [ -s "$P/$datadir/$f" ] || fail "$datadir/$f not installed"
done
# No path of the source or build tree (or of the first prefix) in any installed file.
if grep -rlF -e "$src" -e "$work/prefix" "$P" > "$work/paths"; then
  fail "installed files name the source tree or the install prefix: $(tr '\n' ' ' < "$work/paths")"
fi

run=(env -u MMREP_CCX "$P/$bindir/FaceModelPipeline" "$P/$datadir/SampleData/cthead.nrrd"
     "$P/$datadir/SampleData/cthead.ControlPoints.mrk.json" --outputDirectory "$work/speaker" --noPictures)
# Hide the source tree (and the build tree inside it) with an empty mount in a private namespace.
if unshare -rm true 2> /dev/null; then
  (cd "$work" && unshare -rm bash -c 'mount -t tmpfs none "$0" && [ -z "$(ls -A "$0")" ] && exec "$@"' "$src" "${run[@]}") \
    > "$work/run.log" 2>&1 || { cat "$work/run.log"; fail "installed FaceModelPipeline failed with the source tree hidden"; }
else
  echo "note: unshare is not permitted here, the source tree stays visible (its paths are checked above)"
  (cd "$work" && "${run[@]}") > "$work/run.log" 2>&1 || { cat "$work/run.log"; fail "installed FaceModelPipeline failed"; }
fi
for f in model.vtu model.inp report.json; do [ -s "$work/speaker/$f" ] || fail "missing $f"; done
grep -qF "\"atlas\": \"$P/$datadir/Atlas/FaceAtlas.vtu\"" "$work/speaker/report.json" ||
  fail "the model was not made with the installed default atlas: $(grep '"atlas"' "$work/speaker/report.json")"
grep -q 'Repair succeeded' "$work/speaker/report.md" || fail "repair did not succeed"
echo "installed tree relocated to $P: model made with $P/$datadir/Atlas/FaceAtlas.vtu"
