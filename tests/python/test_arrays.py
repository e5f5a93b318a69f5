# SPDX-License-Identifier: GPL-3.0-or-later
"""NumPy shapes and dtypes of what the module returns."""

import numpy as np

import kinstab


def test_surface_arrays():
    s = kinstab.surface([0.7, 0.9, 1.1], [0.5, 1.0], threads=2)
    for name in ("tau_c", "gamma_c"):
        a = getattr(s, name)
        assert a.shape == (3, 2) and a.dtype == np.float64
    assert s.outcome.shape == (3, 2) and s.outcome.dtype == np.int8
    assert s.amplitudes.dtype == np.float64 and s.amplitudes.shape == (3,)
    assert s.frequencies.shape == (2,)
    assert s.exit_side is None
    collapsed = s.outcome == kinstab.OUTCOMES.index("collapsed")
    # tau_c is NaN exactly where the slab did not collapse; gamma_c is 0 there.
    assert np.array_equal(np.isnan(s.tau_c), ~collapsed)
    assert np.all(s.gamma_c[~collapsed] == 0.0)
    assert np.allclose(s.gamma_c[collapsed], s.tau_ref / s.tau_c[collapsed], rtol=0, atol=0)


def test_planar_surface_has_exit_sides():
    s = kinstab.surface([1.2], [1.0, 2.0], planar=kinstab.Planar(fy=1.0))
    assert s.exit_side.shape == (1, 2) and s.exit_side.dtype == np.int8


def test_history_and_events_arrays():
    r = kinstab.simulate(0.9, 1.0, events=True, history=True, history_step=0.1)
    h = r.history
    assert set(h) == {"tau", "accel", "delta", "velocity", "state"}
    n = len(h["tau"])
    assert n > 10
    for key in ("tau", "accel", "delta", "velocity"):
        assert h[key].dtype == np.float64 and h[key].shape == (n,)
    assert h["state"].dtype == np.int8
    assert np.all(np.diff(h["tau"]) >= 0)
    e = r.events
    assert e["tau"].dtype == np.float64 and e["direction"].dtype == np.int8
    assert len(e["kind"]) == len(e["tau"]) == len(e["delta"])
    plain = kinstab.simulate(0.9, 1.0)
    assert plain.events is None and plain.history is None


def test_record_arrays(source_dir):
    rec = kinstab.read_record(str(source_dir / "resources" / "records" / "RSN68_SFERN_PEL090.AT2"))
    assert rec.samples.dtype == np.float64 and rec.samples.shape == (len(rec),)
    assert rec.time.shape == rec.samples.shape and rec.time[1] == rec.dt
    assert abs(rec.peak) == np.max(np.abs(rec.samples))
    floor = kinstab.floor_filter(rec, 1.0, damping=0.05)
    assert floor.dt == rec.dt and len(floor) > len(rec)  # plus the free-vibration tail


def test_critical_array_nan_where_none():
    a = kinstab.critical([1.0], max_amplitude=0.3, scan_step=0.01)  # below mu = 0.6: no slip
    assert a.shape == (1,) and np.isnan(a[0])
