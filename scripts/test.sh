#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Install, build, and run every test: offscreen for most, under Xvfb for the few that need OpenGL.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
build="${BUILD_DIR:-build}"
export QTEST_FUNCTION_TIMEOUT=600000
QT_QPA_PLATFORM=offscreen QT_QPA_OFFSCREEN_NO_GLX=1 \
  ctest --test-dir "$build" -LE gl --output-on-failure --timeout 900
QT_QPA_PLATFORM=xcb xvfb-run -a -s "-screen 0 1280x1024x24" \
  ctest --test-dir "$build" -L gl --output-on-failure --timeout 900
