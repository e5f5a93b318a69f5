#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A design check from Python, cell by cell (the "# %%" cells run one at a time in Jupyter,
VS Code or Spyder; as a script it runs top to bottom). It does what the GUI's design-check
workflow does for the paper's 16-story building, without the CLI:

    export PYTHONPATH=build/python
    /usr/bin/python3 examples/python/project_notebook.py [OUTPUT_FOLDER]

writes OUTPUT_FOLDER/design-check.pdf (default: the current folder). Tables print as pandas
DataFrames when pandas is installed (Debian: python3-pandas), as plain rows otherwise.
tests/python/test_examples.py runs it.
"""

# %% The project and its assessment
import pathlib
import sys

import kinstab

examples = pathlib.Path(__file__).resolve().parents[2] / "resources" / "examples"
out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")

try:
    import pandas  # noqa: F401

    def show(table):
        print(table.to_string(index=False))
except ImportError:
    pandas = None

    def show(rows):
        for row in rows:
            print(row)

project = kinstab.Project.load(examples / "paper-16-story-floors.json")
assessment = project.check()
columns = ["id", "demand", "capacity", "margin", "verdict"]
print(project)
show(assessment.to_dataframe()[columns] if pandas else
     [{k: c[k] for k in columns} for c in assessment["checks"]])
print("governing:", assessment.governing["id"], "-", assessment.governing["verdict"])

# %% The floors: peak floor acceleration and the critical ground PGA per level
floors = project.floors()
levels = floors.to_dataframe() if pandas else floors["levels"]
show(levels)

# %% The ground motion: its catalogue numbers, Sa at the building's period
period = project.data["excitation"]["record"]["floor_filter"]["period_s"]
record = kinstab.read_record(floors["record"]["file"])
metrics = record.metrics(sa_period=period)
print(f"{record.name}: PGA {metrics['pga_g']:.3f} g, PGV {100 * metrics['pgv_m_s']:.1f} cm/s, "
      f"Arias {metrics['arias_m_s']:.2f} m/s, D5-95 {metrics['d5_95_s']:.1f} s, "
      f"Tm {metrics['mean_period_s']:.2f} s, Sa({period:g} s) {metrics['sa_g']:.3f} g")

# %% The record-suite study: fragility and the spread of the critical intensity per set
study = kinstab.Project.load(examples / "paper-16-story-risk.json").study(bootstrap=200)
stats = ["set", "mu", "records", "censored", "critical_im_mean_g", "critical_im_median_g",
         "critical_im_std_g", "ln_critical_im_std", "median_g", "beta"]
show(study.sets_dataframe()[stats] if pandas else
     [{k: s.get(k, s["record_statistics"].get(k)) for k in stats}
      for s in study["fragility"]["sets"]])

# %% The report, as File -> Export report... writes it
report = project.report(out / "design-check.pdf")
print(f"wrote {report['output']} ({report['pages']} pages)")
