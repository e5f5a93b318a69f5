# SPDX-License-Identifier: GPL-3.0-or-later
"""No memory grows over 10^4 calls (resident set size, after a warm-up)."""

import kinstab


def rss_kib():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS")


def test_no_leak_over_ten_thousand_calls():
    case = kinstab.SlabCase(envelope="fast")
    for _ in range(1000):
        kinstab.simulate(0.9, 1.0, case=case, events=True, history=True, history_step=1.0)
    before = rss_kib()
    for _ in range(10_000):
        r = kinstab.simulate(0.9, 1.0, case=case, events=True, history=True, history_step=1.0)
        r.events, r.history, r.work  # build the arrays and dicts every time
    grown = rss_kib() - before
    # A call builds ~600 history samples and ~170 events (~25 KiB of arrays); leaking them
    # would grow the RSS by ~250 MiB, and leaking as little as 100 bytes a call reaches the bound
    # (measured here: 24 KiB, the allocator's own slack).
    assert grown < 1024, f"RSS grew by {grown} KiB"
