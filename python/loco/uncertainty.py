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
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
from threadpoolctl import threadpool_limits

from loco import _loco
from loco.profiles import jm3
from loco.schema import parameter_schema
from loco.simulation import SCENARIOS, Scenario
from loco.stability import critical_speed, eigen
from loco.vehicle import Locomotive

__all__ = [
    "OUTPUTS",
    "Output",
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
    vehicle: Locomotive, keys: Sequence[str], values: Sequence[float], outputs: Sequence[str]
) -> list[float]:
    """The ``outputs`` of ``vehicle`` with the inputs ``keys`` set to ``values`` (vehicle
    parameters as overrides, ``scenario.rail_inclination`` on every scenario, a JM3 wheel's
    field on the scenarios that run on it). An output the model cannot give (no mode passes
    the rule, no equilibrium) is NaN."""
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
    varied = vehicle.replace(overrides)
    out = []
    with threadpool_limits(limits=1):
        for name in outputs:
            o = OUTPUTS[name]
            settings = dict(scenario_settings)
            wheel = _SCENARIO_WHEELS[o.scenario]
            if wheel in wheels:
                settings["wheel"] = jm3(**wheels[wheel])
                settings["rail"] = SCENARIOS[o.scenario][1]
            else:
                settings["name"] = o.scenario
            scenario = Scenario(speed=SPEED, yaw_damper=o.damper, **settings)
            out.append(_output(varied, scenario, o.quantity))
    return out


def _output(vehicle: Locomotive, scenario: Scenario, quantity: str) -> float:
    try:
        if quantity == "critical_speed":
            return float(critical_speed(vehicle, scenario))
        modes = eigen(vehicle, scenario)
        mode = modes.carbody_mode() if quantity == "carbody_zeta" else modes.bogie_mode()
        return mode.damping_ratio
    except (_loco.ParameterError, _loco.EquilibriumError):
        return math.nan


def _evaluate_row(args: tuple[Locomotive, list[str], list[float], list[str]]) -> list[float]:
    return evaluate(*args)


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
) -> pd.DataFrame:
    """Morris screening (SALib, ``levels``-level grid, ``trajectories`` trajectories from
    ``seed``) of every input of :func:`ranges` that can change ``outputs`` (see
    :func:`screened_inputs`), each uniform over its range, on the outputs named in
    :data:`OUTPUTS`. Returns one row per input and output: ``mu_star`` (mean absolute
    elementary effect, in the output's unit for a step across the whole range), ``mu``,
    ``sigma`` (their spread: interactions and nonlinearity), ``mu_star_conf`` (95 % bootstrap),
    and ``trajectories_used``; a trajectory with a NaN output (the rule picks no mode there) is
    left out of that output. ``executor`` is any :class:`concurrent.futures.Executor` (a process
    pool, or ``distributed.Client.get_executor()`` for a Dask cluster); default: this process,
    one row after the other. Results are the same whichever executor runs the rows."""
    from SALib.analyze import morris as analyze
    from SALib.sample import morris as sample

    vehicle = vehicle or Locomotive.default()
    names = _checked_outputs(outputs)
    if not (isinstance(trajectories, int) and trajectories >= 2):
        raise _loco.ParameterError(
            f"invalid parameter `trajectories`: must be a whole number ≥ 2, got {trajectories!r}"
        )
    table = screened_inputs(ranges(vehicle, ranges_file), names)
    keys = list(table["key"])
    problem = {
        "num_vars": len(keys),
        "names": keys,
        "bounds": [[lo, hi] for lo, hi in zip(table["low"], table["high"], strict=True)],
    }
    x = sample.sample(problem, trajectories, num_levels=levels, seed=seed)
    tasks = [(vehicle, keys, [float(v) for v in row], names) for row in x]
    rows: Iterable[list[float]]
    rows = executor.map(_evaluate_row, tasks) if executor else map(_evaluate_row, tasks)
    if progress:
        from tqdm import tqdm

        rows = tqdm(rows, total=len(tasks), desc="morris", unit="sample")
    y = np.full((len(tasks), len(names)), np.nan)
    for i, values in enumerate(rows):
        y[i] = values
        if on_row is not None:
            on_row(i, values)
    per = len(keys) + 1
    frames = []
    for j, name in enumerate(names):
        complete = np.isfinite(y[:, j].reshape(trajectories, per)).all(axis=1)
        used = np.repeat(complete, per)
        result = analyze.analyze(
            problem, x[used], y[used, j], num_levels=levels, seed=seed, print_to_console=False
        )
        frames.append(
            pd.DataFrame(
                {
                    "output": name,
                    "input": keys,
                    "mu_star": result["mu_star"],
                    "mu": result["mu"],
                    "sigma": result["sigma"],
                    "mu_star_conf": result["mu_star_conf"],
                    "trajectories_used": int(complete.sum()),
                }
            )
        )
    return pd.concat(frames, ignore_index=True)


def plot_morris(result: pd.DataFrame, top: int = 5, path: str | Path | None = None) -> Any:
    """μ* against σ per output (one panel each) of a :func:`morris` table, the ``top`` inputs
    of each labelled; saved to ``path`` when given. Returns the matplotlib figure."""
    import matplotlib

    if path is not None:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = list(dict.fromkeys(result["output"]))
    cols = min(len(names), 3)
    rows = math.ceil(len(names) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(5.2 * cols, 4.2 * rows), squeeze=False)
    for ax, name in zip(axes.flat, names, strict=False):
        part = result[result["output"] == name].sort_values("mu_star", ascending=False)
        ax.scatter(part["mu_star"], part["sigma"], s=12, color="0.5")
        for _, r in part.head(top).iterrows():
            ax.scatter([r["mu_star"]], [r["sigma"]], s=18, color="C3")
            ax.annotate(r["input"], (r["mu_star"], r["sigma"]), fontsize=7)
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("μ*")
        ax.set_ylabel("σ")
    for ax in list(axes.flat)[len(names) :]:
        ax.set_visible(False)
    fig.tight_layout()
    if path is not None:
        fig.savefig(path, dpi=130)
    return fig
