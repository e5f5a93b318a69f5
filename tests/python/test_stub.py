# SPDX-License-Identifier: GPL-3.0-or-later
"""The type stub shipped next to the extension names everything the extension exports, and the
package's public functions carry docstrings."""

import ast
import inspect
import pathlib

import kinstab
from kinstab import _core


def test_stub_covers_the_extension():
    stub = pathlib.Path(_core.__file__).with_name("_core.pyi")
    tree = ast.parse(stub.read_text())
    declared = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            declared.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            declared.add(node.target.id)
    exported = {n for n in dir(_core) if not n.startswith("__")}
    assert exported - declared == set()


def test_public_functions_documented():
    for name in ("simulate", "surface", "critical", "simulate_record", "codes", "slab_case",
                 "read_record", "floor_filter", "risk", "read_hazard", "rocking",
                 "rocking_critical", "overturning_map"):
        assert inspect.getdoc(getattr(kinstab, name)), name
    assert inspect.getdoc(kinstab.friction.calibrate)
    assert inspect.getdoc(kinstab.Envelope)
