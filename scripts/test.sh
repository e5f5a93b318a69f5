#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Install, build, and run every test: offscreen for most, under Xvfb for the few that need OpenGL.
# Each phase prints its wall seconds (scripts/phase.sh). Every test has its own CTest TIMEOUT
# (tests/CMakeLists.txt); the slow ones carry the label "slow".
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/phase.sh
build="${BUILD_DIR:-build}"
phase install bash scripts/install-deps.sh
phase build bash scripts/build.sh
export QTEST_FUNCTION_TIMEOUT=600000
phase test-offscreen env QT_QPA_PLATFORM=offscreen QT_QPA_OFFSCREEN_NO_GLX=1 \
  ctest --test-dir "$build" -LE gl --output-on-failure -j"$(nproc)"
phase test-gl env QT_QPA_PLATFORM=xcb xvfb-run -a -s "-screen 0 1280x1024x24" \
  ctest --test-dir "$build" -L gl --output-on-failure
