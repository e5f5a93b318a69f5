# SPDX-License-Identifier: GPL-3.0-or-later
"""kinstab.rocking, rocking_critical and overturning_map: the free-standing block of
docs/theory.md §10 from Python. The published cases (Makris & Roussos 2000; Zhang & Makris 2001,
as docs/theory.md §10 quotes them), the same numbers as kinstab-cli rocking / rocking-map, NumPy
arrays for the map and the history, and bad keywords as ValueError naming the keyword."""

import math

import numpy as np
import pytest

import kinstab
from conftest import SOURCE_DIR

G = 9.80665
RECORD = SOURCE_DIR / "resources" / "records" / "RSN77_SFERN_PUL164.AT2"


def zhang_makris_block():
    """p = 2.14 rad/s, alpha = 0.25 (Zhang & Makris 2001): R = 3 g / (4 p^2)."""
    r = 3 * G / (4 * 2.14 ** 2)
    return dict(half_width=r * math.sin(0.25), half_height=r * math.cos(0.25))


def test_makris_roussos_half_sine():
    # Makris & Roussos 2000: b 0.2 m, h 0.6 m, half-sine of omega_p = 2 pi, linearised:
    # 5.430 m/s^2 survives, 5.440 m/s^2 overturns.
    block = dict(half_width=0.2, half_height=0.6, linear=True, pulse="half-sine",
                 pulse_frequency=1.0)
    stands = kinstab.rocking(amplitude=5.430 / G, **block)
    falls = kinstab.rocking(amplitude=5.440 / G, **block)
    assert stands.outcome == "rocks" and stands["overturn_time_s"] is None
    assert falls.outcome == "overturns" and falls.overturn_time_s > 0.5
    assert isinstance(stands.impact_times_s, np.ndarray) and stands.impacts > 0


def test_zhang_makris_safe_cape():
    # Zhang & Makris 2001 (eta 0.9, omega_p / p = 5, linearised one-sine): 3.00 alpha g stands,
    # 3.01 overturns, overturning to 6.32, 6.33-7.17 stand, 7.18 overturns; the ends to 1e-3 g
    # as tst_cli_rocking checks them (3.0186, 6.3181 and eq. 47's 7.1681 alpha g).
    r = kinstab.rocking_critical(**zhang_makris_block(), linear=True, restitution=0.9,
                                 pulse="one-sine", pulse_frequency=5 * 2.14 / (2 * math.pi),
                                 max_amplitude=2.5)
    (a0, a1), (b0, b1) = r["overturning_intervals_g"]
    assert abs(r["critical_amplitude_g"] / 0.25 - 3.0186) < 4e-3
    assert abs(a1 / 0.25 - 6.3181) < 4e-3
    assert abs(b0 / 0.25 - 7.1681) < 4e-3
    assert b1 == 2.5


def test_same_as_the_cli(cli):
    args = dict(half_width=0.15, half_height=0.5, mu=0.7, pulse="one-cosine", amplitude=0.4,
                pulse_frequency=0.8)
    py = kinstab.rocking(**args)
    c = cli("rocking", "--half-width", "0.15", "--half-height", "0.5", "--mu", "0.7", "--pulse",
            "one-cosine", "--amplitude", "0.4", "--pulse-frequency", "0.8")
    for key in ("outcome", "max_theta_over_alpha", "overturn_time_s", "sliding_displacement_m",
                "max_sliding_m", "end_time_s", "impacts", "steps", "events"):
        assert py[key] == c[key], key
    assert list(py["impact_times_s"]) == c["impact_times_s"]
    assert py.alpha_rad == c["block"]["alpha_rad"]


def test_record_scaled_and_history():
    record = kinstab.read_record(str(RECORD))
    r = kinstab.rocking(half_width=0.075, half_height=0.45, record=record, amplitude=0.1,
                        history=True, history_step=0.05)
    by_path = kinstab.rocking(half_width=0.075, half_height=0.45, record=RECORD, amplitude=0.1)
    assert r.outcome == by_path.outcome and r.max_theta_over_alpha == by_path.max_theta_over_alpha
    assert r.t_s.shape == r.theta_rad.shape and r.t_s.size > 10
    assert np.all(np.diff(r.t_s) >= 0)
    # West's rule: below b/h g = 0.167 g the block never lifts, so 0.1 g leaves it at rest.
    assert r.outcome == "rest" and r.max_theta_over_alpha == 0


def test_overturning_map_arrays(cli):
    m = kinstab.overturning_map(half_width=0.2, half_height=0.6, linear=True,
                                amplitudes=(1.0, 6.0), frequencies=(1.0, 8.0),
                                amplitude_points=6, frequency_points=5)
    assert m["overturns"].shape == (5, 6) and m["overturns"].dtype == np.uint8
    assert m["max_theta_over_alpha"].shape == (5, 6)
    assert np.allclose(m["amplitudes"], np.linspace(1, 6, 6))
    # Below a_p = alpha g the block does not lift (linearised: a_p / (alpha g) <= 1).
    assert not m["overturns"][:, 0].any() and not m["max_theta_over_alpha"][:, 0].any()
    c = cli("rocking-map", "--half-width", "0.2", "--half-height", "0.6", "--linear",
            "--amplitudes", "1,6", "--frequencies", "1,8", "--amplitude-points", "6",
            "--frequency-points", "5")
    assert m["overturns"].tolist() == c["state"]
    assert np.allclose(m["max_theta_over_alpha"], c["max_theta_over_alpha"], rtol=1e-6)
    assert np.allclose(m["frequencies"], c["omega_p_over_p"])


@pytest.mark.parametrize("kwargs,keyword", [
    (dict(half_width=-1, half_height=0.6, initial_tilt=0.5), "half_width"),
    (dict(half_width=0.2, half_height=0.6, restitution=1.5, initial_tilt=0.5), "restitution"),
    (dict(half_width=0.2, half_height=0.6, pulse="square", amplitude=1, pulse_frequency=1),
     "pulse"),
    (dict(half_width=0.2, half_height=0.6, pulse="half-sine", pulse_frequency=1), "amplitude"),
    (dict(half_width=0.2, half_height=0.6, pulse="rectangular", amplitude=1,
          pulse_frequency=1), "pulse_frequency"),
    (dict(half_width=0.2, half_height=0.6), "pulse"),
    (dict(half_width=0.2, half_height=0.6, initial_tilt=1.2), "initial_tilt"),
])
def test_bad_keywords(kwargs, keyword):
    with pytest.raises(ValueError, match=keyword):
        kinstab.rocking(**kwargs)


def test_bad_search_and_map_keywords():
    with pytest.raises(ValueError, match="scan_points"):
        kinstab.rocking_critical(half_width=0.2, half_height=0.6, pulse="half-sine",
                                 pulse_frequency=1, scan_points=1)
    with pytest.raises(ValueError, match="amplitudes"):
        kinstab.overturning_map(half_width=0.2, half_height=0.6, amplitudes=(3, 1))
    with pytest.raises(ValueError, match="shape"):
        kinstab.overturning_map(half_width=0.2, half_height=0.6, shape="triangle")
    with pytest.raises(TypeError):
        kinstab.rocking(0.2, 0.6)  # keyword-only
