"""Types of the module dtwin (docs/python.md), for type checkers (mypy) and editors.

The argument types are those each call checks when it runs (a wrong one raises TypeError naming
the keyword); tests/python/stub_test.py checks that every name and signature here is the module's."""
import os
from typing import Any, Callable, Mapping, Sequence

_Path = str | os.PathLike[str]
_Paths = _Path | Sequence[_Path]
_Names = str | Sequence[str]
_Window = tuple[float, float]
_Settings = Mapping[str, float | str] | Sequence[str]
_Effects = Mapping[str, Mapping[str, float | str] | None] | Sequence[str]
_Progress = Callable[[str, int, int], object]

__version__: str
git_describe: str
simbody: str

class InputError(ValueError):
    """Bad input (a file, a field, an argument, a value): the one line `twin` prints after 'twin: error: '."""

class StorageError(OSError):
    """A write failed because the disk (or the quota) is full."""

class SimulationError(RuntimeError):
    """A simulation failed (its step or wall-clock budget, divergence)."""

def default_study() -> str: ...

class Study:
    def __init__(self, path: _Path | None = None) -> None: ...
    @property
    def path(self) -> str: ...
    @property
    def name(self) -> str: ...
    @property
    def seed(self) -> int: ...
    @property
    def assemblies(self) -> dict[str, str]: ...
    @property
    def scenarios(self) -> list[str]: ...
    def to_dict(self) -> dict[str, Any]: ...
    def simulate(
        self,
        assembly: str = "M1",
        scenario: str = "lab",
        *,
        set: _Settings | None = None,
        effects: _Effects | None = None,
        seed: int | None = None,
        channels: _Names | None = None,
        window: _Window | None = None,
        integrator: str | None = None,
        accuracy: float | None = None,
        max_step: float | None = None,
        obstacle_step: float | None = None,
        output_rate: float | None = None,
        out: _Path | None = None,
    ) -> dict[str, Any]:
        """{column: numpy array}; with assembly="all", {id: {column: numpy array}}."""
    def calibrate(
        self,
        data: _Path,
        *,
        assembly: _Names = "all",
        out: _Path,
        threads: int = 0,
        lhs_points: int | None = None,
        iterations: int | None = None,
        burn_in: int | None = None,
        starts: int | None = None,
        region: str | None = None,
        design: str | None = None,
        interval: str | None = None,
        steps: str | None = None,
        max_rounds: int | None = None,
        ridge_steps: int | None = None,
        seed: int | None = None,
        force: bool = False,
        quiet: bool = False,
        progress: _Progress | None = None,
    ) -> dict[str, dict[str, Any]]:
        """{assembly id: its summary.json as a dict}."""
    def compare(
        self,
        calibration: _Path,
        data: _Paths,
        *,
        baseline: _Paths | None = None,
        discrepancy: _Paths | None = None,
        draws: int = 30,
        threads: int = 0,
        out: _Path | None = None,
        force: bool = False,
        quiet: bool = False,
    ) -> dict[str, Any]:
        """The compare.json dict."""
    def diagnose(
        self,
        data: _Paths,
        *,
        assembly: str = "M1",
        holdout: _Paths | None = None,
        effects: _Names | None = None,
        apply: _Names | None = None,
        candidates: int = 6,
        causes: int = 3,
        confirm_within: float = 2.0,
        all_intervals: bool = False,
        propose: int = 3,
        draws: int = 20,
        threads: int = 0,
        lhs_points: int | None = None,
        iterations: int | None = None,
        burn_in: int | None = None,
        starts: int | None = None,
        steps: str | None = None,
        out: _Path | None = None,
        force: bool = False,
        quiet: bool = False,
        progress: _Progress | None = None,
    ) -> dict[str, Any]:
        """The diagnosis.json dict."""

def import_log(
    log: _Path,
    *,
    map: _Path | None = None,
    out: _Path,
    study: _Path | None = None,
    scenario: str = "drive",
    time: str | None = None,
    speed: str | None = None,
    road: str | None = None,
    road_left: str | None = None,
    road_right: str | None = None,
    road_fl: str | None = None,
    road_fr: str | None = None,
    road_rl: str | None = None,
    road_rr: str | None = None,
    channel: _Names | None = None,
    highpass_hz: float | None = None,
    speed_lowpass_hz: float | None = None,
    separator: str | None = None,
    window: _Window | None = None,
    run_in: float | None = None,
    quiet: bool = False,
    progress: _Progress | None = None,
) -> dict[str, Any]:
    """The measurements.json dict."""
