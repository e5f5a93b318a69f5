#!/usr/bin/env bash
# ThreadSanitizer run of the threaded code: the sweep and its cancel (core, tst_sweep) and the
# GUI's sweep worker (SweepRunner: QtConcurrent + std::thread, tst_mainwindow's sweep, cancel
# and responsiveness cases). Builds only those two tests into build-tsan. Any data race fails.
# Qt itself is not built with TSan, so races reported inside Qt's own frames are suppressed
# (tests/tsan.supp); a race with one of our frames on each side is reported.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-tsan
cmake -S . -B "$build" -DKINSTAB_TSAN=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
cmake --build "$build" -j"$(nproc)" --target tst_sweep tst_mainwindow
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$PWD/tests/tsan.supp"
export QT_QPA_PLATFORM=offscreen QT_QPA_OFFSCREEN_NO_GLX=1
"$build/tests/tst_sweep"
"$build/tests/tst_mainwindow" completedSweepMatchesRunSweep cancelKeepsPartialResults \
  uiStaysResponsiveDuringSweep pickingShowsHistory
