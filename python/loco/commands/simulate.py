"""``loco simulate``: one run from files, its time histories, metrics, statistics and figures.

The vehicle is the embedded one or a vehicle TOML file; the wheel and rail a study scenario or
profiles; the track synthetic, perfect or a measured CSV, optionally on a designed curve (a
sections CSV). What the run writes into ``--out`` is described in
:mod:`loco.simulation_output` and in the command's help.
"""

from __future__ import annotations

import argparse
import sys
import threading
import time
from pathlib import Path
from typing import Any

import loco
from loco import dampers
from loco.channels import channel_table, metric_table
from loco.commands.arguments import (
    UsageError,
    add_integrator_argument,
    existing_file,
    finite_float,
    non_negative_int,
    output_dir,
    positive_float,
)
from loco.simulation import SCENARIOS, Scenario, SimulationResult
from loco.simulation_output import write_simulation

NAME = "simulate"
HELP = "one run from files: time histories (NetCDF, Parquet), metrics and statistics, figures"

#: Yaw dampers ``--yaw-damper`` takes: the vehicle file's own damper or a preset label.
YAW_DAMPERS: tuple[str, ...] = ("file", *sorted(dampers.PRESETS), "FSD-H")
#: Highest ``--speed`` (km/h), the core's bound on a run's speed.
MAX_SPEED_KMH = 400.0
#: A run that takes longer than this (s) prints its elapsed time while it runs.
PROGRESS_AFTER_S = 2.0

EPILOG = """\
output files in --out DIR:
  histories.nc       NetCDF-4: every channel on a time coordinate (s), each with its SI units
                     and kind; the metrics as attributes (read with loco.simulation_output
                     .load_histories or xarray.open_dataset)
  histories.parquet  the same table: a time column (s) and one column per channel
  metrics.json       {"metrics": {name: value}, "units": {name: unit}}; null where undefined
  run.json           loco version, vehicle file, every scenario setting as run (speed in m/s),
                     run statistics (evaluations, steps, Newton iterations, wall time in s),
                     channels (name, unit, kind) and the files written
  accelerations.png  carbody floor and bogie frame accelerations (m/s²)
  wheelsets.png      wheelset lateral displacements (mm) and yaw angles (mrad)
  curving.png        Y/Q and ΔQ/Q of every wheel (only with --curve)
"""


def _speed_kmh(text: str) -> float:
    v = positive_float(text)
    if v > MAX_SPEED_KMH:
        raise argparse.ArgumentTypeError(f"must be <= {MAX_SPEED_KMH:g} km/h, got {text!r}")
    return v


def _track(text: str) -> str:
    if text in ("synthetic", "perfect"):
        return text
    return str(existing_file(text))


def _lead_in(text: str) -> float:
    x = finite_float(text)
    if x < 0.0:
        raise argparse.ArgumentTypeError(f"must be >= 0, got {text!r}")
    return x


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.epilog = EPILOG
    parser.add_argument("--out", type=Path, default=Path("out/simulate"), help="output directory")
    parser.add_argument(
        "--vehicle", type=existing_file, default=None, help="vehicle TOML file (default: embedded)"
    )
    wheel_rail = parser.add_mutually_exclusive_group()
    wheel_rail.add_argument(
        "--scenario",
        choices=list(SCENARIOS),
        default=None,
        help="study scenario: its wheel and rail (default S_high unless --wheel is given)",
    )
    wheel_rail.add_argument(
        "--wheel", default=None, help="wheel: a built-in profile name or a profile file"
    )
    parser.add_argument(
        "--rail", default=None, help="rail with --wheel: a built-in name or a profile file"
    )
    speed = Scenario.defaults()["speed"] * 3.6
    parser.add_argument(
        "--speed",
        type=_speed_kmh,
        default=speed,
        help=f"running speed in km/h (default {speed:g} km/h)",
    )
    distance = Scenario.defaults()["distance"]
    parser.add_argument(
        "--distance",
        type=positive_float,
        default=distance,
        help=f"recorded distance in m (default {distance:g} m)",
    )
    parser.add_argument(
        "--lead-in", type=_lead_in, default=0.0, help="distance run before the record, m"
    )
    parser.add_argument(
        "--track",
        type=_track,
        default="synthetic",
        help="synthetic (default), perfect, or a measured track CSV (distance in m, then "
        "vertical, alignment, cross_level, gauge in mm)",
    )
    parser.add_argument(
        "--spectrum", default=None, help="spectrum of a synthetic track (default cn-hsr)"
    )
    parser.add_argument("--seed", type=non_negative_int, default=None, help="synthetic track seed")
    parser.add_argument(
        "--curve", type=existing_file, default=None, help="designed alignment: a sections CSV"
    )
    parser.add_argument(
        "--yaw-damper",
        choices=YAW_DAMPERS,
        default="file",
        help="yaw damper: the vehicle file's own (default) or a preset",
    )
    add_integrator_argument(parser)
    parser.add_argument("--no-figures", action="store_true", help="write no figures")


def _scenario(args: argparse.Namespace) -> Scenario:
    if args.rail is not None and args.wheel is None:
        raise UsageError("argument --rail: needs --wheel (a --scenario has its own rail)")
    synthetic = args.track == "synthetic"
    for option, value in (("--spectrum", args.spectrum), ("--seed", args.seed)):
        if value is not None and not synthetic:
            raise UsageError(f"argument {option}: only with a synthetic track")
    settings: dict[str, Any] = {
        "speed": args.speed / 3.6,
        "distance": args.distance,
        "lead_in": args.lead_in,
        "track": args.track,
        "integrator": args.integrator,
    }
    if args.wheel is not None:
        settings["wheel"] = args.wheel
        if args.rail is not None:
            settings["rail"] = args.rail
    else:
        settings["name"] = args.scenario or "S_high"
    if args.spectrum is not None:
        settings["spectrum"] = args.spectrum
    if args.seed is not None:
        settings["seed"] = args.seed
    if args.curve is not None:
        settings["curve"] = str(args.curve)
    if args.yaw_damper == "FSD-H":
        settings.update(yaw_damper="FSD", fsd_trigger="hydraulic")
    else:
        settings["yaw_damper"] = args.yaw_damper
    scenario = Scenario(**settings)
    scenario.native()  # the core's checks of every setting, before any work
    return scenario


def _simulate(vehicle: loco.Locomotive, scenario: Scenario) -> SimulationResult:
    """``loco.simulate``, printing the elapsed time on stderr while a long run lasts."""
    done = threading.Event()
    start = time.perf_counter()

    def report() -> None:
        while not done.wait(PROGRESS_AFTER_S):
            print(f"  running … {time.perf_counter() - start:.0f} s", file=sys.stderr, flush=True)

    ticker = threading.Thread(target=report, daemon=True)
    ticker.start()
    try:
        return loco.simulate(vehicle, scenario)
    finally:
        done.set()
        ticker.join()


def run(args: argparse.Namespace) -> int:
    scenario = _scenario(args)
    out = output_dir(args.out)
    vehicle = (
        loco.Locomotive.default()
        if args.vehicle is None
        else loco.Locomotive.from_toml(args.vehicle)
    )
    settings = {**Scenario.defaults(), **scenario.given()}
    wheel_rail = settings.get("name") or f"{settings['wheel']} on {settings['rail']}"
    print(
        f"simulating {wheel_rail}: {scenario.distance:g} m at {scenario.speed * 3.6:g} km/h "
        f"({scenario.distance / scenario.speed:.1f} s of running), track {scenario.track}, "
        f"yaw damper {args.yaw_damper}"
    )
    result = _simulate(vehicle, scenario)
    stats = result.statistics
    print(
        f"done in {stats['wall_time']:.2f} s: {int(stats['steps'])} steps, "
        f"{int(stats['rhs_evaluations'])} force evaluations, "
        f"{len(result.time)} samples at {result.sampling_rate:g} Hz"
    )
    record = {
        "vehicle": None if args.vehicle is None else str(args.vehicle),
        "scenario": settings,
        "yaw_damper_label": args.yaw_damper,
    }
    written = write_simulation(
        result,
        channel_table(vehicle.native),
        out,
        run_record=record,
        curved=args.curve is not None,
        figures=not args.no_figures,
    )
    units = {m.name: m.unit for m in metric_table()}
    for key in ("wy_max", "ayc_peak", "ayb_peak_lp", "ayb_f0_hz"):
        if key in result.metrics:
            print(f"  {key}: {result.metrics[key]:.4g} {units[key]}")
    print(f"wrote {len(written.files)} files into {out}")
    return 0
