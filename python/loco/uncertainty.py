"""Input uncertainty: the plausible range of every uncertain input and which of them matter.

:func:`ranges` lists each input's range as the core reads it from a ranges file (the embedded
``default_uncertainty.toml`` or a user's): a tolerance on a value the SPEC gives, or the range an
estimate or a scaling from another vehicle leaves open, with its reasoning and source.
:func:`morris` screens them (Morris elementary effects, SALib) on the linearised vehicle: the
damping of the carbody mode on S_low and of the bogie mode on S_high with each fixed yaw damper
(:meth:`loco.stability.Eigen.carbody_mode`, :meth:`~loco.stability.Eigen.bogie_mode`) and the
linear critical speeds. :func:`plot_morris` draws μ* against σ.
"""

from __future__ import annotations

import concurrent.futures
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
from threadpoolctl import threadpool_limits

from loco import _loco
from loco.dampers import PRESETS, Damper, maxwell
from loco.elementary_effects import elementary_effects, plot_morris
from loco.profiles import jm3
from loco.schema import parameter_schema
from loco.simulation import SCENARIOS, Scenario
from loco.stability import critical_speed, eigen
from loco.vehicle import Locomotive

__all__ = [
    "OUTPUTS",
    "PRESET_DAMPER_KEYS",
    "Output",
    "analyse",
    "evaluate",
    "morris",
    "plot_morris",
    "ranges",
    "screened_inputs",
]

#: Columns of :func:`ranges`.
RANGE_COLUMNS = ("key", "nominal", "low", "high", "unit", "kind", "why", "source")


def ranges(vehicle: Locomotive | None = None, file: str | Path | None = None) -> pd.DataFrame:
    """Every ranged input of ``vehicle`` (default: the default vehicle) with its nominal value,
    range (``low``, ``high``, SI), ``unit``, ``kind`` (``tolerance``, ``scaling``,
    ``estimate``), reasoning (``why``) and ``source``, from the ranges file ``file`` (default:
    the embedded one). Keys are vehicle parameters, ``scenario.rail_inclination`` and
    ``wheel.<built-in JM3 wheel>.<field>`` (the construction parameters of
    :func:`loco.profiles.jm3`). A bad range (unknown key, empty or reversed, outside the
    parameter's validity, not containing the vehicle's value) raises
    :class:`loco.ParameterError` naming the key, the file and the line."""
    vehicle = vehicle or Locomotive.default()
    if file is None:
        rows = _loco.input_ranges(vehicle.native)
    else:
        path = Path(file)
        try:
            text = path.read_text(encoding="utf-8")
        except OSError as e:
            raise _loco.LocoIOError(f"cannot access `{path}`: {e}") from e
        rows = _loco.input_ranges(vehicle.native, text, str(path))
    return pd.DataFrame(rows, columns=list(RANGE_COLUMNS))


@dataclass(frozen=True)
class Output:
    """One screened output: a mode's damping ratio (``quantity`` ``"carbody_zeta"`` or
    ``"bogie_zeta"``, –) or the linear critical speed (``"critical_speed"``, m/s) of the vehicle
    on ``scenario`` at 200 km/h with the yaw damper preset ``damper``."""

    name: str
    scenario: str
    damper: str
    quantity: str


#: The outputs :func:`morris` can screen, by name.
OUTPUTS: dict[str, Output] = {
    o.name: o
    for o in (
        Output("S_low_carbody_zeta_YD1", "S_low", "YD1", "carbody_zeta"),
        Output("S_low_carbody_zeta_YD2", "S_low", "YD2", "carbody_zeta"),
        Output("S_high_bogie_zeta_YD1", "S_high", "YD1", "bogie_zeta"),
        Output("S_high_bogie_zeta_YD2", "S_high", "YD2", "bogie_zeta"),
        Output("S_low_critical_speed_YD2", "S_low", "YD2", "critical_speed"),
        Output("S_high_critical_speed_YD1", "S_high", "YD1", "critical_speed"),
    )
}

#: The study speed of the screened eigen analyses, m/s.
SPEED = 200 / 3.6

#: The built-in wheel of each scenario the outputs use (the core's presets).
_SCENARIO_WHEELS = {name: wheel for name, (wheel, _rail) in SCENARIOS.items()}

#: The built-in JM3 wheels' construction parameters (:func:`loco.profiles.jm3`), from the core.
_JM3_STATES = {
    name: {"tread_slope": slope, "band_radius": band, "flange_thickness": flange}
    for name, slope, band, flange in _loco.jm3_builtin_states()
}


def screened_inputs(
    table: pd.DataFrame, outputs: Sequence[str], vehicle: Locomotive | None = None
) -> pd.DataFrame:
    """The rows of a :func:`ranges` table that can change ``outputs``: not the parameters that
    only set where metrics are measured (the schema's ``affects`` is ``metrics`` alone), not the
    wheels of scenarios no output uses."""
    schema = parameter_schema()
    used = {_SCENARIO_WHEELS[OUTPUTS[o].scenario] for o in outputs}

    def keep(key: str) -> bool:
        if key.startswith("wheel."):
            return key.split(".")[1] in used
        if key in schema:
            return set(schema[key].affects) != {"metrics"}
        return True

    return table[[keep(k) for k in table["key"]]].reset_index(drop=True)


def _checked_outputs(outputs: Iterable[str]) -> list[str]:
    out = list(outputs)
    for name in out:
        if name not in OUTPUTS:
            raise _loco.ParameterError(
                f"invalid parameter `outputs`: unknown output `{name}` (known: "
                f"{', '.join(OUTPUTS)})"
            )
    if not out:
        raise _loco.ParameterError("invalid parameter `outputs`: no output given")
    return out


def evaluate(
    vehicle: Locomotive,
    keys: Sequence[str],
    values: Sequence[float],
    outputs: Sequence[str],
    guesses: dict[str, float] | None = None,
) -> list[float]:
    """The ``outputs`` of ``vehicle`` with the inputs ``keys`` set to ``values`` (vehicle
    parameters as overrides, ``scenario.rail_inclination`` on every scenario, a JM3 wheel's
    field on the scenarios that run on it). The yaw damper's damping and series stiffness are
    tolerances on a given damper: an output with a preset damper (YD1, YD2) takes the preset
    scaled by the same factor as the file's damper (value over the file's nominal), since the
    preset replaces the file's damper in that scenario. A critical speed named in ``guesses``
    (m/s, such as the nominal vehicle's) starts its search there (:func:`loco.critical_speed`'s
    ``guess``: the same speed within its tolerance, in about half the time). An output the
    model cannot give (no mode passes the rule, no equilibrium, no JM3 tread for the wheel's
    construction values) is NaN; a vehicle stable up to the critical speed search's upper limit
    (110 m/s) takes that limit as its critical speed (censored)."""
    overrides: dict[str, float] = {}
    scenario_settings: dict[str, Any] = {}
    wheels: dict[str, dict[str, float]] = {}
    for key, value in zip(keys, values, strict=True):
        if key == "scenario.rail_inclination":
            scenario_settings["rail_inclination"] = float(value)
        elif key.startswith("wheel."):
            _, wheel, field = key.split(".")
            wheels.setdefault(wheel, dict(_JM3_STATES[wheel]))[field] = float(value)
        else:
            overrides[key] = float(value)
    damper_factors = _yaw_damper_factors(vehicle, overrides)
    varied = vehicle.replace(overrides)
    out = []
    with threadpool_limits(limits=1):
        for name in outputs:
            o = OUTPUTS[name]
            settings = dict(scenario_settings)
            wheel = _SCENARIO_WHEELS[o.scenario]
            if wheel in wheels:
                try:
                    settings["wheel"] = jm3(**wheels[wheel])
                except _loco.ParameterError:
                    # The ranges are per field: a corner of them can give no JM3 tread (the
                    # band and the flange root overlap); the model has no vehicle there.
                    out.append(math.nan)
                    continue
                settings["rail"] = SCENARIOS[o.scenario][1]
            else:
                settings["name"] = o.scenario
            damper = _scaled_preset(o.damper, damper_factors)
            scenario = Scenario(speed=SPEED, yaw_damper=damper, **settings)
            out.append(_output(varied, scenario, o.quantity, (guesses or {}).get(name)))
    return out


#: The file's yaw damper keys a preset damper takes as factors, with the preset's field.
PRESET_DAMPER_KEYS = {
    "secondary.yaw_damper_damping": "damping",
    "secondary.yaw_damper_series_stiffness": "series_stiffness",
}


def _yaw_damper_factors(vehicle: Locomotive, overrides: dict[str, float]) -> dict[str, float]:
    """Each overridden yaw damper key's value over the vehicle's own, by the preset's field."""
    return {
        field: overrides[key] / vehicle[key]
        for key, field in PRESET_DAMPER_KEYS.items()
        if key in overrides
    }


def _scaled_preset(name: str, factors: dict[str, float]) -> Damper | str:
    """The preset damper ``name`` with its fields scaled by ``factors`` (the name itself when
    none is)."""
    if not factors:
        return name
    preset = PRESETS[name].parameters()
    return maxwell(
        float(preset["damping"] or 0.0) * factors.get("damping", 1.0),
        float(preset["series_stiffness"] or 0.0) * factors.get("series_stiffness", 1.0),
    )


def _output(
    vehicle: Locomotive, scenario: Scenario, quantity: str, guess: float | None = None
) -> float:
    try:
        if quantity == "critical_speed":
            speed = critical_speed(vehicle, scenario, guess=guess)
            # Stable up to the search limit: the speed is censored there (the limit, not inf).
            return speed.limit if speed.outcome == "stable_at_high" else float(speed)
        modes = eigen(vehicle, scenario)
        mode = modes.carbody_mode() if quantity == "carbody_zeta" else modes.bogie_mode()
        return mode.damping_ratio
    except (_loco.ParameterError, _loco.EquilibriumError):
        return math.nan


def _evaluate_trajectory(
    args: tuple[Locomotive, list[str], list[list[float]], list[str], dict[str, float]],
) -> list[list[float]]:
    """The outputs of one Morris trajectory's points, in order: each point's critical speeds
    start from the previous point's (one input apart: close), the first from ``guesses``."""
    vehicle, keys, points, names, guesses = args
    out = []
    guess = dict(guesses)
    for values in points:
        row = evaluate(vehicle, keys, values, names, guess)
        guess.update(
            (n, v) for n, v in zip(names, row, strict=True) if n in guess and math.isfinite(v)
        )
        out.append(row)
    return out


def _problem(table: pd.DataFrame) -> dict[str, Any]:
    """The SALib problem of a :func:`screened_inputs` table: each input uniform over its range."""
    return {
        "num_vars": len(table),
        "names": list(table["key"]),
        "bounds": [[lo, hi] for lo, hi in zip(table["low"], table["high"], strict=True)],
    }


def morris_samples(
    vehicle: Locomotive | None = None,
    outputs: Iterable[str] = tuple(OUTPUTS),
    trajectories: int = 20,
    seed: int = 0,
    levels: int = 4,
    ranges_file: str | Path | None = None,
) -> np.ndarray:
    """The points :func:`morris` evaluates with these settings, one row per point (columns:
    the inputs of :func:`screened_inputs`, SI), ``trajectories`` runs of ``inputs + 1`` points."""
    from SALib.sample import morris as sample

    if not (isinstance(trajectories, int) and trajectories >= 2):
        raise _loco.ParameterError(
            f"invalid parameter `trajectories`: must be a whole number ≥ 2, got {trajectories!r}"
        )
    table = screened_inputs(ranges(vehicle, ranges_file), _checked_outputs(outputs))
    x: np.ndarray = sample.sample(_problem(table), trajectories, num_levels=levels, seed=seed)
    return x


def morris(
    vehicle: Locomotive | None = None,
    outputs: Iterable[str] = tuple(OUTPUTS),
    trajectories: int = 20,
    seed: int = 0,
    executor: concurrent.futures.Executor | None = None,
    progress: bool = True,
    *,
    levels: int = 4,
    ranges_file: str | Path | None = None,
    on_row: Callable[[int, list[float]], None] | None = None,
    known: Mapping[int, Sequence[float]] | None = None,
) -> pd.DataFrame:
    """Morris screening (SALib, ``levels``-level grid, ``trajectories`` trajectories from
    ``seed``) of every input of :func:`ranges` that can change ``outputs`` (see
    :func:`screened_inputs`), each uniform over its range, on the outputs named in
    :data:`OUTPUTS`. Returns one row per input and output: ``mu_star`` (mean absolute
    elementary effect, in the output's unit for a step across the whole range), ``mu``,
    ``sigma`` (their spread: interactions and nonlinearity), ``mu_star_conf`` (95 % bootstrap),
    and ``effects`` (the steps that gave one: a step touching a point with a NaN output, where
    the rule picks no mode, gives none; :mod:`loco.elementary_effects`). ``executor`` is any
    :class:`concurrent.futures.Executor` (a process
    pool, or ``distributed.Client.get_executor()`` for a Dask cluster); default: this process,
    one trajectory after the other (a trajectory is one task: its points run in order, each
    critical speed searched from the previous point's). Results are the same whichever executor
    runs the trajectories. ``on_row(i, outputs)`` receives each point's outputs as its trajectory
    finishes; ``known`` holds outputs of earlier runs by point index (as ``on_row`` gave them):
    a trajectory whose points are all known is not evaluated again (a resumed screening)."""
    vehicle = vehicle or Locomotive.default()
    names = _checked_outputs(outputs)
    table = screened_inputs(ranges(vehicle, ranges_file), names)
    keys = list(table["key"])
    x = morris_samples(vehicle, names, trajectories, seed, levels, ranges_file)
    # The nominal vehicle's critical speeds start each sample's search (same result within
    # the search's tolerance, in about half the linearisations).
    nominal = evaluate(vehicle, keys, [float(v) for v in table["nominal"]], names)
    guesses = {
        n: v
        for n, v in zip(names, nominal, strict=True)
        if OUTPUTS[n].quantity == "critical_speed" and math.isfinite(v)
    }
    per = len(keys) + 1
    points = [[float(v) for v in row] for row in x]
    known = known or {}
    todo = [
        t for t in range(trajectories) if any(i not in known for i in range(t * per, (t + 1) * per))
    ]
    tasks = [(vehicle, keys, points[t * per : (t + 1) * per], names, guesses) for t in todo]
    done: Iterable[list[list[float]]]
    if executor:
        done = executor.map(_evaluate_trajectory, tasks)
    else:
        done = map(_evaluate_trajectory, tasks)
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=len(points), desc="morris", unit="sample")
    y = np.full((len(points), len(names)), np.nan)
    for i, values in known.items():
        if 0 <= i < len(points):
            y[i] = values
    if bar is not None:
        bar.update(len(points) - len(todo) * per)
    for t, rows in zip(todo, done, strict=True):
        for k, values in enumerate(rows):
            y[t * per + k] = values
            if on_row is not None:
                on_row(t * per + k, values)
        if bar is not None:
            bar.update(len(rows))
    if bar is not None:
        bar.close()
    return analyse(table, x, y, names, seed)


def analyse(
    table: pd.DataFrame, x: np.ndarray, y: np.ndarray, outputs: Sequence[str], seed: int = 0
) -> pd.DataFrame:
    """The screening table of :func:`morris` from its points ``x`` (the inputs of ``table``,
    :func:`screened_inputs`) and outputs ``y`` (one column per output, NaN where the model
    gives none): :func:`loco.elementary_effects.elementary_effects` per output."""
    frames = []
    for j, name in enumerate(outputs):
        frame = elementary_effects(
            x, y[:, j], table["low"], table["high"], list(table["key"]), seed=seed
        )
        frame.insert(0, "output", name)
        frames.append(frame)
    return pd.concat(frames, ignore_index=True)
