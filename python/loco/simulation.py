"""Simulating the locomotive: scenarios, a single run and its result.

>>> import loco
>>> scenario = loco.Scenario(scenario="S_high", speed=200 / 3.6)
>>> result = loco.simulate(loco.Locomotive.default(), scenario)  # doctest: +SKIP
>>> result.metrics["wy_max"], result.channel("frame1_ay_wheelset1").max()  # doctest: +SKIP
"""

from __future__ import annotations

from dataclasses import InitVar, dataclass, field, fields
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco import field_types as types
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
            types.text("scenario", self.scenario)
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
        return _profile("wheel", self.wheel), _profile("rail", self.rail)

    def native(self, *, seed: int | None = None) -> _loco.RunScenario:
        """The checked native scenario (``seed`` replaces the track seed when given).

        Raises :class:`loco.ParameterError` naming the field for a non-physical value or a
        value of the wrong type (:mod:`loco.field_types`)."""
        wheel, rail = self.profiles()
        track_seed = types.whole("seed", self.seed if seed is None else seed)
        if self.track is not None and not isinstance(self.track, Track):
            raise types.wrong_type("track", "a loco.Track or None", self.track)
        if self.yaw_damper is not None and not isinstance(self.yaw_damper, Damper):
            raise types.wrong_type("yaw_damper", "a loco.dampers.Damper or None", self.yaw_damper)
        band = types.pair("band", self.band)
        grid = types.pair("fastsim_grid", self.fastsim_grid)
        return _loco.RunScenario(
            wheel,
            rail,
            types.real("speed", self.speed),
            types.real("distance", self.distance),
            track=None if self.track is None else self.track.native,
            track_kind="perfect"
            if types.flag("perfect_track", self.perfect_track)
            else "synthetic",
            spectrum=types.text("spectrum", self.spectrum),
            seed=track_seed,
            band=(types.real("band", band[0]), types.real("band", band[1])),
            yaw_damper=self.yaw_damper,
            step=types.real("step", self.step),
            output_rate=types.real("output_rate", self.output_rate),
            fastsim_grid=(
                types.whole("fastsim_grid", grid[0], 1, GRID_BOUND),
                types.whole("fastsim_grid", grid[1], 1, GRID_BOUND),
            ),
            creep=types.text("creep", self.creep),
            initial_lateral_offset=types.real(
                "initial_lateral_offset", self.initial_lateral_offset
            ),
            lead_in=types.real("lead_in", self.lead_in),
        )


#: Bound of each grid size before it reaches the core (whose bound, on nx·ny, gives the reason):
#: keeps the conversion to the core's integers from overflowing.
GRID_BOUND = 2**32


def _profile(name: str, value: object) -> Profile:
    """A wheel or rail: a profile or a built-in name."""
    if isinstance(value, str):
        return builtin(value)
    if not isinstance(value, Profile):
        raise types.wrong_type(name, "a loco.profiles.Profile or a built-in name", value)
    return value


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
