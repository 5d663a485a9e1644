#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# Installs MMRep's build and test dependencies from Debian 12 packages.
# Idempotent: does nothing (no apt-get update either) when every package is already installed.
#   bash Utilities/install-deps.sh          # everything: build, demo, tests
#   bash Utilities/install-deps.sh --demo   # only what the demo builds and runs (no test tools)
set -euo pipefail

DEMO_PACKAGES=(
  cmake g++ make pkg-config
  libinsighttoolkit5-dev   # ITK 5.2: images, filters, DICOM (GDCM)
  libvtk9-dev              # VTK 9.1: surface and mesh file formats, rendering
  libeigen3-dev            # linear algebra
  libopenmesh-dev          # half-edge surface meshes
  nlohmann-json3-dev       # Slicer markups (.mrk.json), reports
  libtclap-dev             # command-line parsing (as Slicer's GenerateCLP)
  liblbfgspp-dev           # L-BFGS minimiser (header-only, Eigen) of the foldover-free untangling
  zlib1g-dev               # the decompressed length of .nii.gz volumes, checked before reading
  calculix-ccx             # the muscle-activation solver
  xvfb xauth libx11-dev    # off-screen X server for VTK pictures, X connection check
)
TEST_PACKAGES=(
  libgtest-dev             # unit tests
  libxml2-utils            # xmllint: module descriptions against the Slicer schema
  gmsh                     # a real FE tool that reads our exports in the tests
  clang-format pmccabe     # tree hygiene tests: formatting, function lengths
)
case "${1:-}" in
  --demo) PACKAGES=("${DEMO_PACKAGES[@]}") ;;
  "") PACKAGES=("${DEMO_PACKAGES[@]}" "${TEST_PACKAGES[@]}") ;;
  *) echo "usage: bash Utilities/install-deps.sh [--demo]" >&2; exit 2 ;;
esac

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "MMRep: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
