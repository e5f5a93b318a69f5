#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Lists the production functions longer than a screen (default 50 lines), longest first, and
# the count and mean length of all of them. Exit 1 when one is longer. Needs universal-ctags (apt).
# Usage: scripts/long-functions.sh [MAX_LINES]
set -euo pipefail
max=${1:-50}
cd "$(dirname "$0")/.."
ctags -R --c++-kinds=f --fields=+ne --output-format=u-ctags -f - core ui report app python/src |
    awk -F'\t' -v max="$max" '
        { n = ""; e = ""
          for (i = 4; i <= NF; i++) {
              if ($i ~ /^line:/) n = substr($i, 6)
              if ($i ~ /^end:/) e = substr($i, 5)
          }
          if (n == "" || e == "") next
          len = e - n + 1; count++; sum += len
          if (len > max) { long++; printf "%d %s %s\n", len, $2, $1 | "sort -rn" } }
        END { close("sort -rn")
              printf "%d functions, mean %.1f lines, %d over %d\n", count, sum / count, long, max
              exit long > 0 }'
