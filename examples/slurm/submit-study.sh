#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Submits a kinstab study to Slurm: the shard array, then the merge, which waits for every
# array task to succeed (afterok). Usage: submit-study.sh STUDY.json [OUT_FOLDER]
set -euo pipefail
SPEC=$(realpath "${1:?usage: submit-study.sh STUDY.json [OUT_FOLDER]}")
OUT=$(realpath -m "${2:-results}")
HERE=$(dirname "$(realpath "$0")")
array=$(sbatch --parsable --export=ALL,SPEC="$SPEC",OUT="$OUT" "$HERE/study-array.sbatch")
sbatch --dependency=afterok:"${array%%;*}" --array=0 --job-name=kinstab-merge \
    --export=ALL,SPEC="$SPEC",OUT="$OUT" --output=kinstab-merge-%j.log \
    "$HERE/study-array.sbatch" --merge
