#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The main job: install, build, check the paper's 16-story building (Furgerson 1980 ch. V) and
# write its PDF design report to paper-16-story.pdf.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
cli=build/app/kinstab-cli
project=resources/examples/paper-16-story.json
echo "== gamma_c = tau_max / tau_c, moderate envelope, mu = 0.6, t* = 0.099 s (the paper's grid, Fig. 29)"
"$cli" surface --amplitudes 0.70:1.15:0.05 --frequencies 0.5:1.125:0.125 --envelope moderate --format table
echo "== design check: code ratios against A_crit at f = 1/T"
"$cli" check --project "$project"
"$cli" report --project "$project" -o paper-16-story.pdf
echo "== wrote $(pwd)/paper-16-story.pdf"
