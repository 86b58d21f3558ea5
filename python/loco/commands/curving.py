"""``loco curving``: YD1, YD2 and the FSD in designed curves, assessed as EN 14363 does.

Runs every curve of :data:`loco.studies.curving.CURVES` (or the ``--radius`` ones) at the speeds
giving the ``--deficiency`` cant deficiencies, on perfect track (``--irregular``: S_norm
irregularities with ``--seed``), and writes ``curving.csv``, ``curving.png`` and
``curving.json`` into ``--out`` (see :func:`loco.studies.curving.save_curving`).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from loco.commands.arguments import (
    UsageError,
    add_integrator_argument,
    non_negative_int,
    output_dir,
    positive_int,
)
from loco.studies import curving
from loco.studies.stages import Runtime

NAME = "curving"
HELP = "ΣY, Y/Q and Y_qst of YD1, YD2 and the FSD in curves against cant deficiency (EN 14363)"


def _float_list(text: str) -> list[float]:
    try:
        values = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"not a comma-separated list of numbers: {text!r}"
        ) from None
    if not values or any(v != v for v in values):
        raise argparse.ArgumentTypeError(f"not a comma-separated list of numbers: {text!r}")
    return values


def add_arguments(parser: argparse.ArgumentParser) -> None:
    radii = ",".join(f"{c.radius_m:g}" for c in curving.CURVES)
    parser.add_argument("--out", type=Path, default=Path("out/curving"), help="output dir")
    parser.add_argument(
        "--radius",
        type=_float_list,
        default=None,
        help=f"curves to run, a subset of the study's radii {radii} m (default: all)",
    )
    parser.add_argument(
        "--deficiency",
        type=_float_list,
        default=list(curving.CANT_DEFICIENCIES_MM),
        help="cant deficiencies, mm (default: "
        + ",".join(f"{d:g}" for d in curving.CANT_DEFICIENCIES_MM)
        + ")",
    )
    parser.add_argument(
        "--lead-in",
        type=float,
        default=curving.LEAD_IN,
        help=f"straight run before the record, m (default {curving.LEAD_IN:g})",
    )
    parser.add_argument("--irregular", action="store_true", help="S_norm irregularities on top")
    parser.add_argument("--seed", type=non_negative_int, default=0, help="track seed")
    parser.add_argument("--threads", type=positive_int, default=None, help="threads")
    add_integrator_argument(parser)


def run(args: argparse.Namespace) -> int:
    output_dir(args.out)
    curves = list(curving.CURVES)
    if args.radius is not None:
        known = {c.radius_m: c for c in curving.CURVES}
        unknown = [r for r in args.radius if r not in known]
        if unknown:
            raise UsageError(f"--radius {unknown}: the study's curves are {sorted(known)} m")
        curves = [known[r] for r in args.radius]
    if any(not 0.0 <= d <= 200.0 for d in args.deficiency):
        raise UsageError(f"--deficiency {args.deficiency}: each must be within 0–200 mm")
    if not 0.0 <= args.lead_in <= 5000.0:
        raise UsageError(f"--lead-in {args.lead_in}: must be within 0–5000 m")
    stage = curving.CurvingStage(
        curves=tuple(curves),
        deficiencies_mm=tuple(args.deficiency),
        lead_in=args.lead_in,
        irregular=args.irregular,
        seed=args.seed,
        integrator=args.integrator,
    )
    study = curving.run_curving(stage, Runtime(threads=args.threads, progress=True))
    record = curving.save_curving(study, args.out)
    print(record.notes)
    print(f"wrote {', '.join(str(p) for p in [*record.figures, *record.tables])}")
    return 0
