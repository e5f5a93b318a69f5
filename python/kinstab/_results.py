# SPDX-License-Identifier: GPL-3.0-or-later
"""The dictionaries of the project-level calls, each with ``to_dataframe()`` (pandas, imported
only then). They are plain dicts otherwise: ``json.dumps`` and ``==`` work as before."""

from __future__ import annotations

from typing import Any

from ._frames import frame

_CHECK_COLUMNS = ["id", "basis", "code", "level", "intensity", "unit", "demand_name", "demand",
                  "capacity_name", "capacity", "margin", "margin_at_least", "holds", "verdict"]


class Assessment(dict):
    """A project's assessment: ``checks`` (each with demand, capacity, margin, verdict),
    ``governing`` and ``notes`` (docs/assessment.md)."""

    @property
    def governing(self) -> dict:
        return self["governing"]

    def to_dataframe(self) -> Any:
        """One row per check: id, basis, code, level, intensity, unit, demand, capacity,
        margin, holds, verdict."""
        return frame(self["checks"], _CHECK_COLUMNS)


class Floors(dict):
    """The floor-motion check (``kinstab-cli floors --project``'s JSON): per level the peak
    floor acceleration, the codes' demands and the critical ground PGA; ``checks`` at the
    slab's level."""

    def to_dataframe(self) -> Any:
        """One row per level, bottom first, with the keys of ``self["levels"]``."""
        levels = self["levels"]
        keys = list(levels[0].keys()) if levels else []
        first = [k for k in ("level", "height", "weight") if k in keys]
        return frame(levels, first + [k for k in keys if k not in first])


_SET_COLUMNS = ["set", "mu", "tstar", "limit", "floor_period_s", "floor_damping", "level",
                "motion", "records", "collapsed", "censored", "critical_im_mean_g",
                "critical_im_median_g", "critical_im_std_g", "ln_critical_im_mean",
                "ln_critical_im_std", "median_g", "beta"]


class Study(dict):
    """A project's study: ``rows`` (one per record and parameter set, as ``kinstab-cli study``
    writes them) and ``fragility`` (per set: the lognormal fit, its bootstrap bounds and
    ``record_statistics``, the mean, median and spread of the critical intensity over the records
    that collapse, with the censored ones counted)."""

    def to_dataframe(self) -> Any:
        """One row per case (record x parameter set)."""
        rows = self["rows"]
        return frame(rows, list(rows[0].keys()) if rows else [])

    def sets_dataframe(self) -> Any:
        """One row per parameter set: its parameters, the record statistics and the fit."""
        out = []
        for s in self["fragility"]["sets"]:
            row = {k: v for k, v in s.items() if not isinstance(v, (list, dict))}
            row.update(s.get("record_statistics", {}))
            out.append(row)
        columns = [c for c in _SET_COLUMNS if any(c in r for r in out)]
        return frame(out, columns)
