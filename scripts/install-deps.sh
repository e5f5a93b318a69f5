#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Debian 12 packages kinstab needs to build, test and write reports (README.md "Layout").
set -euo pipefail
packages=(cmake g++ make qt6-base-dev qt6-charts-dev qt6-datavisualization-dev qt6-declarative-dev
          qt6-svg-dev libqt6opengl6-dev libeigen3-dev nlohmann-json3-dev xvfb xauth libgl1-mesa-dri
          fonts-dejavu-core poppler-utils locales
          python3-dev pybind11-dev python3-pybind11 python3-pytest python3-numpy python3-matplotlib
          parallel python3-dask python3-distributed  # studies: GNU parallel and Dask (docs/studies.md)
          dpkg-dev file desktop-file-utils appstream
          clang libclang-rt-14-dev  # the Debian package and its validators; the fuzzers
          ninja-build ccache)  # faster builds (scripts/build.sh)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
if [ ${#missing[@]} -gt 0 ]; then
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# The suite runs the CLI and a GUI test under a German locale (decimal comma): numbers in files
# must not follow the locale. Generated once; later runs find it and do nothing.
if ! locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$'; then
  $SUDO sed -i 's/^# *\(de_DE\.UTF-8 UTF-8\)/\1/' /etc/locale.gen
  grep -q '^de_DE\.UTF-8 UTF-8' /etc/locale.gen || echo 'de_DE.UTF-8 UTF-8' | $SUDO tee -a /etc/locale.gen >/dev/null
  $SUDO locale-gen >/dev/null
fi
