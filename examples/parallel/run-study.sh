#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A kinstab study on one machine (or several, with parallel's --sshlogin) with GNU parallel:
# JOBS shards, one single-threaded kinstab-cli each, then the merge (docs/studies.md).
# Usage: run-study.sh STUDY.json OUT.jsonl [JOBS]   (JOBS: the CPUs this process may use)
set -euo pipefail
SPEC=${1:?usage: run-study.sh STUDY.json OUT.jsonl [JOBS]}
OUT=${2:?usage: run-study.sh STUDY.json OUT.jsonl [JOBS]}
JOBS=${3:-$(nproc)}
CLI=${KINSTAB_CLI:-kinstab-cli}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# -q quotes the command, so paths with spaces survive; --halt stops at the first failed shard.
seq 1 "$JOBS" | parallel -q --halt now,fail=1 -j "$JOBS" \
    "$CLI" study --spec "$SPEC" --threads 1 --shard "{}/$JOBS" -o "$work/shard-{}.jsonl"
"$CLI" merge "$work"/shard-*.jsonl -o "$OUT"
