# SPDX-License-Identifier: GPL-3.0-or-later
"""kinstab.Project (issue 35): load, check, floors, study and report, each the same computation
as kinstab-cli's command for the project, with DataFrames when pandas is installed; and the
record metadata of read_record against kinstab-cli record."""

import json
import math

import pytest

import kinstab
from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "resources" / "examples"
ELCENTRO = SOURCE_DIR / "resources" / "records" / "RSN6_IMPVALL.I_I-ELC180.AT2"


def test_load_and_check_equal_the_cli(cli):
    p = kinstab.Project.load(EXAMPLES / "paper-16-story.json")
    assert p.name == json.loads((EXAMPLES / "paper-16-story.json").read_text())["name"]
    a = p.check()
    assert a == cli("check", "--project", EXAMPLES / "paper-16-story.json")["assessment"]
    assert p.assess() == a
    assert a.governing["id"] in [c["id"] for c in a["checks"]]


def test_load_names_the_bad_field(tmp_path):
    project = json.loads((EXAMPLES / "paper-16-story.json").read_text())
    project["slab"]["mu"] = -1
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(project))
    with pytest.raises(ValueError, match=r"slab\.mu"):
        kinstab.Project.load(path)


def test_floors_equal_the_cli(cli):
    path = EXAMPLES / "paper-16-story-floors.json"
    floors = kinstab.Project.load(path).floors()
    expected = cli("floors", "--project", path)
    for key in ("levels", "checks", "project"):
        assert floors[key] == expected[key], key
    assert floors["record"]["name"] == expected["record"]["name"]


def test_floors_without_a_record_says_so():
    with pytest.raises(ValueError, match="no excitation.record"):
        kinstab.Project.load(EXAMPLES / "paper-16-story.json").floors()


def test_study_from_results_equals_the_cli_fragility(cli):
    # The risk example names its results file: read back and fitted, not run.
    p = kinstab.Project.load(EXAMPLES / "paper-16-story-risk.json")
    s = p.study(bootstrap=50, seed=3)
    expected = cli("fragility", "--results", EXAMPLES / "study-example.jsonl", "--bootstrap",
                   "50", "--seed", "3")
    assert s["fragility"]["sets"] == expected["sets"]
    assert len(s["rows"]) == sum(st["records"] for st in s["fragility"]["sets"])
    stats = s["fragility"]["sets"][0]["record_statistics"]
    collapsed = [r["critical_im_g"] for r in s["rows"]
                 if r["set"] == 0 and r.get("critical_im_g") is not None]
    assert stats["collapsed"] == len(collapsed)
    assert stats["critical_im_mean_g"] == pytest.approx(sum(collapsed) / len(collapsed))


def test_study_without_results_runs_it():
    p = kinstab.Project.load(EXAMPLES / "paper-16-story-study.json")
    s = p.study(bootstrap=0, threads=2)
    read = kinstab.Project.load(EXAMPLES / "paper-16-story-risk.json").study(bootstrap=0)
    assert s["rows"] == read["rows"]  # the shipped results are this study's, bit for bit


def test_study_refuses_bad_arguments():
    p = kinstab.Project.load(EXAMPLES / "paper-16-story-risk.json")
    with pytest.raises(ValueError, match=r"^Project.study\(\): bootstrap=-1"):
        p.study(bootstrap=-1)
    with pytest.raises(TypeError, match=r"^Project.study\(\): bootstrap=1.5 is not a whole"):
        p.study(bootstrap=1.5)
    with pytest.raises(ValueError, match="has no study"):
        kinstab.Project.load(EXAMPLES / "paper-16-story.json").study()


def test_report_writes_the_pdf(tmp_path):
    out = tmp_path / "report.pdf"
    r = kinstab.Project.load(EXAMPLES / "paper-16-story.json").report(out, figure_grid=9)
    assert r["pages"] >= 5 and r["output"] == str(out)
    assert out.read_bytes().startswith(b"%PDF")
    with pytest.raises(ValueError, match=r"^page='a3' must be one of a4\|letter$"):
        kinstab.Project.load(EXAMPLES / "paper-16-story.json").report(tmp_path / "x.pdf",
                                                                      page="a3")


def test_record_metrics_equal_the_cli(cli):
    m = kinstab.read_record(ELCENTRO).metrics(sa_period=1.0)
    expected = cli("record", "--file", ELCENTRO, "--sa-period", "1")["metrics"]
    assert m["sa_period_s"] == 1.0
    for key, value in m.items():
        assert expected[key] == value, key
    # The independent NumPy figures of tests/core/tst_record_metrics.cpp.
    assert m["pgv_m_s"] == pytest.approx(0.309286895, rel=1e-8)
    assert m["arias_m_s"] == pytest.approx(1.541858564, rel=1e-8)
    assert m["sa_g"] == pytest.approx(0.4728542132, rel=1e-7)
    assert kinstab.read_record(ELCENTRO).metrics()["sa_g"] is None
    with pytest.raises(ValueError, match=r"^sa_period=0.0"):
        kinstab.read_record(ELCENTRO).metrics(sa_period=0.0)


def test_dataframes():
    pd = pytest.importorskip("pandas")
    a = kinstab.Project.load(EXAMPLES / "paper-16-story.json").check()
    df = a.to_dataframe()
    assert isinstance(df, pd.DataFrame) and len(df) == len(a["checks"])
    assert list(df["id"]) == [c["id"] for c in a["checks"]]
    s = kinstab.Project.load(EXAMPLES / "paper-16-story-risk.json").study(bootstrap=0)
    assert len(s.to_dataframe()) == len(s["rows"])
    sets = s.sets_dataframe()
    assert len(sets) == len(s["fragility"]["sets"])
    assert "critical_im_median_g" in sets.columns and "censored" in sets.columns
    surf = kinstab.surface([0.5, 1.2], [1.0, 2.0, 3.0])
    sdf = surf.to_dataframe()
    assert len(sdf) == 6 and set(sdf["outcome"]) <= set(kinstab.OUTCOMES)
    assert sdf["amplitude_g"].tolist() == [0.5, 0.5, 0.5, 1.2, 1.2, 1.2]
    records = pd.DataFrame(kinstab.record_table([ELCENTRO], sa_period=1.0))
    assert records.loc[0, "pga_g"] == pytest.approx(0.2807955)
    assert not math.isnan(records.loc[0, "mean_period_s"])
