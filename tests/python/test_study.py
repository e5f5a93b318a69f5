# SPDX-License-Identifier: GPL-3.0-or-later
"""kinstab.study.run on a Dask LocalCluster of two worker processes gives the same JSONL bytes
as kinstab-cli study (docs/studies.md, "Dask"), also for a study with record scales, building
levels and fitted-sine motions; a bad study file raises ValueError naming the field before any
task runs."""

import json
import subprocess

import pytest

from conftest import CLI, SOURCE_DIR

SPEC = SOURCE_DIR / "tests" / "data" / "study" / "small-study.json"


def test_dask_rows_equal_the_cli_rows():
    distributed = pytest.importorskip("distributed")
    import kinstab.study

    cli = subprocess.run([str(CLI), "study", "--spec", str(SPEC), "--threads", "1"],
                         capture_output=True, timeout=600, check=True).stdout.decode()
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        text = kinstab.study.run(str(SPEC), client, batch=5)  # batches cross parameter sets
    assert text == cli
    assert kinstab.study.case_count(str(SPEC)) == 12


def test_dask_rows_with_scale_levels_and_motions(tmp_path):
    distributed = pytest.importorskip("distributed")
    import kinstab.study

    records = SOURCE_DIR / "resources" / "records"
    spec = tmp_path / "levels.json"
    spec.write_text(json.dumps({
        "format": "kinstab-study", "version": 1,
        "records": [{"path": str(records / "RSN6_IMPVALL.I_I-ELC180.AT2"), "scale": 2},
                    {"path": str(records / "RSN68_SFERN_PEL090.AT2")}],
        "building": {"stories": 3, "height": 36, "plan_dimension": 60, "period_s": 0.4},
        "floors": {"damping": 0.05},
        "parameters": {"mu": [0.5], "levels": [1, 3], "motion": ["record", "fitted_sine"]},
        "search": {"max_g": 2, "scan_step_g": 0.05, "tolerance_g": 1e-3}}))
    cli = subprocess.run([str(CLI), "study", "--spec", str(spec), "--threads", "1"],
                         capture_output=True, timeout=600, check=True).stdout.decode()
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        text = kinstab.study.run(str(spec), client, batch=3)
    assert text == cli
    rows = [json.loads(line) for line in text.splitlines()]
    assert len(rows) == 8  # 2 levels x 2 motions x 2 records
    assert [r["level"] for r in rows[::2]] == [1, 1, 3, 3]
    assert rows[0]["scale"] == 2.0 and rows[0]["im_as_given_g"] == 2 * rows[0]["record_im_g"]


def test_bad_study_names_the_field(tmp_path):
    import kinstab.study

    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "kinstab-study", "version": 1, "records": []}')
    with pytest.raises(ValueError, match="records: expected a non-empty array"):
        kinstab.study.case_count(str(bad))
    with pytest.raises(ValueError, match="batch=0"):
        kinstab.study.run(str(SPEC), client=None, batch=0)
