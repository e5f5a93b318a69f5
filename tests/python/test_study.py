# SPDX-License-Identifier: GPL-3.0-or-later
"""kinstab.study.run on a Dask LocalCluster of two worker processes gives the same JSONL bytes
as kinstab-cli study (docs/studies.md, "Dask"); a bad study file raises ValueError naming the
field before any task runs."""

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


def test_bad_study_names_the_field(tmp_path):
    import kinstab.study

    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "kinstab-study", "version": 1, "records": []}')
    with pytest.raises(ValueError, match="records: expected a non-empty array"):
        kinstab.study.case_count(str(bad))
    with pytest.raises(ValueError, match="batch=0"):
        kinstab.study.run(str(SPEC), client=None, batch=0)
