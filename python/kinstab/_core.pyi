# SPDX-License-Identifier: GPL-3.0-or-later
"""Type stub of kinstab._core, the compiled engine (python/src/*.cpp)."""

from typing import Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str
OUTCOMES: tuple[str, str, str, str]
EXIT_SIDES: tuple[str, str, str]

class Envelope:
    def __init__(self, alpha: float, beta: float) -> None: ...
    @staticmethod
    def preset(name: str) -> Envelope: ...
    @property
    def alpha(self) -> float: ...
    @property
    def beta(self) -> float: ...
    @property
    def name(self) -> str: ...
    @property
    def preset_name(self) -> Optional[str]: ...
    def times(self, tstar: float = 0.099, computed: bool = False) -> dict[str, float]: ...

class SlabCase:
    def __init__(
        self,
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
    ) -> None: ...
    envelope: Envelope
    tstar: float
    mu: float
    limit: float
    duration: Optional[float]
    scale: str
    solver: str
    paper_steps: float
    tau_ref: float

class PlanarCase:
    def __init__(
        self,
        common: SlabCase,
        *,
        fy: float,
        ay_ratio: float = 0.9,
        theta: float = 20.0,
        normalization: str = "product",
        vertical: Optional[str] = None,
    ) -> None: ...
    fy: float
    ay_ratio: float
    theta: float
    mu: float
    limit: float
    tstar: float
    normalization: str
    has_vertical: bool
    tau_ref: float

class SimulationResult:
    outcome: str
    tau_c: float
    gamma_c: float
    tau_ref: float
    amplitude: float
    frequency: float
    tau_end: float
    slip_intervals: int
    max_abs_delta: float
    residual_delta: float
    failure: str
    work: dict[str, int]
    events: Optional[dict[str, Union[npt.NDArray[np.float64], npt.NDArray[np.int8], list[str]]]]
    history: Optional[dict[str, Union[npt.NDArray[np.float64], npt.NDArray[np.int8]]]]

class PlanarResult:
    outcome: str
    tau_c: float
    gamma_c: float
    tau_ref: float
    amplitude: float
    frequency: float
    tau_end: float
    slip_intervals: int
    max_abs_delta: float
    residual_delta: float
    failure: str
    work: dict[str, int]
    exit_side: str
    tau_lift_off: float
    max_abs_delta_y: float
    residual_delta_y: float
    events: dict[str, Union[npt.NDArray[np.float64], list[str]]]
    path: dict[str, Union[npt.NDArray[np.float64], npt.NDArray[np.bool_]]]

class Record:
    dt: float
    samples: npt.NDArray[np.float64]
    time: npt.NDArray[np.float64]
    name: str
    station: str
    component: str
    source_file: str
    format: str
    file_unit: str
    header_peak: Optional[float]
    duration: float
    peak: float
    peak_time: float
    def metrics(self, sa_period: Optional[float] = None) -> dict[str, Optional[float]]: ...
    def __len__(self) -> int: ...

def simulate(
    case: SlabCase,
    amplitude: float,
    frequency: float,
    *,
    events: bool = False,
    history: bool = False,
    history_step: float = 0.05,
) -> SimulationResult: ...
def simulate_planar(
    case: PlanarCase, amplitude: float, frequency: float, *, events: bool = False, path: bool = False
) -> PlanarResult: ...
def read_record(
    path: str,
    *,
    format: str = "auto",
    dt: Optional[float] = None,
    unit: Optional[str] = None,
    channel: str = "",
) -> Record: ...
def floor_filter(
    record: Record, period: float, damping: float = 0.02, tail: Optional[float] = None
) -> Record: ...
def _surface(
    case: Union[SlabCase, PlanarCase],
    amplitudes: Union[Sequence[float], npt.ArrayLike, str],
    frequencies: Union[Sequence[float], npt.ArrayLike, str],
    threads: int = 0,
) -> dict: ...
def _critical(
    case: Union[SlabCase, PlanarCase],
    frequencies: Union[Sequence[float], npt.ArrayLike, str],
    max_amplitude: float = 5.0,
    scan_step: float = 0.01,
    tolerance: float = 1e-6,
) -> npt.NDArray[np.float64]: ...
def _simulate_record(
    case: SlabCase,
    path: str,
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
) -> dict: ...
def _codes_json(building: str, codes: str) -> str: ...
def _assess_json(path: str) -> str: ...
def _risk_json(
    hazard: str,
    hazard_format: str,
    site: Optional[tuple[float, float]],
    results: Optional[str],
    set: Optional[int],
    median: Optional[float],
    beta: Optional[float],
    measure: Optional[str],
    years: float,
    target_rate: Optional[float],
    im: Optional[float],
    bootstrap: int,
    seed: int,
) -> str: ...
def _read_hazard(
    path: str,
    hazard_format: str = "auto",
    site: Optional[tuple[float, float]] = None,
    measure: Optional[str] = None,
) -> dict: ...
def _calibrate_json(
    data: str,
    bearing_area: Optional[float] = None,
    alpha: float = 2.0,
    beta: str = "best",
    max_cp: float = 400.0,
    outlier_alpha: float = 0.05,
    outlier_min_runs: int = 5,
    keep_outliers: bool = False,
) -> str: ...
def _core_seconds(
    case: SlabCase, amplitude: float, frequency: float, repeats: int
) -> list[float]: ...

def _project_json(path: str) -> str: ...
def _floors_json(path: str) -> str: ...
def _study_json(path: str, bootstrap: int, seed: int, threads: int) -> str: ...
def study_case_count(spec: str) -> int: ...
def study_rows(spec: str, cases: list[int]) -> list[str]: ...
