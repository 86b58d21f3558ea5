"""Simulating the locomotive: scenarios, a single run and its result.

>>> import loco
>>> scenario = loco.Scenario(scenario="S_high", speed=200 / 3.6)
>>> result = loco.simulate(loco.Locomotive.default(), scenario)  # doctest: +SKIP
>>> result.metrics["wy_max"], result.channel("frame1_ay_wheelset1").max()  # doctest: +SKIP
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from dataclasses import InitVar, dataclass, field, fields
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco.dampers import Damper
from loco.profiles import Profile, builtin
from loco.track import Track
from loco.vehicle import Locomotive

if TYPE_CHECKING:
    import xarray

__all__ = [
    "CREEP_MODELS",
    "RUN_STATISTICS",
    "SCENARIOS",
    "Scenario",
    "SimulationResult",
    "simulate",
]

FloatArray = npt.NDArray[np.float64]

#: The study's scenarios (SPEC §2): name -> (wheel, rail) built-in profiles.
SCENARIOS: dict[str, tuple[str, str]] = {
    "S_low": ("jm3-thin-flange", "cn60"),
    "S_norm": ("jm3-new", "cn60"),
    "S_high": ("jm3-worn", "cn60"),
}


#: The creep models a scenario accepts (``Scenario(creep=...)``), from the core.
CREEP_MODELS: tuple[str, ...] = tuple(_loco.creep_model_names())


@dataclass(frozen=True)
class Scenario:
    """What a run is: wheel and rail, speed (m/s), distance (m), track, yaw damper, settings.

    Give either ``scenario`` (``"S_low"``, ``"S_norm"``, ``"S_high"``) or ``wheel`` (a
    :class:`loco.profiles.Profile` or a built-in name) with an optional ``rail`` (default
    ``cn60``). The track is ``track`` when given, perfect when ``perfect_track`` is true, and
    otherwise synthesised from ``spectrum`` (``"cn-hsr"``, ``"german-low"``, ``"german-high"``),
    ``seed`` and the wavelength ``band`` (m). ``creep`` is the creep model (:data:`CREEP_MODELS`):
    ``"fastsim"``, FASTSIM at every evaluation (the study's method, default); ``"fastrip"``,
    FaStrip (strip theory with spin, closer to Kalker's exact theory in the spin moment); or
    ``"table"``, FASTSIM tabulated once per run or batch: about 2 % of μN force error for a
    faster time loop, worth it for large batches (the table takes ~0.5 s). ``fastsim_grid`` is
    the grid of any of them. (``creep_table`` was replaced by ``creep="table"``.)
    ``lead_in`` (m) is run before the recorded ``distance`` and not recorded, so that start
    transients (an FSD valve leaving its defined start state) settle first; 0 as in the study.
    ``curve`` is the designed alignment the track follows (None: straight): a CSV file of
    sections or a list of dicts, each ``kind`` (``"straight"``, ``"transition"``, ``"curve"``)
    and ``length_m``; a curve adds ``radius_m``, ``cant_mm`` and ``direction`` (``"left"`` or
    ``"right"``), a transition (clothoid, linear cant run-off) may give ``cant_run_off_m``.
    s = 0 is where the leading wheelset starts; irregularities come on top.
    """

    scenario: str | None = None
    wheel: Profile | str | None = None
    rail: Profile | str = "cn60"
    speed: float = 200.0 / 3.6
    distance: float = 500.0
    track: Track | None = None
    perfect_track: bool = False
    spectrum: str = "cn-hsr"
    seed: int = 0
    band: tuple[float, float] = (2.0, 200.0)
    yaw_damper: Damper | None = None
    step: float = 1e-3
    output_rate: float = 500.0
    fastsim_grid: tuple[int, int] = (10, 10)
    creep: str = "fastsim"
    initial_lateral_offset: float = 0.0
    lead_in: float = 0.0
    curve: str | Sequence[Mapping[str, float | str]] | None = None
    creep_table: InitVar[object] = None
    """Removed: refused with :class:`loco.ParameterError` naming ``creep``."""

    def __post_init__(self, creep_table: object) -> None:
        if creep_table is not None:
            raise _loco.ParameterError(
                "invalid parameter `creep_table`: replaced by `creep`; "
                'write creep="table" (or "fastsim", "fastrip")'
            )

    def __repr__(self) -> str:
        """The fields that differ from their defaults (speed in m/s, distance in m)."""
        changed = []
        for f in fields(self):
            value = getattr(self, f.name)
            try:
                same = bool(value == f.default)
            except (TypeError, ValueError):
                same = False
            if not same:
                changed.append(f"{f.name}={value!r}")
        return f"Scenario({', '.join(changed)})"

    def profiles(self) -> tuple[Profile, Profile]:
        """The wheel and rail profiles of the run."""
        if self.scenario is not None:
            if self.wheel is not None:
                raise _loco.ParameterError(
                    "invalid parameter `wheel`: give either a scenario or a wheel, not both"
                )
            if self.scenario not in SCENARIOS:
                raise _loco.ParameterError(
                    f"invalid parameter `scenario`: unknown '{self.scenario}', "
                    f"expected one of {sorted(SCENARIOS)}"
                )
            wheel_name, rail_name = SCENARIOS[self.scenario]
            return builtin(wheel_name), builtin(rail_name)
        if self.wheel is None:
            raise _loco.ParameterError("invalid parameter `wheel`: give a wheel or a scenario")
        wheel = builtin(self.wheel) if isinstance(self.wheel, str) else self.wheel
        rail = builtin(self.rail) if isinstance(self.rail, str) else self.rail
        return wheel, rail

    def native(self, *, seed: int | None = None) -> _loco.RunScenario:
        """The checked native scenario (``seed`` replaces the track seed when given).

        Raises :class:`loco.ParameterError` naming the field for a non-physical value."""
        wheel, rail = self.profiles()
        track_seed = int(self.seed if seed is None else seed)
        if track_seed < 0:
            raise _loco.ParameterError(f"invalid parameter `seed`: must be >= 0, got {track_seed}")
        return _loco.RunScenario(
            wheel,
            rail,
            float(self.speed),
            float(self.distance),
            track=None if self.track is None else self.track.native,
            track_kind="perfect" if self.perfect_track else "synthetic",
            spectrum=self.spectrum,
            seed=track_seed,
            band=(float(self.band[0]), float(self.band[1])),
            yaw_damper=self.yaw_damper,
            step=float(self.step),
            output_rate=float(self.output_rate),
            fastsim_grid=(int(self.fastsim_grid[0]), int(self.fastsim_grid[1])),
            creep=str(self.creep),
            initial_lateral_offset=float(self.initial_lateral_offset),
            lead_in=float(self.lead_in),
            curve=None if self.curve is None else _curve_argument(self.curve),
        )


def _curve_argument(
    curve: str | Sequence[Mapping[str, float | str]],
) -> str | list[dict[str, float | str]]:
    """The ``curve`` setting for the native scenario: a CSV path, or the sections as dicts."""
    if isinstance(curve, (str, os.PathLike)):
        return os.fspath(curve)
    return [dict(section) for section in curve]


#: Names of the run statistics (:attr:`SimulationResult.statistics`, batch columns), from the core.
RUN_STATISTICS: list[str] = _loco.run_statistics_names()


@dataclass(frozen=True)
class SimulationResult:
    """Time histories (SI), metrics and cost statistics of one run.

    ``statistics`` (keys :data:`RUN_STATISTICS`): ``rhs_evaluations`` of the force model (static
    search and time integration), time ``steps``, ``newton_iterations`` of the static
    equilibrium and ``wall_time`` (s); empty for histories kept by a batch (see
    :attr:`loco.BatchResult.statistics`).
    """

    time: FloatArray
    channel_names: list[str]
    channels: FloatArray
    metrics: dict[str, float]
    sampling_rate: float
    parameters: dict[str, Any] = field(default_factory=dict)
    statistics: dict[str, float] = field(default_factory=dict)

    def __repr__(self) -> str:
        duration = float(self.time[-1] - self.time[0]) if len(self.time) else 0.0
        cost = ""
        if self.statistics:
            cost = (
                f", {int(self.statistics['rhs_evaluations'])} evaluations in "
                f"{self.statistics['wall_time']:.2f} s"
            )
        return (
            f"SimulationResult({duration:.3f} s at {self.sampling_rate:g} Hz, "
            f"{len(self.channel_names)} channels, {len(self.metrics)} metrics{cost})"
        )

    def channel(self, name: str) -> FloatArray:
        """The channel called ``name`` (see ``channel_names``)."""
        try:
            return self.channels[self.channel_names.index(name)]
        except ValueError:
            raise _loco.ParameterError(
                f"invalid parameter `name`: no channel '{name}'; available: {self.channel_names}"
            ) from None

    def to_xarray(self) -> xarray.Dataset:
        """The channels as an ``xarray.Dataset`` on a ``time`` coordinate, metrics as attributes."""
        import xarray

        data = {n: ("time", self.channels[i]) for i, n in enumerate(self.channel_names)}
        attrs: dict[str, Any] = {f"metric_{k}": v for k, v in self.metrics.items()}
        attrs["sampling_rate_hz"] = self.sampling_rate
        attrs["loco_version"] = _loco.__version__
        return xarray.Dataset(data, coords={"time": self.time}, attrs=attrs)


def simulate(vehicle: Locomotive, scenario: Scenario) -> SimulationResult:
    """Runs the locomotive through a scenario (static equilibrium, then RK4 in time).

    Raises :class:`loco.ParameterError` for non-physical inputs, :class:`loco.DivergenceError`
    or :class:`loco.DerailmentError` when the run fails (the message says when and where), and
    :class:`loco.EquilibriumError` when its static equilibrium is not found.
    """
    time, names, channels, metric_names, metric_values, statistics = _loco.simulate(
        scenario.native(),
        toml_text=vehicle.toml_text,
        origin=vehicle.origin,
        overrides=dict(vehicle.overrides),
    )
    return SimulationResult(
        time=time,
        channel_names=list(names),
        channels=channels,
        metrics=dict(zip(metric_names, metric_values.tolist(), strict=True)),
        sampling_rate=float(scenario.output_rate),
        parameters={"speed": scenario.speed, "distance": scenario.distance},
        statistics=dict(statistics),
    )
