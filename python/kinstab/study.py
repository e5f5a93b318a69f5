# SPDX-License-Identifier: GPL-3.0-or-later
"""Studies on a Dask cluster (docs/studies.md, "Dask").

A study file crosses a suite of records with lists of slab and floor parameters; each case is the
intensity at which the scaled record first collapses the slab. :func:`run` maps the cases over a
``dask.distributed`` client in batches and returns the same JSONL text ``kinstab-cli study``
writes, byte for byte::

    from dask.distributed import Client
    import kinstab.study
    with Client("tcp://scheduler:8786") as client:
        text = kinstab.study.run("study.json", client)

The study file and its records must be readable at the same path on every worker (a shared
filesystem), and every worker needs the kinstab package.
"""

from __future__ import annotations

import os
from typing import Any, List

from . import _core


def case_count(spec: str) -> int:
    """Number of cases of the study file."""
    return _core.study_case_count(os.path.abspath(spec))


def _run_batch(spec: str, cases: List[int]) -> List[str]:
    from kinstab import _core as core  # imported on the worker

    return core.study_rows(spec, cases)


def run(spec: str, client: Any, batch: int = 8) -> str:
    """Run every case of the study file on the client's workers; return the JSONL text.

    ``batch`` cases go to a worker at a time (fewer tasks for the scheduler; each task reads
    the study file once). The rows come back in case order, as one unsharded
    ``kinstab-cli study`` run writes them.
    """
    if not isinstance(batch, int) or batch < 1:
        raise ValueError(f"batch={batch!r}: must be a whole number >= 1")
    path = os.path.abspath(spec)
    n = _core.study_case_count(path)  # a bad study file raises here, before any task
    batches = [list(range(i, min(i + batch, n))) for i in range(0, n, batch)]
    futures = client.map(_run_batch, [path] * len(batches), batches, pure=False)
    rows = client.gather(futures)
    return "".join(line + "\n" for lines in rows for line in lines)
