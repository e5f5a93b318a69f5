#!/usr/bin/env bash
# Debian 12 packages kinstab needs to build, test and write reports (SPEC §1).
set -euo pipefail
packages=(cmake g++ make qt6-base-dev qt6-charts-dev qt6-datavisualization-dev qt6-declarative-dev
          qt6-svg-dev libqt6opengl6-dev libeigen3-dev nlohmann-json3-dev xvfb xauth libgl1-mesa-dri
          fonts-dejavu-core poppler-utils
          clang libclang-rt-14-dev) # clang + libFuzzer runtime: scripts/fuzz.sh
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
