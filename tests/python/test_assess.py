# SPDX-License-Identifier: GPL-3.0-or-later
"""kinstab.assess(path) returns the same dictionary as `kinstab-cli check`'s "assessment" on every
example project that the check accepts (one assessment, every front end), and a bad project
raises ValueError naming the field."""

import json

import pytest

import kinstab
from conftest import SOURCE_DIR

EXAMPLES = sorted(p for p in (SOURCE_DIR / "resources" / "examples").glob("*.json")
                  if json.loads(p.read_text()).get("format") == "kinstab-project")


@pytest.mark.parametrize("project", EXAMPLES, ids=lambda p: p.name)
def test_assess_equals_the_cli_check(cli, project):
    check = cli("check", "--project", project)
    assessed = kinstab.assess(project)
    # Timings aside, the two are one computation: bit for bit equal.
    assert assessed == check["assessment"]
    assert assessed["governing"]["id"] in [c["id"] for c in assessed["checks"]]


def test_assess_names_the_bad_field(tmp_path):
    project = json.loads((SOURCE_DIR / "resources/examples/paper-16-story.json").read_text())
    project["building"]["height"] = -3
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(project))
    with pytest.raises(ValueError, match="building.height"):
        kinstab.assess(path)
