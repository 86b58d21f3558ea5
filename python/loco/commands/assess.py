"""``loco assess DIR``: the EN 14363 / EN 12299 assessment of a run ``loco simulate`` wrote.

Reads the run back (:func:`loco.simulation_output.load_result`: its channels, metrics and the
scenario as run, whose vehicle file, speed, lead-in and designed curve place the zones and set
the limits), assesses it with :func:`loco.assess` and writes ``assessment.csv`` (one row per
quantity: value, limit, unit, pass/fail, the limit's source) and ``assessment.png`` (each value
over its limit) beside the run, or into ``--out``.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import loco
from loco.assessment import VEHICLE_CLASSES, Quantity
from loco.commands.arguments import output_dir
from loco.simulation_output import load_result

NAME = "assess"
HELP = "EN 14363 / EN 12299 assessment of a `loco simulate` output directory (table and figure)"
#: The files the command writes.
TABLE = "assessment.csv"
FIGURE = "assessment.png"


def _directory(text: str) -> Path:
    path = Path(text)
    if not path.is_dir():
        raise argparse.ArgumentTypeError(f"no such directory: {text!r}")
    return path


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("directory", type=_directory, help="output directory of `loco simulate`")
    parser.add_argument(
        "--out", type=Path, default=None, help="where to write the table and figure (default: DIR)"
    )
    parser.add_argument(
        "--vehicle-class",
        choices=sorted(VEHICLE_CLASSES),
        default="locomotive",
        help="vehicle class of the ΣY limit's α (default locomotive)",
    )
    parser.add_argument("--no-figure", action="store_true", help="write no figure")


def _line(q: Quantity) -> str:
    verdict = {True: "pass", False: "FAIL", None: "—"}[q.passed]
    limit = f"{q.limit:.4g}" if math.isfinite(q.limit) else "no limit"
    note = f"  ({q.note})" if q.note else ""
    return (
        f"  {q.zone:<20} {q.quantity:<46} {q.value:>11.4g} / {limit:<9} {q.unit:<5} {verdict}{note}"
    )


def run(args: argparse.Namespace) -> int:
    result, record = load_result(args.directory)
    scenario = record["scenario"]
    vehicle = (
        loco.Locomotive.default()
        if record.get("vehicle") is None
        else loco.Locomotive.from_toml(record["vehicle"])
    )
    found = loco.assess(
        result,
        vehicle,
        curve=scenario.get("curve"),
        lead_in=float(scenario.get("lead_in", 0.0)),
        vehicle_class=args.vehicle_class,
    )
    out = output_dir(args.out or args.directory)
    found.frame().to_csv(out / TABLE, index=False, float_format="%.6g")
    written = [out / TABLE]
    if not args.no_figure:
        written.append(found.figure(out / FIGURE))
    print(f"EN 14363 / EN 12299 assessment of {args.directory} (limits from secondary sources):")
    for q in found.quantities:
        print(_line(q))
    print(("every assessed quantity passes" if found.passed() else "some quantities FAIL") + ";")
    print(f"wrote {', '.join(str(p) for p in written)}")
    return 0
