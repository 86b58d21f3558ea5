"""Simulating the locomotive: scenarios, a single run and its result.

>>> import loco
>>> scenario = loco.Scenario(name="S_high", speed=200 / 3.6)
>>> result = loco.simulate(loco.Locomotive.default(), scenario)  # doctest: +SKIP
>>> result.metrics[loco.Metric.WY_MAX]  # doctest: +SKIP
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco import field_types as types
from loco.channels import channel_kinds_of
from loco.dampers import Damper
from loco.profiles import Profile
from loco.track import Track
from loco.vehicle import Locomotive

if TYPE_CHECKING:
    import xarray

__all__ = [
    "CREEP_MODELS",
    "RUN_STATISTICS",
    "SCENARIOS",
    "SETTINGS",
    "Scenario",
    "SimulationResult",
    "simulate",
]

FloatArray = npt.NDArray[np.float64]

#: The study's scenarios (SPEC §2): name -> (wheel, rail) built-in profiles (the core's presets).
SCENARIOS: dict[str, tuple[str, str]] = {n: (w, r) for n, w, r in _loco.scenario_presets()}


#: The creep models a scenario accepts (``Scenario(creep=...)``), from the core.
CREEP_MODELS: tuple[str, ...] = tuple(_loco.creep_model_names())

#: The integration schemes a scenario accepts (``Scenario(integrator=...)``), from the core.
INTEGRATORS: tuple[str, ...] = tuple(_loco.integrator_names())

#: Each scheme's default step, s, from the core: a scenario naming a scheme without a ``step``
#: runs at it.
INTEGRATOR_STEPS: dict[str, float] = dict(_loco.integrator_steps())

#: Every setting with a default, at its default, from the core (``ScenarioSettings::defaults``).
_DEFAULTS: dict[str, Any] = {
    k: v for k, v in _loco.scenario_defaults().items() if k not in ("per_sample_track", "speed_kmh")
}

#: Spellings that were replaced, with what to write instead.
_REPLACED = {
    "scenario": 'replaced by `name` (the study file\'s spelling); write name="S_high"',
    "perfect_track": 'replaced by `track`; write track="perfect"',
    "track_kind": 'replaced by `track`; write track="perfect" or track="synthetic"',
    "creep_table": 'replaced by `creep`; write creep="table" (or "fastsim", "fastrip")',
}


class _Setting:
    """A scenario setting: the value the user gave (kept in the instance), else the core's
    default (this class attribute)."""

    def __init__(self, default: Any = None) -> None:
        self.default = default

    def __set_name__(self, owner: type, name: str) -> None:
        self.default = _DEFAULTS.get(name)

    def __get__(self, obj: object, objtype: type | None = None) -> Any:
        return self.default


class _StepSetting(_Setting):
    """The step: the value given, else the default step of the scenario's integrator (the core
    resolves it the same way)."""

    def __get__(self, obj: Any, objtype: type | None = None) -> Any:
        if obj is None:
            return self.default
        return INTEGRATOR_STEPS.get(obj.integrator, self.default)


class Scenario:
    """What a run is: wheel and rail, speed (m/s), distance (m), track, yaw damper, settings.

    Every setting is optional; the ones given are kept and forwarded to the core, which supplies
    the others (:meth:`defaults`, the same defaults and checks as the study file's ``[scenario]``
    section of ``loco-batch``). Reading a setting gives its value, given or default.

    Give either ``name`` (``"S_low"``, ``"S_norm"``, ``"S_high"``: :data:`SCENARIOS`) or
    ``wheel`` (a :class:`loco.profiles.Profile`, a built-in name or a profile file) with an
    optional ``rail`` (default ``cn60``). ``track`` is ``"synthetic"`` (default: synthesised from
    ``spectrum`` — ``"cn-hsr"``, ``"german-low"``, ``"german-high"`` —, ``seed`` and the
    wavelength ``band``, m), ``"perfect"``, a :class:`loco.track.Track` or the path of a measured
    track CSV; ``spectrum``, ``seed`` and ``band`` are refused with any but a synthesised track.
    ``yaw_damper`` is ``"file"`` (the parameter file's Maxwell damper, default), a preset name of
    :data:`loco.dampers.PRESETS` (``"YD1"``, ``"YD2"``, ``"FSD"``, with ``fsd_trigger``
    ``"rms-frequency"`` or ``"hydraulic"``) or a :class:`loco.dampers.Damper`. ``creep`` is the
    creep model (:data:`CREEP_MODELS`): ``"fastsim"``, FASTSIM at every evaluation (the study's
    method, default); ``"fastrip"``, FaStrip (strip theory with spin, closer to Kalker's exact
    theory in the spin moment); or ``"table"``, FASTSIM tabulated once per run or batch: about
    2 % of μN force error for a faster time loop, worth it for large batches (the table takes
    ~0.5 s). ``fastsim_grid`` is the grid of any of them. ``lead_in`` (m) is run before the
    recorded ``distance`` and not recorded, so that start transients (an FSD valve leaving its
    defined start state) settle first; 0 as in the study. ``gauge`` (m), ``gauge_height`` (m below
    the rail top) and ``rail_inclination`` (rad) set the track. ``curve`` is the designed
    alignment the track follows (default: straight): a CSV file of sections or a list of dicts,
    each ``kind`` (``"straight"``, ``"transition"``, ``"curve"``) and ``length_m``; a curve adds
    ``radius_m``, ``cant_mm`` and ``direction`` (``"left"`` or ``"right"``), a transition
    (clothoid, linear cant run-off) may give ``cant_run_off_m``; s = 0 is where the leading
    wheelset starts; irregularities come on top. ``curve=[]`` is refused (leave it out for
    straight track). A run longer than its design continues on straight, level track after the
    last section when the design ends straight (a straight, or a transition, which runs out to
    straight track); beyond a design that ends in a circular curve it is refused naming
    ``distance`` (docs/errors.md). ``integrator`` is the time integration scheme
    (:data:`INTEGRATORS`) with its fixed ``step`` (s; without it the scheme's own,
    :data:`INTEGRATOR_STEPS`): ``"etdrk4"`` (default), RK4's four stages with the gearbox
    bearings' stiff springs and the linear dampers' series springs solved exactly, at 2 ms:
    1.6–1.8 times faster than the reference, within 0.5 % of it in W_y, A_yb and the A_yc PSD
    peak over the study's parameter box on 500 m runs (a step beyond 1 ms is cut to 1 ms while a
    wheelset is more than 3 mm off centre, and not taken at all where it would reduce a damper
    law it cannot solve exactly); or ``"rk4"``, the classical RK4, the reference at 1 ms.
    ``scenario``, ``perfect_track`` and ``creep_table`` were replaced (``name="S_high"``,
    ``track="perfect"``, ``creep="table"``): refused with :class:`loco.ParameterError` saying so.
    """

    name: str | None = _Setting()  # type: ignore[assignment]
    wheel: Profile | str | None = _Setting()  # type: ignore[assignment]
    rail: Profile | str = _Setting()  # type: ignore[assignment]
    speed: float = _Setting()  # type: ignore[assignment]
    distance: float = _Setting()  # type: ignore[assignment]
    lead_in: float = _Setting()  # type: ignore[assignment]
    track: Track | str = _Setting()  # type: ignore[assignment]
    spectrum: str = _Setting()  # type: ignore[assignment]
    seed: int = _Setting()  # type: ignore[assignment]
    band: tuple[float, float] = _Setting()  # type: ignore[assignment]
    yaw_damper: Damper | str = _Setting()  # type: ignore[assignment]
    fsd_trigger: str = _Setting()  # type: ignore[assignment]
    step: float = _StepSetting()  # type: ignore[assignment]
    integrator: str = _Setting()  # type: ignore[assignment]
    output_rate: float = _Setting()  # type: ignore[assignment]
    fastsim_grid: tuple[int, int] = _Setting()  # type: ignore[assignment]
    creep: str = _Setting()  # type: ignore[assignment]
    initial_lateral_offset: float = _Setting()  # type: ignore[assignment]
    gauge: float = _Setting()  # type: ignore[assignment]
    gauge_height: float = _Setting()  # type: ignore[assignment]
    rail_inclination: float = _Setting()  # type: ignore[assignment]
    curve: str | Sequence[Mapping[str, float | str]] | None = _Setting()  # type: ignore[assignment]

    def __init__(
        self,
        name: str | None = None,
        *,
        wheel: Profile | str | None = None,
        rail: Profile | str | None = None,
        speed: float | None = None,
        distance: float | None = None,
        lead_in: float | None = None,
        track: Track | str | None = None,
        spectrum: str | None = None,
        seed: int | None = None,
        band: tuple[float, float] | None = None,
        yaw_damper: Damper | str | None = None,
        fsd_trigger: str | None = None,
        step: float | None = None,
        integrator: str | None = None,
        output_rate: float | None = None,
        fastsim_grid: tuple[int, int] | None = None,
        creep: str | None = None,
        initial_lateral_offset: float | None = None,
        gauge: float | None = None,
        gauge_height: float | None = None,
        rail_inclination: float | None = None,
        curve: str | os.PathLike[str] | Sequence[Mapping[str, float | str]] | None = None,
        **replaced: object,
    ) -> None:
        for old in replaced:
            if old not in _REPLACED:
                raise TypeError(f"Scenario() got an unexpected keyword argument '{old}'")
            raise _loco.ParameterError(f"invalid parameter `{old}`: {_REPLACED[old]}")
        given = {k: v for k, v in locals().items() if k in SETTINGS and v is not None}
        for setting, value in given.items():
            if isinstance(value, list):
                value = tuple(value)
            object.__setattr__(self, setting, value)

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"Scenario is immutable; use replace({name}=...)")

    def given(self) -> dict[str, Any]:
        """The settings the user gave, by name (the others take :meth:`defaults`)."""
        return dict(self.__dict__)

    @staticmethod
    def defaults() -> dict[str, Any]:
        """Every setting that has a default, at its default, from the core (the same as the
        study file's ``[scenario]`` section)."""
        return dict(_DEFAULTS)

    def replace(self, **changes: Any) -> Scenario:
        """A copy with settings changed (None: back to the default)."""
        return Scenario(**{**self.given(), **changes})

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Scenario):
            return NotImplemented
        return self.given() == other.given()

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        """The settings given (speed in m/s, distance in m)."""
        return f"Scenario({', '.join(f'{k}={v!r}' for k, v in self.given().items())})"

    def native(self, *, seed: int | None = None) -> _loco.RunScenario:
        """The checked native scenario (``seed``, when given, replaces the track seed as if the
        user had given it). Raises :class:`loco.ParameterError` naming the field for a
        non-physical or contradictory value."""
        settings: dict[str, Any] = {}
        objects: dict[str, Any] = {}
        given = self.given()
        if seed is not None:
            given["seed"] = seed
        for setting, value in given.items():
            if isinstance(value, (Profile, Damper)):
                objects[setting] = value
            elif isinstance(value, Track):
                objects[setting] = value.native
            elif isinstance(value, os.PathLike):
                settings[setting] = os.fspath(value)
            else:
                check = _CHECKS.get(setting)
                settings[setting] = value if check is None else check(setting, value)
        return _loco.RunScenario(settings, **objects)


#: The settings of a :class:`Scenario`, in the order of its signature.
SETTINGS: tuple[str, ...] = tuple(n for n, v in vars(Scenario).items() if isinstance(v, _Setting))


def _reals(name: str, value: Any) -> tuple[float, float]:
    a, b = types.pair(name, value)
    return types.real(name, a), types.real(name, b)


def _grid(name: str, value: Any) -> tuple[int, int]:
    a, b = types.pair(name, value)
    return types.whole(name, a, 1), types.whole(name, b, 1)


def _name_or_path(name: str, value: Any) -> str:
    """A name (a built-in profile, a preset, ``"synthetic"``/``"perfect"``) or a file path; the
    objects (profiles, dampers, tracks) are passed apart."""
    return types.text(name, value)


def _curve(name: str, value: Any) -> Any:
    """The ``curve`` setting: a CSV path, or the sections with any mapping as a dict (the core
    reads dicts as the study file's ``[[scenario.curve]]`` tables and names a bad field)."""
    if isinstance(value, str):
        return value
    if isinstance(value, bytes) or not isinstance(value, Sequence):
        raise types.wrong_type(name, "a CSV path or a list of sections (dicts)", value)
    return [dict(s) if isinstance(s, Mapping) else s for s in value]


#: The Python type check of each plain setting (:mod:`loco.field_types`), before the core checks
#: its value: a wrong type is a :class:`loco.ParameterError` naming the field, never a silent
#: conversion (``True`` as 1, ``1.5`` as 1, a complex number's real part).
_CHECKS: dict[str, Any] = {
    **{
        n: types.real
        for n in (
            "speed",
            "distance",
            "lead_in",
            "step",
            "output_rate",
            "initial_lateral_offset",
            "gauge",
            "gauge_height",
            "rail_inclination",
        )
    },
    "seed": types.whole,
    "band": _reals,
    "fastsim_grid": _grid,
    **{
        n: _name_or_path
        for n in (
            "name",
            "spectrum",
            "creep",
            "integrator",
            "fsd_trigger",
            "wheel",
            "rail",
            "track",
            "yaw_damper",
        )
    },
    "curve": _curve,
}


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
    #: The kind (a :class:`loco.ChannelKind`) of each channel, by name (empty when not known).
    channel_kinds: dict[str, str] = field(default_factory=dict, repr=False)

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

    def channels_of_kind(self, kind: str) -> list[str]:
        """Names of the channels of kind ``kind`` (a :class:`loco.ChannelKind`), in order."""
        return [n for n in self.channel_names if self.channel_kinds.get(n) == kind]

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
        vehicle.native,
        scenario.native(),
    )
    return SimulationResult(
        time=time,
        channel_names=list(names),
        channels=channels,
        metrics=dict(zip(metric_names, metric_values.tolist(), strict=True)),
        sampling_rate=float(scenario.output_rate),
        parameters={"speed": scenario.speed, "distance": scenario.distance},
        statistics=dict(statistics),
        channel_kinds=channel_kinds_of(vehicle.native),
    )
