# SPDX-License-Identifier: GPL-3.0-or-later
# Sourced by scripts/test.sh and .ci/run: `phase NAME COMMAND...` runs COMMAND and prints
# "phase NAME: S s" with its wall seconds, so a slow phase shows in every log. A failing
# command still prints its line, then the script stops (set -e in the caller).
phase() {
  local name="$1" start end rc=0
  shift
  start=$(date +%s)
  "$@" || rc=$?
  end=$(date +%s)
  echo "phase ${name}: $((end - start)) s$([ "$rc" -ne 0 ] && echo " (failed, exit $rc)")"
  return "$rc"
}
