#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Configure and build kinstab into ${BUILD_DIR:-build} (extra CMake arguments pass through).
# Ninja and ccache when installed (scripts/install-deps.sh installs both): ccache's cache lives
# in $HOME/.cache/ccache, so a developer's builds warm CI's on the same machine.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${BUILD_DIR:-build}"
args=(-DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" -DKINSTAB_WERROR=ON)
if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja >/dev/null; then
  args+=(-G Ninja)
fi
if command -v ccache >/dev/null; then
  args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Precompiled headers are cached only with these (ccache's manual, "Precompiled headers").
  export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}"
  # Paths under the checkout count relative to it, and the compile folder does not count, so a
  # clone in another folder (CI's) hits what this one compiled. The tests' compiled-in paths
  # (KINSTAB_SOURCE_DIR, KINSTAB_CLI) still differ from folder to folder.
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
fi
cmake -S . -B "$build" "${args[@]}" "$@" >/dev/null
cmake --build "$build" -j"$(nproc)"
