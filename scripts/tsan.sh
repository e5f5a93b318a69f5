#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# ThreadSanitizer run of the threaded sweep: runSweep's worker threads, its progress counter and
# its cancel (core/sweep/Sweep.cpp; tst_sweep). Builds only that test into build-tsan; any data
# race fails. The GUI's sweep worker (ui/SweepRunner.cpp) is not run here: it hands its job to
# Qt's thread pool, and Debian's Qt is not built with TSan, so that hand-off is invisible and
# every access after it is reported as a race (tests/tsan.supp says more).
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-tsan
export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}" # as build.sh
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
generator=()
[ ! -f "$build/CMakeCache.txt" ] && command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S . -B "$build" "${generator[@]}" "${launcher[@]}" -DKINSTAB_TSAN=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKINSTAB_PYTHON=OFF "$@" >/dev/null
cmake --build "$build" -j"$(nproc)" --target tst_sweep tst_study_runner
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$PWD/tests/tsan.supp"
QT_QPA_PLATFORM=offscreen "$build/tests/tst_sweep"
# The study runner's worker threads, its blocks of rows and its cancel (core/study/StudyRunner.cpp).
QT_QPA_PLATFORM=offscreen "$build/tests/tst_study_runner"
