#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# Installs MMRep's build and test dependencies from Debian 12 packages.
# Idempotent: does nothing (no apt-get update either) when every package is already installed.
set -euo pipefail

PACKAGES=(
  cmake g++ make pkg-config
  libinsighttoolkit5-dev   # ITK 5.2: images, filters, DICOM (GDCM)
  libvtk9-dev              # VTK 9.1: surface and mesh file formats, rendering
  libeigen3-dev            # linear algebra
  libopenmesh-dev          # half-edge surface meshes
  nlohmann-json3-dev       # Slicer markups (.mrk.json), reports
  libtclap-dev             # command-line parsing (as Slicer's GenerateCLP)
  zlib1g-dev               # the decompressed length of .nii.gz volumes, checked before reading
  libgtest-dev             # unit tests
  libxml2-utils            # xmllint: module descriptions against the Slicer schema
  calculix-ccx gmsh        # real FE tools that read our exports in the tests
  xvfb xauth libx11-dev     # off-screen X server for VTK pictures, X connection check
  clang-format pmccabe      # tree hygiene tests: formatting, function lengths
)

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
