# SPDX-License-Identifier: GPL-3.0-or-later
"""The module computes what kinstab-cli computes, bit for bit.

The CLI prints doubles in nlohmann::json's shortest round-trip form and Python's json parses
them correctly rounded, so a float from the CLI's JSON is the same double the core returned:
every comparison here is ==, never approx."""

import math

import numpy as np
import pytest

import kinstab


def same(python_value, cli_value):
    """Exact equality, with the CLI's null standing for NaN."""
    if cli_value is None:
        return isinstance(python_value, float) and math.isnan(python_value)
    return python_value == cli_value


SIMULATE_CASES = [
    # (python keywords, cli flags): collapse, stable, custom envelope, paper solver, duration
    (dict(), []),
    (dict(envelope="fast", mu=0.5), ["--envelope", "fast", "--mu", "0.5"]),
    (dict(envelope=kinstab.Envelope(0.2, 0.7), tstar=0.12),
     ["--alpha", "0.2", "--beta", "0.7", "--tstar", "0.12"]),
    (dict(solver="paper", paper_steps=32), ["--solver", "paper", "--paper-steps", "32"]),
    (dict(duration=40.0, limit=2.0, scale="tau_rise", wall_width_in=10),
     ["--duration", "40", "--limit", "2", "--scale", "tau_rise", "--wall-width-in", "10"]),
]


@pytest.mark.parametrize("keywords,flags", SIMULATE_CASES)
@pytest.mark.parametrize("amplitude,frequency", [(0.9, 1.0), (0.65, 2.5), (1.1, 0.625)])
def test_simulate_equals_cli(cli, keywords, flags, amplitude, frequency):
    j = cli("simulate", "--amplitude", amplitude, "--frequency", frequency, "--events", *flags)
    r = kinstab.simulate(amplitude, frequency, events=True, **keywords)
    assert r.outcome == j["outcome"]
    for key in ("tau_c", "gamma_c", "tau_end", "max_abs_delta", "residual_delta", "tau_ref"):
        assert same(getattr(r, key), j[key]), key
    assert r.slip_intervals == j["slip_intervals"]
    assert r.work == j["work"]
    ev = r.events
    assert len(ev["tau"]) == len(j["events"])
    for k, e in enumerate(j["events"]):
        assert ev["tau"][k] == e["tau"] and ev["kind"][k] == e["kind"]
        assert ev["delta"][k] == e["delta"] and ev["velocity"][k] == e["velocity"]
        assert ev["direction"][k] == e["direction"]


def test_surface_equals_cli(cli):
    amps, freqs = "0.7:1.15:0.05", "0.5:1.125:0.125"  # the paper's 16-story grid
    j = cli("surface", "--amplitudes", amps, "--frequencies", freqs, "--envelope", "slow")
    s = kinstab.surface(amps, freqs, envelope="slow", threads=2)
    assert s.amplitudes.tolist() == j["amplitudes"]
    assert s.frequencies.tolist() == j["frequencies"]
    assert s.tau_ref == j["tau_ref"]
    for i in range(len(j["amplitudes"])):
        for k in range(len(j["frequencies"])):
            assert same(float(s.tau_c[i, k]), j["tau_c"][i][k])
            assert s.gamma_c[i, k] == j["gamma_c"][i][k]
            assert s.outcome_names()[i, k] == j["outcome"][i][k]


def test_critical_equals_cli(cli):
    freqs = [0.5, 1.0, 2.0, 4.0]
    j = cli("critical", "--frequencies", ",".join(map(str, freqs)), "--mu", "0.5",
            "--scan-step", "0.02")
    a = kinstab.critical(freqs, mu=0.5, scan_step=0.02)
    assert a.dtype == np.float64 and a.shape == (4,)
    for x, y in zip(a.tolist(), j["a_crit"]):
        assert same(x, y)


def test_planar_simulate_equals_cli(cli):
    j = cli("simulate", "--model", "planar", "--fy", "2", "--amplitude", "1.0", "--frequency",
            "1.0", "--ay-ratio", "0.8")
    r = kinstab.simulate(1.0, 1.0, planar=kinstab.Planar(fy=2.0, ay_ratio=0.8))
    assert r.outcome == j["outcome"] and r.exit_side == j["exit_side"]
    for key in ("tau_c", "gamma_c", "tau_end", "max_abs_delta", "max_abs_delta_y"):
        assert same(getattr(r, key), j[key]), key


def test_record_run_equals_cli(cli, source_dir):
    path = source_dir / "resources" / "records" / "RSN68_SFERN_PEL090.AT2"
    j = cli("simulate", "--record", path, "--amplitude", "0.9", "--floor-period", "1.0")
    r = kinstab.simulate_record(str(path), amplitude=0.9, floor_period=1.0)
    assert r["outcome"] == j["outcome"]
    for key in ("tau_c", "gamma_c", "tau_ref", "tau_end", "max_abs_delta", "scale_factor"):
        assert same(r[key], j[key]), key
    assert r["ground"].peak == j["record"]["peak_g"]
    assert len(r["ground"]) == j["record"]["npts"]


def test_codes_equal_cli(cli, source_dir):
    import json
    project_file = source_dir / "resources" / "examples" / "paper-16-story.json"
    j = cli("codes", "--project", project_file)
    project = json.loads(project_file.read_text())
    assert kinstab.codes(project["building"], **project["codes"]) == j


def test_friction_equals_cli(cli, source_dir):
    data = source_dir / "resources" / "data" / "furgerson1980" / "table1_triplet_tests.csv"
    j = cli("friction", "--data", data, "--bearing-area", "65.7")
    assert kinstab.friction.calibrate(str(data), bearing_area=65.7) == j


def test_read_record_and_floor_filter_equal_cli(cli, source_dir):
    path = source_dir / "resources" / "records" / "RSN77_SFERN_PUL164.AT2"
    j = cli("record", "--file", path, "--floor-period", "1", "--damping", "0.02")
    ground = kinstab.read_record(str(path))
    assert len(ground) == j["record"]["npts"] and ground.dt == j["record"]["dt"]
    assert ground.peak == j["record"]["peak_g"]
    assert ground.peak_time == j["record"]["peak_time_s"]
    floor = kinstab.floor_filter(ground, 1.0, damping=0.02)
    assert len(floor) == j["floor"]["npts"]
    assert floor.peak == j["floor"]["peak_g"] and floor.peak_time == j["floor"]["peak_time_s"]


def test_planar_surface_equals_cli(cli):
    j = cli("surface", "--model", "planar", "--fy", "0.5", "--amplitudes", "0.9,1.2",
            "--frequencies", "0.5,1,2")
    s = kinstab.surface([0.9, 1.2], [0.5, 1, 2], planar=kinstab.Planar(fy=0.5))
    names = s.outcome_names()
    for i in range(2):
        for k in range(3):
            assert same(float(s.tau_c[i, k]), j["tau_c"][i][k])
            assert s.gamma_c[i, k] == j["gamma_c"][i][k]
            assert names[i, k] == j["outcome"][i][k]
