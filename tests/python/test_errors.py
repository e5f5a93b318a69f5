# SPDX-License-Identifier: GPL-3.0-or-later
"""Bad arguments raise ValueError with kinstab-cli's message for the same value: the CLI's
"--mu 11: friction coefficient must be between 0 and 10" is "mu=11.0: friction coefficient must
be between 0 and 10" in Python. Each case runs both and compares the text after the name."""

import pytest

import kinstab

# (python call, cli arguments, python prefix)
CASES = [
    (lambda: kinstab.simulate(0.9, 1.0, mu=11), ["simulate", "--amplitude", "0.9", "--frequency", "1", "--mu", "11"], "mu=11"),
    (lambda: kinstab.simulate(0.9, 1.0, mu=-0.5), ["simulate", "--amplitude", "0.9", "--frequency", "1", "--mu", "-0.5"], "mu=-0.5"),
    (lambda: kinstab.simulate(1200, 1.0), ["simulate", "--amplitude", "1200", "--frequency", "1"], "amplitude=1200"),
    (lambda: kinstab.simulate(0.9, 0), ["simulate", "--amplitude", "0.9", "--frequency", "0"], "frequency=0"),
    (lambda: kinstab.simulate(0.9, 1.0, tstar=0), ["simulate", "--amplitude", "0.9", "--frequency", "1", "--tstar", "0"], "tstar=0"),
    (lambda: kinstab.simulate(0.9, 1.0, wall_width_in=2000), ["simulate", "--amplitude", "0.9", "--frequency", "1", "--wall-width-in", "2000"], "wall_width_in=2000"),
    (lambda: kinstab.simulate(0.9, 1.0, limit=0), ["simulate", "--amplitude", "0.9", "--frequency", "1", "--limit", "0"], "limit=0"),
    (lambda: kinstab.simulate(0.9, 1.0, duration=-1), ["simulate", "--amplitude", "0.9", "--frequency", "1", "--duration", "-1"], "duration=-1"),
    (lambda: kinstab.simulate(0.9, 1.0, solver="paper", paper_steps=2), ["simulate", "--amplitude", "0.9", "--frequency", "1", "--solver", "paper", "--paper-steps", "2"], "paper_steps=2"),
    (lambda: kinstab.simulate(0.9, 1.0, history=True, history_step=0), ["simulate", "--amplitude", "0.9", "--frequency", "1", "--history", "/dev/null", "--history-step", "0"], "history_step=0"),
    (lambda: kinstab.Envelope(0.5, 0.2), ["simulate", "--amplitude", "0.9", "--frequency", "1", "--alpha", "0.5", "--beta", "0.2"], "beta=0.2"),
    (lambda: kinstab.surface([0.5, -1], [1.0]), ["surface", "--amplitudes", "0.5,-1", "--frequencies", "1"], "amplitudes"),
    (lambda: kinstab.surface("1:0:0.1", [1.0]), ["surface", "--amplitudes", "1:0:0.1", "--frequencies", "1"], "amplitudes"),
    (lambda: kinstab.critical([1.0], scan_step=6), ["critical", "--frequencies", "1", "--scan-step", "6"], "scan_step=6"),
    (lambda: kinstab.critical([1.0], tolerance=0.1), ["critical", "--frequencies", "1", "--tolerance", "0.1"], "tolerance=0.1"),
    (lambda: kinstab.simulate(0.9, 1.0, planar=kinstab.Planar(fy=-1)), ["simulate", "--model", "planar", "--amplitude", "0.9", "--frequency", "1", "--fy", "-1"], "fy=-1"),
    (lambda: kinstab.simulate(0.9, 1.0, planar=kinstab.Planar(fy=1, ay_ratio=200)), ["simulate", "--model", "planar", "--amplitude", "0.9", "--frequency", "1", "--fy", "1", "--ay-ratio", "200"], "ay_ratio=200"),
    (lambda: kinstab.simulate(0.9, 1.0, planar=kinstab.Planar(fy=1, theta=0)), ["simulate", "--model", "planar", "--amplitude", "0.9", "--frequency", "1", "--fy", "1", "--theta", "0"], "theta=0"),
    # Issue 31: values accepted before that hung or gave NaN; one declaration in core words both.
    (lambda: kinstab.critical([2.0], mu=1e-300), ["critical", "--frequencies", "2", "--mu", "1e-300"], "mu=1e-300"),
    (lambda: kinstab.simulate(1.2, 1.0, tstar=1e-300), ["simulate", "--amplitude", "1.2", "--frequency", "1", "--tstar", "1e-300"], "tstar=1e-300"),
    (lambda: kinstab.Envelope(1e-9, 3.0), ["critical", "--frequencies", "2", "--alpha", "1e-9", "--beta", "3"], "alpha=1e-09"),
    (lambda: kinstab.simulate(0.9, 1.0, limit=1e-5), ["simulate", "--amplitude", "0.9", "--frequency", "1", "--limit", "1e-5"], "limit=1e-05"),
    (lambda: kinstab.simulate(0.9, 1.0, wall_width_in=5e-324), ["simulate", "--amplitude", "0.9", "--frequency", "1", "--wall-width-in", "5e-324"], "wall_width_in=5e-324"),
    (lambda: kinstab.critical([1.0], max_amplitude=1000, scan_step=0.001), ["critical", "--frequencies", "1", "--max-amplitude", "1000", "--scan-step", "0.001"], "scan_step=0.001"),
]


def tail(message):
    """The message after its "name value" part."""
    return message.split(": ", 1)[1]


@pytest.mark.parametrize("call,cli_args,prefix", CASES)
def test_message_as_cli(cli, call, cli_args, prefix):
    code, stderr = cli(*cli_args, expect_ok=False)
    assert code == 2, stderr
    cli_message = stderr.split(": error: ", 1)[1]
    with pytest.raises(ValueError) as e:
        call()
    assert str(e.value).startswith(prefix), str(e.value)
    assert tail(str(e.value)) == tail(cli_message)


def test_choice_names_allowed_words():
    with pytest.raises(ValueError, match=r"^envelope='quick' must be one of fast\|moderate\|slow$"):
        kinstab.simulate(0.9, 1.0, envelope="quick")
    with pytest.raises(ValueError, match=r"^scale='max' must be one of one\|tau_dur\|tau_max\|tau_rise$"):
        kinstab.simulate(0.9, 1.0, scale="max")


def test_not_finite_named():
    with pytest.raises(ValueError, match=r"^mu=nan is not a finite number$"):
        kinstab.simulate(0.9, 1.0, mu=float("nan"))
    with pytest.raises(ValueError, match=r"^amplitude=inf is not a finite number$"):
        kinstab.simulate(float("inf"), 1.0)


def test_record_errors_name_the_file(tmp_path):
    missing = tmp_path / "none.AT2"
    with pytest.raises(FileNotFoundError, match=r"read_record\(\): path: no such file"):
        kinstab.read_record(str(missing))
    broken = tmp_path / "broken.AT2"
    broken.write_text("PEER NGA STRONG MOTION DATABASE RECORD\nnot a record\n")
    with pytest.raises(ValueError, match=r"^path='.*broken\.AT2': "):
        kinstab.read_record(str(broken))
    with pytest.raises(ValueError, match=r"^format='values': needs dt"):
        kinstab.read_record(str(broken), format="values")


def test_record_path_with_nul_is_refused(source_dir):
    # Cut at the NUL, the path would name a record that exists: refused, not read (issue 31).
    path = str(source_dir / "resources" / "records" / "RSN68_SFERN_PEL090.AT2")
    with pytest.raises(ValueError, match="NUL character"):
        kinstab.read_record(path + "\0junk")


def test_codes_errors_name_the_field():
    with pytest.raises(ValueError, match=r"building\.stories"):
        kinstab.codes({"stories": -3, "height": 100, "plan_dimension": 50},
                      ubc1976={"zone": 4, "k": 0.8})


def test_case_and_keywords_exclude_each_other():
    with pytest.raises(ValueError, match=r"^simulate\(\): give either case= or the case keywords"):
        kinstab.simulate(0.9, 1.0, case=kinstab.SlabCase(), mu=0.5)


def test_search_bounds_are_value_errors():
    """The search's own bounds (issue 30): too many scan points, or a tolerance finer than
    double precision resolves, are a ValueError naming the keyword, as the CLI's exit 2."""
    with pytest.raises(ValueError, match=r"^scan_step=1e-06: at most 100000 scan points"):
        kinstab.critical([1.0], scan_step=1e-6)
    with pytest.raises(ValueError, match="^tolerance=1e-17: below what double precision"):
        kinstab.critical([1.0], tolerance=1e-17)
