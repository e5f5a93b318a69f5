# SPDX-License-Identifier: GPL-3.0-or-later
"""The GIL is released while the engine works, and Ctrl+C cancels a surface."""

import os
import signal
import threading
import time

import pytest

import kinstab

GRID = ("0.6:1.6:0.005", "0.25:4:0.025")  # 201 x 151 points: about a second of work


def test_surface_lets_other_threads_run():
    ticks = 0
    done = threading.Event()

    def sweep():
        kinstab.surface(*GRID, threads=1)
        done.set()

    t = threading.Thread(target=sweep)
    t.start()
    # A pure-Python loop on this thread: it only advances while the sweep does not hold the GIL.
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    t.join()
    # The sweep takes well over 0.1 s (30351 points); with the GIL held we would count ~0.
    assert ticks > 50


def test_ctrl_c_cancels_surface():
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        kinstab.surface("0.6:1.6:0.002", "0.25:4:0.01", threads=1)  # 501 x 376 points: several seconds
    timer.join()
    assert time.monotonic() - start < 10
