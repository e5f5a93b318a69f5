# SPDX-License-Identifier: GPL-3.0-or-later
"""The package's public face (issue 35): keyword-only parameters spelled out in the signatures,
errors that name the public function and keyword, FileNotFoundError for a missing file,
``__all__`` and a ``dir()`` without the package's own imports, and the README's first Python
line printing something true."""

import inspect
import os
import re
import subprocess
import sys

import pytest

import kinstab
from conftest import SOURCE_DIR

CASE_KEYWORDS = ["envelope", "tstar", "wall_width_in", "mu", "limit", "duration", "scale",
                 "solver", "paper_steps", "planar"]
ELCENTRO = SOURCE_DIR / "resources" / "records" / "RSN6_IMPVALL.I_I-ELC180.AT2"


@pytest.mark.parametrize("name", ["simulate", "surface", "critical"])
def test_case_keywords_in_the_signature(name):
    sig = inspect.signature(getattr(kinstab, name))
    params = sig.parameters
    assert not any(p.kind == p.VAR_KEYWORD for p in params.values())
    for k in CASE_KEYWORDS:
        assert params[k].kind == inspect.Parameter.KEYWORD_ONLY, k
    # help() shows the defaults as values, not as a sentinel's repr.
    text = str(sig)
    assert "mu: 'float' = 0.6" in text or "mu: float = 0.6" in text, text
    assert "envelope: 'Union[str, Envelope]' = 'moderate'" in text or "= 'moderate'" in text


def test_simulate_record_signature_lists_its_case_keywords():
    params = inspect.signature(kinstab.simulate_record).parameters
    for k in ["envelope", "tstar", "wall_width_in", "mu", "limit", "duration", "scale"]:
        assert params[k].kind == inspect.Parameter.KEYWORD_ONLY, k


def test_misspelt_keyword_names_the_public_function():
    with pytest.raises(TypeError) as e:
        kinstab.simulate(0.9, 1.0, mue=0.5)
    assert str(e.value) == ("simulate() got an unexpected keyword argument 'mue' "
                            "(did you mean 'mu'?)")
    with pytest.raises(TypeError, match=r"^critical\(\) got an unexpected keyword argument "
                                        r"'envelop' \(did you mean 'envelope'\?\)$"):
        kinstab.critical([1.0], envelop="fast")
    with pytest.raises(TypeError, match=r"^surface\(\) got an unexpected keyword argument 'zzz'$"):
        kinstab.surface([0.5], [1.0], zzz=1)


def test_list_amplitude_names_function_and_keyword():
    with pytest.raises(TypeError) as e:
        kinstab.simulate([0.9], 1.0)
    message = str(e.value)
    assert message.startswith("simulate(): amplitude=[0.9] is not a number (a list)"), message
    assert "_core" not in message and "SlabCase" not in message
    with pytest.raises(TypeError, match=r"^simulate\(\): mu='0.5' is not a number \(a str\)"):
        kinstab.simulate(0.9, 1.0, mu="0.5")
    with pytest.raises(TypeError, match=r"^simulate_record\(\): amplitude=\(1, 2\)"):
        kinstab.simulate_record(ELCENTRO, amplitude=(1, 2))
    with pytest.raises(TypeError, match=r"^simulate\(\): missing a required argument: "
                                        r"'frequency'$"):
        kinstab.simulate(0.9)


def test_case_and_case_keywords_exclude_each_other():
    c = kinstab.slab_case(mu=0.3)
    with pytest.raises(ValueError, match=r"^simulate\(\): give either case= or the case "
                                         r"keywords, not both \(mu\)$"):
        kinstab.simulate(0.9, 1.0, case=c, mu=0.6)  # 0.6 is the default: still refused
    assert kinstab.simulate(0.9, 1.0, case=c).outcome in kinstab.OUTCOMES


@pytest.mark.parametrize("call,function", [
    (lambda: kinstab.read_record("nope.AT2"), "read_record"),
    (lambda: kinstab.simulate_record("nope.AT2", amplitude=0.5), "simulate_record"),
    (lambda: kinstab.assess("nope.AT2"), "assess"),
    (lambda: kinstab.Project.load("nope.AT2"), "Project.load"),
    (lambda: kinstab.read_hazard("nope.AT2"), "read_hazard"),
    (lambda: kinstab.risk("nope.AT2", median=0.5, beta=0.4), "risk"),
    (lambda: kinstab.record_table(["nope.AT2"]), "read_record"),
])
def test_missing_file_is_file_not_found(call, function):
    with pytest.raises(FileNotFoundError) as e:
        call()
    assert e.value.filename == "nope.AT2"
    assert f"{function}()" in str(e.value)
    assert "cannot open" not in str(e.value)


def test_all_and_dir():
    for name in kinstab.__all__:
        assert hasattr(kinstab, name), name
    listed = dir(kinstab)
    for private in ("np", "json", "Optional", "Union", "os", "dataclass", "Sequence"):
        assert private not in listed, private
    for public in ("simulate", "Project", "read_record", "Envelope"):
        assert public in listed
    namespace = {}
    exec("from kinstab import *", namespace)
    assert "simulate" in namespace and "np" not in namespace


def test_readme_first_python_line_prints_something_true():
    readme = (SOURCE_DIR / "README.md").read_text()
    line = next(ln for ln in readme.splitlines() if "/usr/bin/python3 -c" in ln)
    code = re.search(r'-c "(.*)"', line).group(1)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env={**os.environ}, check=True, timeout=60).stdout.split()
    assert "nan" not in out, out
    outcome, tau_c, gamma_c = out
    # The printed values are the run's: a collapse with its time and gamma_c = tau_ref / tau_c.
    r = kinstab.simulate(float(re.search(r"simulate\(([\d.]+)", code).group(1)), 1.0)
    assert outcome == r.outcome == "collapsed"
    assert float(tau_c) == pytest.approx(r.tau_c) and float(gamma_c) == pytest.approx(r.gamma_c)
    assert r.gamma_c == pytest.approx(r.tau_ref / r.tau_c)


def test_import_does_not_load_pandas_or_qt():
    code = ("import sys, kinstab; print(sorted(m for m in sys.modules "
            "if m.split('.')[0] in ('pandas', 'PySide6', 'kinstab') and m != 'kinstab'))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, timeout=60).stdout
    assert "pandas" not in out and "kinstab._report" not in out, out
