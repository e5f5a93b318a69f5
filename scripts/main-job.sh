#!/usr/bin/env bash
# The main job: install, build, and check the paper's 16-story building (Furgerson 1980 ch. V).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
cli=build/app/kinstab-cli
echo "== gamma_c = tau_max / tau_c, moderate envelope, mu = 0.6, t* = 0.099 s (Furgerson 1980, Fig. 29 grid)"
"$cli" surface --amplitudes 0.70:1.15:0.05 --frequencies 0.5:1.125:0.125 --envelope moderate --format table
echo "== critical amplitude at the building's frequency f = 1/T = 1.0 Hz"
"$cli" critical --frequencies 1.0
