# SPDX-License-Identifier: GPL-3.0-or-later
"""The notebook-style example (examples/python/project_notebook.py) runs as a script from start
to end, prints the verdicts, the per-level table, the record's metrics and the per-set statistics,
and writes the report."""

import os
import subprocess
import sys

from conftest import SOURCE_DIR


def test_project_notebook_runs(tmp_path):
    script = SOURCE_DIR / "examples" / "python" / "project_notebook.py"
    p = subprocess.run([sys.executable, str(script), str(tmp_path)], capture_output=True,
                       text=True, timeout=300, env={**os.environ, "LC_ALL": "C"})
    assert p.returncode == 0, p.stderr
    out = p.stdout
    assert "governing: floors.asce7_22.mce_r" in out
    assert "PGA 1.219 g" in out and "Sa(1 s)" in out  # Pacoima Dam 164, the project's record
    assert "critical_im_median_g" in out or "'critical_im_median_g'" in out
    assert (tmp_path / "design-check.pdf").read_bytes().startswith(b"%PDF")


def test_project_notebook_runs_without_pandas(tmp_path):
    # A pandas that cannot be imported, first on the path: the example prints plain rows.
    blocker = tmp_path / "block"
    (blocker / "pandas").mkdir(parents=True)
    (blocker / "pandas" / "__init__.py").write_text("raise ImportError('no pandas here')\n")
    script = SOURCE_DIR / "examples" / "python" / "project_notebook.py"
    env = {**os.environ, "LC_ALL": "C",
           "PYTHONPATH": os.pathsep.join([str(blocker), os.environ.get("PYTHONPATH", "")])}
    p = subprocess.run([sys.executable, str(script), str(tmp_path)], capture_output=True,
                       text=True, timeout=300, env=env)
    assert p.returncode == 0, p.stderr
    assert "{'id': 'sine.ubc1976'" in p.stdout
    assert (tmp_path / "design-check.pdf").exists()
