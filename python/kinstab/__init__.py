# SPDX-License-Identifier: GPL-3.0-or-later
# Over 400 lines on purpose: this is the package's whole public surface, each function's
# signature and docstring, so that help(kinstab) reads as one page beside its stub _core.pyi.
# What the functions do lives elsewhere: the engine in python/src (C++), the argument checks in
# _api.py, the result types in _results.py, projects in project.py, studies in study.py.
"""kinstab: can a floor slab held by friction slide off its walls in an earthquake?

The engine of kinstab (Furgerson 1980 stick-slip model) in Python::

    import kinstab
    r = kinstab.simulate(1.2, 1.0, envelope="moderate")
    print(r.outcome, r.tau_c, r.gamma_c)   # collapsed 20.156... 1.879...

(At 0.9 g the same slab stays on its walls: outcome 'stable', tau_c NaN, gamma_c 0.)

Every run takes the same case keywords as ``kinstab-cli``'s model flags: ``envelope`` (a preset
name or an :class:`Envelope`), ``tstar`` or ``wall_width_in``, ``mu``, ``limit``, ``duration``,
``scale``, ``solver``, ``paper_steps``; ``planar=Planar(fy=...)`` selects the planar slab of
ch. VI, each spelt out in the signatures. A bad value raises ``ValueError`` with the command
line's message; a value of the wrong type or a misspelt keyword ``TypeError`` naming the function
and the keyword; a missing file ``FileNotFoundError``. A project file is :class:`Project`
(``Project.load(path).check()``, ``.floors()``, ``.study()``, ``.report(pdf)``).
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from typing import Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._api import Default as _D
from ._api import public as _public
from ._core import (
    EXIT_SIDES,
    OUTCOMES,
    Envelope,
    PlanarCase,
    PlanarResult,
    Record,
    SimulationResult,
    SlabCase,
)
from . import friction

__version__: str = _core.__version__

Axis = Union[Sequence[float], np.ndarray, str]
PathLike = Union[str, "os.PathLike[str]"]

__all__ = [
    "EXIT_SIDES", "OUTCOMES", "Envelope", "PlanarCase", "PlanarResult", "Record",
    "SimulationResult", "SlabCase", "Planar", "Surface", "Project", "Assessment",
    "slab_case", "simulate", "surface", "critical", "simulate_record", "read_record",
    "floor_filter", "record_table", "codes", "assess", "risk", "read_hazard", "friction",
    "study", "rocking", "rocking_critical", "overturning_map", "RockingRun", "__version__",
]


def __dir__() -> list:
    """What the package offers (its imports, np, json, Optional, are not part of it)."""
    return sorted(__all__)


@dataclass(frozen=True)
class Planar:
    """The planar model's own inputs (Furgerson 1980, ch. VI): frequency along the walls
    ``fy`` (Hz), ``ay_ratio`` = A_y / A_x, the along-wall limit ``theta`` (2 wall length / wall
    width), ``normalization`` ('product' or 'envelope') and an optional ``vertical`` record file
    (upward base acceleration; None: gravity only)."""

    fy: float
    ay_ratio: float = 0.9
    theta: float = 20.0
    normalization: str = "product"
    vertical: Optional[str] = None


_CASE_DOC = """The case keywords (the CLI's model flags; defaults as shown): ``envelope`` (a preset
    name 'fast', 'moderate', 'slow' or an :class:`Envelope`), ``tstar`` (s; default 0.099, the
    paper's 8 inch wall) or ``wall_width_in``, ``mu``, ``limit``, ``duration`` (s), ``scale``
    ('one', 'tau_dur', 'tau_max', 'tau_rise'), ``solver`` ('exact' or 'paper'), ``paper_steps``
    and ``planar=Planar(fy=...)`` for the planar slab of ch. VI. Or ``case=``, a made case (then
    none of the keywords)."""


@_public
def slab_case(
    *,
    envelope: Union[str, Envelope] = "moderate",
    tstar: Optional[float] = None,
    wall_width_in: Optional[float] = None,
    mu: float = 0.6,
    limit: float = 1.0,
    duration: Optional[float] = None,
    scale: str = "tau_max",
    solver: str = "exact",
    paper_steps: float = 16.0,
    planar: Optional[Planar] = None,
) -> Union[SlabCase, PlanarCase]:
    """The checked case of a run: a SlabCase, or a PlanarCase when ``planar`` is given.
    ``tstar`` defaults to 0.099 s (the paper's 8 inch wall)."""
    common = SlabCase(envelope=envelope, tstar=tstar, wall_width_in=wall_width_in, mu=mu,
                      limit=limit, duration=duration, scale=scale, solver=solver,
                      paper_steps=paper_steps)
    if planar is None:
        return common
    return PlanarCase(common, fy=planar.fy, ay_ratio=planar.ay_ratio, theta=planar.theta,
                      normalization=planar.normalization, vertical=planar.vertical)


_default_case: Optional[SlabCase] = None


def _case(function: str, case: Optional[Union[SlabCase, PlanarCase]],
          keywords: dict) -> Union[SlabCase, PlanarCase]:
    global _default_case
    set_ = {k: v for k, v in keywords.items() if v.__class__ is not _D}
    if case is not None:
        if set_:
            raise ValueError(f"{function}(): give either case= or the case keywords, not both ("
                             + ", ".join(sorted(set_)) + ")")
        return case
    if set_:
        return slab_case(**set_)  # slab_case's defaults are the keywords' defaults
    if _default_case is None:  # a case is immutable: the default one is made once
        _default_case = slab_case()
    return _default_case


@_public
def simulate(
    amplitude: float,
    frequency: float,
    *,
    envelope: Union[str, Envelope] = _D("moderate"),
    tstar: Optional[float] = _D(None),
    wall_width_in: Optional[float] = _D(None),
    mu: float = _D(0.6),
    limit: float = _D(1.0),
    duration: Optional[float] = _D(None),
    scale: str = _D("tau_max"),
    solver: str = _D("exact"),
    paper_steps: float = _D(16.0),
    planar: Optional[Planar] = _D(None),
    case: Optional[Union[SlabCase, PlanarCase]] = None,
    events: bool = False,
    history: bool = False,
    history_step: float = 0.05,
) -> Union[SimulationResult, PlanarResult]:
    """One run under A e(t) sin(2 pi f t): ``amplitude`` in g, ``frequency`` in Hz.

    ``events=True`` keeps the event list, ``history=True`` the sampled history (every
    ``history_step`` in tau and at every event; planar: the solver's path), as NumPy arrays.
    ``tau_c`` is NaN and ``gamma_c`` 0 when the slab does not collapse (``outcome`` says what
    happened instead).

    {case}
    """
    c = _case("simulate", case, dict(
        envelope=envelope, tstar=tstar, wall_width_in=wall_width_in, mu=mu, limit=limit,
        duration=duration, scale=scale, solver=solver, paper_steps=paper_steps, planar=planar))
    if isinstance(c, PlanarCase):
        if history_step != 0.05:
            raise ValueError("history_step: with the planar model the history lists the "
                             "solver's own steps and events")
        return _core.simulate_planar(c, amplitude, frequency, events=events, path=history)
    return _core.simulate(c, amplitude, frequency, events=events, history=history,
                          history_step=history_step)


@dataclass(frozen=True)
class Surface:
    """A swept (A, f) grid. 2-D arrays are indexed [amplitude, frequency].

    ``tau_c`` is NaN where the slab did not collapse, ``gamma_c`` = tau_ref / tau_c is 0 there;
    ``outcome`` holds indices into :data:`OUTCOMES` (-1: not run); ``exit_side`` (planar only)
    indices into :data:`EXIT_SIDES`."""

    amplitudes: np.ndarray
    frequencies: np.ndarray
    tau_c: np.ndarray
    gamma_c: np.ndarray
    outcome: np.ndarray
    exit_side: Optional[np.ndarray]
    tau_ref: float
    wall_time_s: float

    def outcome_names(self) -> np.ndarray:
        """The outcome array as names ('collapsed', 'stable', ..., 'not_run')."""
        names = np.array(list(OUTCOMES) + ["not_run"], dtype=object)
        return names[self.outcome]

    def to_dataframe(self):
        """One row per grid point: amplitude_g, frequency_hz, outcome, tau_c, gamma_c (and
        exit_side for the planar model). Needs pandas (Debian: python3-pandas)."""
        from ._frames import surface_frame

        return surface_frame(self)


@_public
def surface(
    amplitudes: Axis,
    frequencies: Axis,
    *,
    envelope: Union[str, Envelope] = _D("moderate"),
    tstar: Optional[float] = _D(None),
    wall_width_in: Optional[float] = _D(None),
    mu: float = _D(0.6),
    limit: float = _D(1.0),
    duration: Optional[float] = _D(None),
    scale: str = _D("tau_max"),
    solver: str = _D("exact"),
    paper_steps: float = _D(16.0),
    planar: Optional[Planar] = _D(None),
    case: Optional[Union[SlabCase, PlanarCase]] = None,
    threads: int = 0,
) -> Surface:
    """Sweeps every (A, f) of the grid on ``threads`` threads (0: all cores) with the GIL
    released; Ctrl+C cancels it (KeyboardInterrupt). Axes are sequences of numbers or the
    command line's LIST text ("0.7:1.15:0.05").

    {case}
    """
    c = _case("surface", case, dict(
        envelope=envelope, tstar=tstar, wall_width_in=wall_width_in, mu=mu, limit=limit,
        duration=duration, scale=scale, solver=solver, paper_steps=paper_steps, planar=planar))
    return Surface(**_core._surface(c, amplitudes, frequencies, threads))


@_public
def critical(
    frequencies: Axis,
    *,
    envelope: Union[str, Envelope] = _D("moderate"),
    tstar: Optional[float] = _D(None),
    wall_width_in: Optional[float] = _D(None),
    mu: float = _D(0.6),
    limit: float = _D(1.0),
    duration: Optional[float] = _D(None),
    scale: str = _D("tau_max"),
    solver: str = _D("exact"),
    paper_steps: float = _D(16.0),
    planar: Optional[Planar] = _D(None),
    case: Optional[Union[SlabCase, PlanarCase]] = None,
    max_amplitude: float = 5.0,
    scan_step: float = 0.01,
    tolerance: float = 1e-6,
) -> np.ndarray:
    """A_crit(f) in g: the smallest amplitude that collapses the slab at each frequency (a fine
    scan from where slip can start, then bisection); NaN where nothing up to ``max_amplitude``
    collapses.

    {case}
    """
    c = _case("critical", case, dict(
        envelope=envelope, tstar=tstar, wall_width_in=wall_width_in, mu=mu, limit=limit,
        duration=duration, scale=scale, solver=solver, paper_steps=paper_steps, planar=planar))
    return _core._critical(c, frequencies, max_amplitude, scan_step, tolerance)


@_public
def simulate_record(
    path: PathLike,
    *,
    amplitude: Optional[float] = None,
    scale_factor: Optional[float] = None,
    floor_period: Optional[float] = None,
    damping: float = 0.02,
    critical: bool = False,
    max_amplitude: float = 5.0,
    scan_step: float = 0.01,
    tolerance: float = 1e-6,
    events: bool = False,
    history_step: Optional[float] = None,
    envelope: Union[str, Envelope] = _D("moderate"),
    tstar: Optional[float] = _D(None),
    wall_width_in: Optional[float] = _D(None),
    mu: float = _D(0.6),
    limit: float = _D(1.0),
    duration: Optional[float] = _D(None),
    scale: str = _D("tau_max"),
    case: Optional[SlabCase] = None,
) -> dict:
    """The 1-DOF slab under a recorded motion (through the floor filter of period
    ``floor_period`` s when given), scaled to peak ``amplitude`` g or by ``scale_factor``.
    ``critical=True`` also searches the smallest peak that collapses the slab
    (``critical_peak``, NaN when none). Returns a dict: outcome, tau_c, gamma_c, tau_ref,
    amplitude, scale_factor, ground and motion (:class:`Record`, the motion unscaled), work,
    events and, with ``history_step``, the sampled history (arrays tau, accel, delta, ...).
    The case keywords are those of :func:`simulate` less solver and planar (a record runs the
    exact 1-DOF solver); a missing file raises FileNotFoundError."""
    c = _case("simulate_record", case, dict(
        envelope=envelope, tstar=tstar, wall_width_in=wall_width_in, mu=mu, limit=limit,
        duration=duration, scale=scale))
    return _core._simulate_record(c, os.fspath(path), amplitude, scale_factor, floor_period,
                                  damping, critical, max_amplitude, scan_step, tolerance, events,
                                  history_step)


@_public
def read_record(
    path: PathLike,
    *,
    format: str = "auto",
    dt: Optional[float] = None,
    unit: Optional[str] = None,
    channel: str = "",
) -> Record:
    """Reads a PEER AT2, COSMOS, CSMIP V2, values or time-accel file (``format`` 'auto',
    'at2', 'cosmos', 'csmip', 'values' or 'time-accel'; ``dt`` s and ``unit`` for the formats
    that do not state them; ``channel`` picks a COSMOS/CSMIP channel). The record's catalogue
    numbers are ``record.metrics(sa_period=T)``: PGA, PGV, PGD, Arias intensity, D5-95, mean
    period and Sa(T, 5 %). A missing file raises FileNotFoundError."""
    return _core.read_record(os.fspath(path), format=format, dt=dt, unit=unit, channel=channel)


@_public
def floor_filter(record: Record, period: float, damping: float = 0.02,
                 tail: Optional[float] = None) -> Record:
    """The floor's absolute acceleration: a damped SDOF (``period`` s, ``damping`` ratio) on the
    record, with a free-vibration tail of ``tail`` s (default: until it decays to 1 %, at most
    120 s)."""
    if not isinstance(record, Record):
        raise TypeError(f"floor_filter(): record={record!r} is not a Record (read_record makes "
                        "one)")
    return _core.floor_filter(record, period, damping, tail)


@_public
def record_table(paths: Sequence[PathLike], *, sa_period: Optional[float] = None) -> list:
    """The catalogue numbers of each record file (:meth:`Record.metrics`), one dict per file
    with its ``file``, ``name`` and ``component``: a list, which ``pandas.DataFrame`` takes
    as it is."""
    if isinstance(paths, (str, os.PathLike)):
        raise TypeError(f"record_table(): paths={paths!r} is one file; give a list of files")
    rows = []
    for p in paths:
        r = read_record(p)
        rows.append({"file": os.fspath(p), "name": r.name, "component": r.component,
                     **r.metrics(sa_period)})
    return rows


for _f in (simulate, surface, critical):
    _f.__doc__ = _f.__doc__.replace("{case}", _CASE_DOC)


@_public
def codes(building: dict, **code_inputs: dict) -> dict:
    """Lateral force ratios of the building codes for one building.

    ``building`` and each code's inputs are the project file's objects (keys as in
    resources/examples/paper-16-story.json): ``codes(building, ubc1976={"zone": 4, "k": 0.8},
    ec8={...})``. Returns one dict per code: base shear coefficient, period, top ratio, story
    forces and the ``trail`` of every coefficient with its clause."""
    return json.loads(_core._codes_json(json.dumps(building), json.dumps(code_inputs)))


@_public
def assess(path: PathLike) -> "Assessment":
    """The assessment of a project file: every check the project implies, each with its id
    (``sine.ubc1976``, ``record.atc306``, ``floors.asce7_22.mce_r``, ``risk.set0``, ...), what
    it compares (demand and capacity in one intensity: g, or 1/yr for a risk check's annual rate
    of collapse against the target rate), its margin and verdict, and the governing check.
    The same dictionary as ``kinstab-cli check --project PATH``'s ``"assessment"``; a bad field
    raises ValueError naming it."""
    return Assessment(json.loads(_core._assess_json(os.fspath(path))))


@_public
def risk(
    hazard: PathLike,
    *,
    hazard_format: str = "auto",
    site: Optional[Tuple[float, float]] = None,
    results: Optional[PathLike] = None,
    set: Optional[int] = None,
    median: Optional[float] = None,
    beta: Optional[float] = None,
    measure: Optional[str] = None,
    years: float = 50.0,
    target_rate: Optional[float] = None,
    im: Optional[float] = None,
    bootstrap: int = 1000,
    seed: int = 1,
) -> dict:
    """The annual rate of the slab falling, lambda_c = integral of P(C|x) |d lambda(x)|, and its
    probability in ``years`` from a site's hazard curve (docs/studies.md, "Risk").

    ``hazard``: an OpenQuake hazard_curve CSV (``site=(lon, lat)`` picks its row), a USGS hazard
    JSON or a CSV ``im_g,annual_rate``. The fragility: ``median`` (g) and ``beta``; ``beta``
    alone for the risk-targeted median at ``target_rate`` (default 1 % in 50 years,
    -ln(0.99)/50 per year); or ``results``, a study's JSONL, for every parameter set (or only
    ``set``) with ``bootstrap`` percentiles. ``measure`` ("pga", "sa(1s/5%)") is checked against
    the hazard file's; ``im`` (g) gives P(collapse) there against 10 %. Returns the same dict as
    ``kinstab-cli risk``'s JSON; a bad argument or file raises ValueError naming it."""
    return json.loads(_core._risk_json(
        str(hazard), hazard_format, site, None if results is None else str(results), set,
        median, beta, measure, years, target_rate, im, bootstrap, seed))


@_public
def read_hazard(
    path: PathLike,
    *,
    hazard_format: str = "auto",
    site: Optional[Tuple[float, float]] = None,
    measure: Optional[str] = None,
) -> dict:
    """A hazard curve as kinstab reads it: ``im_g`` and ``annual_rate`` (NumPy arrays; an
    OpenQuake PoE in T years read as -ln(1 - PoE)/T), ``intensity_measure``, ``format``,
    ``source`` and ``zero_rate_points_dropped``. ``measure`` picks a USGS file's curve and is
    checked against the file's; a bad file raises ValueError naming the file and line."""
    return _core._read_hazard(str(path), hazard_format, site, measure)


class RockingRun(dict):
    """A free-standing block's run: the keys of ``kinstab-cli rocking``'s JSON (``outcome``,
    ``max_theta_over_alpha``, ``impact_times_s``, ``overturn_time_s``, ...), also readable as
    attributes (``r.outcome``)."""

    def __getattr__(self, name: str):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None


def _record_of(record):
    if record is None or isinstance(record, Record):
        return record
    return read_record(record)


@_public
def rocking(
    *,
    half_width: float,
    half_height: float,
    restitution: Optional[float] = None,
    linear: bool = False,
    mu: Optional[float] = None,
    initial_tilt: float = 0.0,
    duration: Optional[float] = None,
    pulse: Optional[str] = None,
    amplitude: Optional[float] = None,
    pulse_frequency: Optional[float] = None,
    pulse_duration: Optional[float] = None,
    record: Union[str, os.PathLike, Record, None] = None,
    history: bool = False,
    history_step: float = 0.01,
) -> RockingRun:
    """One run of a free-standing rigid block (half-width ``half_width``, half-height
    ``half_height``, m; docs/theory.md §10): under ``pulse`` ('half-sine', 'one-sine',
    'one-cosine' with ``amplitude`` g and ``pulse_frequency`` Hz, 'rectangular' with
    ``pulse_duration`` s), under ``record`` (a path or a :class:`Record`, scaled to peak
    ``amplitude`` g when given), or free rocking from ``initial_tilt`` (theta0 / alpha).
    ``restitution`` None is Housner's; ``mu`` None: it never slides. ``history=True`` adds
    ``t_s``, ``theta_rad``, ``omega_rad_s``, ``sliding_m`` arrays every ``history_step`` s."""
    return RockingRun(_core._rocking(
        half_width, half_height, restitution, linear, mu, initial_tilt, duration, pulse,
        _record_of(record), amplitude, pulse_frequency, pulse_duration, history,
        history_step))


@_public
def rocking_critical(
    *,
    half_width: float,
    half_height: float,
    restitution: Optional[float] = None,
    linear: bool = False,
    mu: Optional[float] = None,
    pulse: Optional[str] = None,
    pulse_frequency: Optional[float] = None,
    pulse_duration: Optional[float] = None,
    record: Union[str, os.PathLike, Record, None] = None,
    max_amplitude: float = 5.0,
    scan_points: int = 200,
    tolerance: float = 1e-4,
) -> dict:
    """The amplitudes (g; a record: its peak) that overturn the block under a pulse shape or a
    record, as ``kinstab-cli rocking --critical``: ``critical_amplitude_g`` (None when nothing
    up to ``max_amplitude`` overturns) and ``overturning_intervals_g`` [(from, to), ...], where
    a gap above the first interval is a safe cape (Zhang & Makris 2001). The search refines
    near overturning as the command does (docs/theory.md §10.7) and stops at 5000 runs
    (``critical_run_limit_reached``)."""
    return _core._rocking_critical(
        half_width, half_height, restitution, linear, mu, pulse, _record_of(record),
        pulse_frequency, pulse_duration, max_amplitude, scan_points, tolerance)


@_public
def overturning_map(
    *,
    half_width: float,
    half_height: float,
    restitution: Optional[float] = None,
    linear: bool = False,
    mu: Optional[float] = None,
    shape: str = "one-sine",
    amplitudes: Tuple[float, float] = (0.5, 10.0),
    frequencies: Tuple[float, float] = (0.5, 10.0),
    amplitude_points: int = 101,
    frequency_points: int = 101,
    threads: int = 0,
) -> dict:
    """The overturning map of a pulse shape (Zhang & Makris 2001, figs. 7-9), as
    ``kinstab-cli rocking-map``: ``amplitudes`` a_p / (alpha g) and ``frequencies`` omega_p / p
    (1-D arrays), ``overturns`` (uint8, [frequency, amplitude]: 0 stands, 1 overturns, 2 leaves
    the base) and ``max_theta_over_alpha`` (float, same shape); also ``alpha_rad``, ``p_rad_s``."""
    return _core._overturning_map(
        half_width, half_height, restitution, linear, mu, shape, tuple(amplitudes),
        tuple(frequencies), amplitude_points, frequency_points, threads)


from ._results import Assessment  # noqa: E402  (uses the package's functions above)
from .project import Project  # noqa: E402
from . import study  # noqa: E402,F401
