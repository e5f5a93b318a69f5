# SPDX-License-Identifier: GPL-3.0-or-later
"""The friction law of Furgerson 1980, ch. III, calibrated on triplet shear tests."""

from __future__ import annotations

import json
from typing import Optional

from . import _core


def calibrate(
    data: str,
    *,
    bearing_area: Optional[float] = None,
    alpha: float = 2.0,
    beta: str = "best",
    max_cp: float = 400.0,
    outlier_alpha: float = 0.05,
    outlier_min_runs: int = 5,
    keep_outliers: bool = False,
) -> dict:
    """Fits the decay law to every run of the CSV ``data`` (the layout of
    resources/data/furgerson1980/table1_triplet_tests.csv), tests outliers (Grubbs), averages
    the kept runs per configuration and confining pressure and, with ``bearing_area`` (in^2),
    gives mu_inf per configuration. Returns the dict ``kinstab-cli friction`` prints."""
    return json.loads(_core._calibrate_json(str(data), bearing_area, alpha, beta, max_cp,
                                            outlier_alpha, outlier_min_runs, keep_outliers))
