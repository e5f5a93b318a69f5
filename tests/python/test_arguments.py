# SPDX-License-Identifier: GPL-3.0-or-later
"""Issue 31: True or False where a number belongs is a slip, not 1.0 or 0.0 (pybind11 converts a
bool to a double): simulate(True, 1) ran at 1 g. It raises TypeError; ints and floats still pass.
The floor filter's period has the CLI's lower bound (0.01 s): 1e-300 gave NaN samples."""

import numpy as np
import pytest

import kinstab

RECORD = "resources/records/RSN68_SFERN_PEL-UP.AT2"


def test_bool_is_not_a_number():
    for call in (lambda: kinstab.simulate(True, 1),
                 lambda: kinstab.simulate(0.9, True),
                 lambda: kinstab.simulate(0.9, 1.0, history=True, history_step=True),
                 lambda: kinstab.simulate(np.bool_(True), 1.0),
                 lambda: kinstab.simulate(False, 1.0, planar=kinstab.Planar(fy=1))):
        with pytest.raises(TypeError):
            call()


def test_numbers_still_pass():
    assert kinstab.simulate(1, 1).amplitude == 1.0  # ints convert as before
    assert kinstab.simulate(np.float64(0.9), np.int64(1)).frequency == 1.0


def test_floor_filter_refuses_what_the_cli_refuses(cli, source_dir):
    rec = kinstab.read_record(str(source_dir / RECORD))
    code, stderr = cli("record", "--file", source_dir / RECORD, "--floor-period", "1e-300",
                       expect_ok=False)
    assert code == 2, stderr
    with pytest.raises(ValueError) as e:
        kinstab.floor_filter(rec, 1e-300)
    assert str(e.value) == "period=1e-300: " + stderr.split("--floor-period 1e-300: ", 1)[1]
    with pytest.raises(TypeError):
        kinstab.floor_filter(rec, True)
    with pytest.raises(TypeError):
        kinstab.simulate_record(str(source_dir / RECORD), amplitude=True)
    floor = kinstab.floor_filter(rec, 0.01)  # the least period: a rigid oscillator, finite
    assert np.isfinite(floor.samples).all() and abs(floor.peak) > 0
