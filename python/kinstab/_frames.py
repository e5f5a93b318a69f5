# SPDX-License-Identifier: GPL-3.0-or-later
"""Results as pandas DataFrames. pandas is imported here, when a conversion is asked for, never
when kinstab is imported: the package works without it (Debian: python3-pandas)."""

from __future__ import annotations

from typing import Any, Iterable, List, Mapping


def _pandas() -> Any:
    try:
        import pandas
    except ImportError as e:
        raise ImportError("to_dataframe() needs pandas (Debian: apt-get install python3-pandas; "
                          "pip: pip install pandas)") from e
    return pandas


def frame(rows: Iterable[Mapping[str, Any]], columns: List[str]) -> Any:
    """A DataFrame of dict rows with the columns in this order (keys a row lacks: missing)."""
    return _pandas().DataFrame([dict(r) for r in rows], columns=columns)


def surface_frame(s: Any) -> Any:
    import numpy as np

    pd = _pandas()
    a, f = np.meshgrid(s.amplitudes, s.frequencies, indexing="ij")
    data = {"amplitude_g": a.ravel(), "frequency_hz": f.ravel(),
            "outcome": s.outcome_names().ravel(), "tau_c": s.tau_c.ravel(),
            "gamma_c": s.gamma_c.ravel()}
    if s.exit_side is not None:
        data["exit_side"] = s.exit_side.ravel()
    return pd.DataFrame(data)
