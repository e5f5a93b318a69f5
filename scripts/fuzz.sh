#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the libFuzzer harnesses (tests/fuzz) with clang under ASan + UBSan into
# ${FUZZ_BUILD:-build-fuzz} (CI passes its sanitizer build, configured with KINSTAB_FUZZ=ON, and
# nothing is rebuilt), cuts seed corpora from the shipped files, replays tests/fuzz/regressions,
# then fuzzes each reader for FUZZ_SECONDS (default 30). Any crash, leak of an exception or
# sanitizer report fails the script; the input that did it is left in $build/artifacts/.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${FUZZ_BUILD:-build-fuzz}"
seconds="${FUZZ_SECONDS:-30}"
readers=(at2 cosmos csmip plaintext project friction_csv hazard)
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ BUILD_DIR="$build" BUILD_TYPE=RelWithDebInfo bash scripts/build.sh \
    -DKINSTAB_FUZZ=ON "$@"
fi
cmake --build "$build" -j"$(nproc)" --target "${readers[@]/#/fuzz_}"

# Seeds: the first 120 lines of each shipped file of the kind the harness reads.
seed() { # seed NAME FILE...
  mkdir -p "$build/corpus/$1"
  local name="$1"; shift
  for f in "$@"; do head -n 120 "$f" > "$build/corpus/$name/$(basename "$f")"; done
}
seed at2 resources/records/*.AT2
seed cosmos resources/records/*.V2c resources/records/*.V1c
seed csmip resources/records/*.V2
seed plaintext resources/records/*.acc resources/records/*.AT2 resources/records/*.V2
seed project resources/examples/*.json
seed friction_csv resources/data/furgerson1980/*.csv
seed hazard resources/examples/hazard-*.csv

export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
mkdir -p "$build/artifacts"
failed=()
for name in "${readers[@]}"; do
  exe="$build/tests/fuzz/fuzz_$name"
  # Inputs that once crashed a reader (tests/fuzz/regressions/NAME/): each must now pass.
  regressions=(tests/fuzz/regressions/"$name"/*)
  if [ -e "${regressions[0]}" ] &&
     ! "$exe" "${regressions[@]}" >"$build/$name-regressions.log" 2>&1; then
    echo "== fuzz_$name: a regression input fails"; grep -E "ERROR|what\(\)| in kinstab::" \
      "$build/$name-regressions.log" | head -n 6
    failed+=("$name (regression)")
  fi
  echo "== fuzz_$name: ${seconds} s"
  if ! "$exe" "$build/corpus/$name" -max_total_time="$seconds" -max_len=16384 \
       -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
       -artifact_prefix="$build/artifacts/$name-" >"$build/$name.log" 2>&1; then
    grep -E "ERROR|what\(\)| in kinstab::|Test unit written" "$build/$name.log" | head -n 8
    failed+=("$name")
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/$name.log" | tr -s ' \n' ' '
  echo
done
if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzzing found crashes in: ${failed[*]} (inputs in $build/artifacts/)"
  exit 1
fi
