#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes synthetic study results for timing `kinstab-cli fragility`: SETS parameter sets of
RECORDS records each, critical intensities drawn from a lognormal (median 0.8 g, beta 0.4,
seeded), censored above LIMIT g. The rows have the keys kinstab-cli study writes, with a made-up
study fingerprint.

    scripts/fragility-rows.py 100 1000 > /tmp/rows.jsonl          # 10^5 rows
    time build/app/kinstab-cli fragility --results /tmp/rows.jsonl -o /dev/null
"""

import json
import math
import random
import sys


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: fragility-rows.py SETS RECORDS [LIMIT_G]")
    sets, records = int(sys.argv[1]), int(sys.argv[2])
    limit = float(sys.argv[3]) if len(sys.argv) == 4 else 3.0
    rng = random.Random(42)
    cases = sets * records
    for s in range(sets):
        for r in range(records):
            crit = math.exp(math.log(0.8) + 0.4 * rng.gauss(0, 1))
            collapsed = crit < limit
            row = {"study": "0123456789abcdef", "case": s * records + r, "cases": cases,
                   "set": s, "record": f"rec{r}.AT2",
                   "mu": round(0.3 + 0.01 * s, 6), "tstar": 0.1, "limit": 1.0,
                   "floor_period_s": None, "floor_damping": None, "measure": "pga",
                   "record_im_g": 0.1 + 0.4 * rng.random(),
                   "critical_im_g": crit if collapsed else None,
                   "critical_peak_g": 1.3 * crit if collapsed else None,
                   "limit_im_g": limit, "runs": 100}
            sys.stdout.write(json.dumps(row, separators=(",", ":")) + "\n")


if __name__ == "__main__":
    main()
