#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Starts the desktop application N times, each under its own Xvfb (xvfb-run -a), and counts how
# the starts end: exit 0, another exit code, or a signal (SIGABRT, SIGSEGV, ...). Each start opens
# the paper's project, runs its sweep, saves a screenshot and quits (--screenshot), so it covers
# start-up, a worker thread and shut-down. Issue 31 saw one SIGABRT within 44 ms in 27 starts.
#
#   scripts/gui-starts.sh [-n N] [-j JOBS] [-g] [-- APP ARGUMENTS]
#     -n N     starts (default 100)
#     -j JOBS  starts at once, each with its own server (default 1); xvfb-run -a picks a free
#              display number, so several at once also try its choice under contention
#     -g       run each start under gdb: a backtrace of every thread when a signal stops it
#
# Prints one line per start that did not exit 0 (its log kept in the log folder) and a summary;
# exits 1 when any start did not exit 0. Exit 3 is kinstab's "no display could be opened" (it was
# Qt's SIGABRT before issue 31). BUILD_DIR as for scripts/build.sh.
set -uo pipefail
cd "$(dirname "$0")/.."
build="${BUILD_DIR:-build}"
n=100 jobs=1 gdb=0
while getopts "n:j:g" opt; do
  case "$opt" in
    n) n="$OPTARG" ;;
    j) jobs="$OPTARG" ;;
    g) gdb=1 ;;
    *) exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ "${1:-}" = "--" ] && shift
app="$build/app/kinstab"
[ -x "$app" ] || { echo "gui-starts: $app not built" >&2; exit 2; }
logs="$(mktemp -d /tmp/kinstab-gui-starts.XXXXXX)"
args=("$@")
[ ${#args[@]} -eq 0 ] && args=(resources/examples/paper-16-story.json)

# One start: its exit status in $logs/I.status, its output in $logs/I.log.
start() {
  local i="$1" shot="$logs/$1.png" status
  local cmd=("$app" --screenshot "$shot" "${args[@]}")
  if [ "$gdb" = 1 ]; then
    cmd=(gdb -q -batch -return-child-result -ex "set pagination off" -ex run
         -ex "thread apply all bt" --args "${cmd[@]}")
  fi
  # Settings of a start must not leak into the next (the window restores its state).
  # Our own X authority file: with its own temporary folder xvfb-run may fail to remove it when
  # the program exits at once, and then exits 5 leaving its Xvfb running.
  XDG_CONFIG_HOME="$logs/config-$i" QT_QPA_PLATFORM=xcb timeout -k 10 300 \
    xvfb-run -a -f "$logs/auth-$i" -s "-screen 0 1280x1024x24" "${cmd[@]}" >"$logs/$i.log" 2>&1
  status=$?
  # Under gdb the signal stops the program, and gdb's own exit says nothing of it.
  if [ "$gdb" = 1 ] && grep -q "received signal" "$logs/$i.log"; then
    status=$((128 + $(kill -l "$(grep -o 'received signal SIG[A-Z]*' "$logs/$i.log" |
                                    head -1 | sed 's/.*SIG//')")))
  fi
  echo "$status" >"$logs/$i.status"
  rm -f "$shot"
  rm -rf "$logs/config-$i" "$logs/auth-$i"
}

running=0
for i in $(seq 1 "$n"); do
  start "$i" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n
    running=$((running - 1))
  fi
done
wait

ok=0 failed=0 signalled=0
for i in $(seq 1 "$n"); do
  s="$(cat "$logs/$i.status")"
  if [ "$s" = 0 ]; then
    ok=$((ok + 1))
    rm -f "$logs/$i.log"
    continue
  fi
  if [ "$s" -gt 128 ] && [ "$s" -lt 160 ]; then
    signalled=$((signalled + 1))
    echo "start $i: signal $(kill -l $((s - 128))) (log $logs/$i.log)"
  else
    failed=$((failed + 1))
    echo "start $i: exit $s (log $logs/$i.log)"
  fi
done
echo "gui-starts: $n starts, $ok exit 0, $failed other exit codes, $signalled signals (logs: $logs)"
[ "$ok" = "$n" ]
