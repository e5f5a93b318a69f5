#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Benchmark: what one `kinstab.simulate` call from Python costs beyond the core's own time.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/bench_overhead.py [--repeats N]

For each case, three medians per call:
  core     runSlab1D timed call by call in a C++ loop (kinstab._core._core_seconds)
  _core    kinstab._core.simulate(case, A, f): the binding with a prepared case
  simulate kinstab.simulate(A, f, **keywords): the public call, which also checks the keywords
           and builds the case every time
Overhead = Python median - core median. A benchmark, not a test: it prints, it does not assert.
"""

import argparse
import statistics
import time

import kinstab
from kinstab import _core

CASES = [  # (label, amplitude g, frequency Hz, keywords)
    ("below mu: no slip", 0.5, 1.0, {}),
    ("slips, stays", 0.9, 1.0, {}),
    ("collapses", 1.1, 0.625, {}),
    ("slips long, fast env.", 0.7, 3.0, {"envelope": "fast"}),
]


def median_seconds(call, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        call()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=2000)
    repeats = parser.parse_args().repeats
    print(f"kinstab {kinstab.__version__}; medians of {repeats} calls, microseconds")
    print(f"{'case':24} {'core':>9} {'_core':>9} {'simulate':>9} {'overhead':>9} {'+keywords':>9}")
    for label, a, f, kw in CASES:
        case = kinstab.SlabCase(**kw)
        r = kinstab.simulate(a, f, **kw)
        core = statistics.median(_core._core_seconds(case, a, f, repeats))
        bound = median_seconds(lambda: _core.simulate(case, a, f), repeats)
        public = median_seconds(lambda: kinstab.simulate(a, f, **kw), repeats)
        print(f"{label:24} {core * 1e6:9.2f} {bound * 1e6:9.2f} {public * 1e6:9.2f} "
              f"{(bound - core) * 1e6:9.2f} {(public - core) * 1e6:9.2f}   ({r.outcome}, {r.slip_intervals} slips)")


if __name__ == "__main__":
    main()
