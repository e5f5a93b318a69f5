# SPDX-License-Identifier: GPL-3.0-or-later
"""A project file as one object: what the GUI and ``kinstab-cli`` do with a project, from
Python, without shelling out::

    p = kinstab.Project.load("resources/examples/paper-16-story.json")
    a = p.check()                      # the assessment: every check, the governing one
    print(a.governing["verdict"])
    p.report("design-check.pdf")       # the signable report, as File -> Export report...

Each call runs core's own analysis (core/assessment runAssessment, core/building analyseFloors,
core/study runStudy and studyFragility); the report is written by the report library
``kinstab-cli report`` links (Qt Gui on its offscreen platform: no display needed, loaded only
when a report is asked for).
"""

from __future__ import annotations

import json
import os
from typing import Any, Union

from . import _core
from ._api import existing_file, public
from ._results import Assessment, Floors, Study

PathLike = Union[str, "os.PathLike[str]"]
OutputPath = Union[str, "os.PathLike[str]"]  # a file written (need not exist)


class Project:
    """A project file (docs/user-guide.md), read and checked by core's project reader: a bad
    field raises ValueError naming it, a missing file FileNotFoundError."""

    def __init__(self, path: str, data: dict) -> None:
        self.path = path
        self.data = data

    @classmethod
    @public
    def load(cls, path: PathLike) -> "Project":
        """Reads and checks the project file at ``path``."""
        p = existing_file("Project.load", "path", path)
        return cls(os.path.abspath(p), json.loads(_core._project_json(p)))

    @property
    def name(self) -> str:
        return self.data.get("name", "")

    def __repr__(self) -> str:
        return f"<kinstab.Project {self.name!r} from {self.path}>"

    def check(self) -> Assessment:
        """The project's assessment: the same dict as ``kinstab-cli check --project``'s
        ``"assessment"`` (checks with demand, capacity, margin and verdict; the governing one;
        notes). ``to_dataframe()`` gives one row per check."""
        return Assessment(json.loads(_core._assess_json(self.path)))

    assess = check

    def floors(self) -> Floors:
        """The floor-motion check under the project's ground record (shear-building model, every
        level's critical PGA, the codes' floor demands): ``kinstab-cli floors --project``'s
        JSON less its timing. ``to_dataframe()`` gives one row per level."""
        return Floors(json.loads(_core._floors_json(self.path)))

    @public
    def study(self, *, bootstrap: int = 1000, seed: int = 1, threads: int = 0) -> Study:
        """The project's record-suite study: its results file when the project names one (checked
        against the study file), else every case run here on ``threads`` threads (0: all
        cores; Ctrl+C stops it). Returns ``rows`` and ``fragility`` (per parameter set: the
        lognormal fit with ``bootstrap`` resamples from ``seed``, and the record statistics of
        the critical intensity)."""
        if bootstrap < 0:
            raise ValueError(f"Project.study(): bootstrap={bootstrap}: must be >= 0")
        if threads < 0:
            raise ValueError(f"Project.study(): threads={threads}: must be >= 0")
        return Study(json.loads(_core._study_json(self.path, bootstrap, seed, threads)))

    @public
    def report(self, pdf_path: OutputPath, *, page: str = "a4", figure_grid: int = 41) -> dict:
        """Writes the design report (the PDF of File -> Export report... and ``kinstab-cli
        report``) to ``pdf_path``; ``page`` 'a4' or 'letter'. Returns the number of pages and
        the output path. Needs kinstab's report module (built with Qt Gui; no display)."""
        try:
            from . import _report
        except ImportError as e:
            raise ImportError("Project.report(): kinstab._report (the report library, Qt Gui) "
                              "is not built or cannot load: " + str(e)) from e
        return json.loads(_report.write_report(self.path, os.fspath(pdf_path), page,
                                               figure_grid))
