# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared fixtures: kinstab-cli (to compare the module with) and the repository's files.

CTest sets KINSTAB_CLI, KINSTAB_SOURCE_DIR and PYTHONPATH=build/python (tests/CMakeLists.txt);
run by hand: PYTHONPATH=build/python /usr/bin/python3 -m pytest tests/python
"""

import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("KINSTAB_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
CLI = pathlib.Path(os.environ.get("KINSTAB_CLI", SOURCE_DIR / "build" / "app" / "cli" / "kinstab-cli"))


def run_cli(*args, expect_ok=True):
    """Runs kinstab-cli; returns the parsed JSON on stdout, or (exit code, stderr) when a
    failure is expected."""
    p = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True, timeout=120,
                       env={**os.environ, "LC_ALL": "C"})
    if not expect_ok:
        return p.returncode, p.stderr.strip()
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    # The CLI stamps its JSON with the version that wrote it; the module's dicts carry the
    # same version as kinstab.__version__ instead.
    if isinstance(out, dict):
        out.pop("kinstab_version", None)
    return out


@pytest.fixture(scope="session")
def cli():
    assert CLI.exists(), f"kinstab-cli not found at {CLI} (set KINSTAB_CLI)"
    return run_cli


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR
