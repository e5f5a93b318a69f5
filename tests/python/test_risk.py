# SPDX-License-Identifier: GPL-3.0-or-later
"""kinstab.risk returns the same dictionary as `kinstab-cli risk` (one computation, every front
end) for a given fragility, the risk-targeted median and a study's sets; kinstab.read_hazard
reads the curve the CLI integrates (an OpenQuake PoE in 50 years back as -ln(1 - PoE)/50); a bad
argument or file raises ValueError naming the keyword, or the file and line."""

import json
import math

import numpy as np
import pytest

import kinstab
from conftest import SOURCE_DIR

HAZARD = SOURCE_DIR / "resources" / "examples" / "hazard-second-order.csv"


def rows(measure="pga"):
    """Two sets of 6 records at lognormal quantiles (medians 0.9 and 1.4 g, beta 0.35)."""
    z = [-1.383, -0.674, -0.210, 0.210, 0.674, 1.383]
    lines = []
    for i in range(12):
        critical = (0.9 if i < 6 else 1.4) * math.exp(0.35 * z[i % 6])
        lines.append(json.dumps({
            "study": "0123456789abcdef", "case": i, "cases": 12, "set": i // 6, "record": f"r{i}", "mu": 0.6, "tstar": 0.099,
            "limit": 1, "floor_period_s": None, "floor_damping": None, "measure": measure,
            "record_im_g": 0.3, "critical_im_g": critical, "critical_peak_g": critical,
            "limit_im_g": 3.0, "runs": 10}))
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("python_args,cli_args", [
    (dict(median=1.2, beta=0.4, measure="pga", im=0.6),
     ["--median", "1.2", "--beta", "0.4", "--measure", "pga", "--im", "0.6"]),
    (dict(beta=0.6, target_rate=1e-4), ["--beta", "0.6", "--target-rate", "1e-4"]),
    (dict(median=0.8, beta=0.5, years=100), ["--median", "0.8", "--beta", "0.5", "--years", "100"]),
], ids=["median-beta", "risk-targeted", "100-years"])
def test_risk_equals_the_cli(cli, python_args, cli_args):
    assert kinstab.risk(HAZARD, **python_args) == cli("risk", "--hazard", HAZARD, *cli_args)


def test_study_sets_equal_the_cli(cli, tmp_path):
    results = tmp_path / "study.jsonl"
    results.write_text(rows())
    every = kinstab.risk(HAZARD, results=results, bootstrap=100)
    assert every == cli("risk", "--hazard", HAZARD, "--results", results, "--bootstrap", "100")
    assert [s["set"] for s in every["sets"]] == [0, 1]
    one = kinstab.risk(HAZARD, results=results, set=1, bootstrap=100, seed=7)
    assert one == cli("risk", "--hazard", HAZARD, "--results", results, "--set", "1",
                      "--bootstrap", "100", "--seed", "7")
    b = one["bootstrap"]["lambda_c"]
    assert b["p5"] <= b["p50"] <= b["p95"]


def test_read_hazard_openquake(tmp_path):
    # The example curve written as OpenQuake would: PoE in 50 years, the banner and a site row.
    curve = kinstab.read_hazard(HAZARD)
    assert curve["intensity_measure"] == "PGA" and curve["format"] == "csv"
    poe = -np.expm1(-50 * curve["annual_rate"])
    text = ("#,,,,\"kind='mean', investigation_time=50.0, imt='PGA'\"\nlon,lat,depth,"
            + ",".join(f"poe-{x!r}" for x in curve["im_g"]) + "\n"
            + "-117.0,34.0,0.0," + ",".join(repr(p) for p in poe) + "\n")
    oq = tmp_path / "hazard_curve-mean-PGA_1.csv"
    oq.write_text(text)
    read = kinstab.read_hazard(oq, site=(-117.0, 34.0), measure="pga")
    assert read["format"] == "openquake"
    np.testing.assert_array_equal(read["im_g"], curve["im_g"])
    np.testing.assert_allclose(read["annual_rate"], curve["annual_rate"], rtol=1e-14)


def test_errors_name_the_keyword_or_the_file(tmp_path):
    with pytest.raises(ValueError, match=r"^median=-1\.0: must be > 0 and at most 1000 g$"):
        kinstab.risk(HAZARD, median=-1, beta=0.4)
    with pytest.raises(ValueError, match=r"^median=1\.0: needs beta$"):
        kinstab.risk(HAZARD, median=1)
    with pytest.raises(ValueError, match=r"^hazard_format='xml' must be one of"):
        kinstab.risk(HAZARD, beta=0.4, hazard_format="xml")
    bad = tmp_path / "bad.csv"
    bad.write_text("im_g,annual_rate\n0.1,0.01\n0.2,0.02\n")
    with pytest.raises(ValueError, match=r"^hazard: .*bad\.csv:3: annual rate 0\.02 increases"):
        kinstab.risk(bad, beta=0.4)
    with pytest.raises(ValueError, match=r"^path: .*bad\.csv:3: annual rate 0\.02 increases"):
        kinstab.read_hazard(bad)
    results = tmp_path / "sa.jsonl"
    results.write_text(rows(measure="sa(1s/5%)"))
    with pytest.raises(ValueError, match=r"intensity measure PGA is not the fragility's SA\(1 s\)"):
        kinstab.risk(HAZARD, results=results)
