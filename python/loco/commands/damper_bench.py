"""``loco damper-bench``: the damper bench (:mod:`loco.studies.damper_bench`) into a directory."""

from __future__ import annotations

import argparse
from pathlib import Path

from loco.commands.arguments import output_dir, positive_float
from loco.studies.damper_bench import AMPLITUDE, bench_study

NAME = "damper-bench"
HELP = (
    "bench YD1, YD2, FSD and FSD-H at 1 Hz and 4 Hz: force-velocity curves, hysteresis loops, "
    "frequency-valve states, cut-off vs amplitude, two-tone (sway + dither) bench"
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--out", type=Path, default=Path("out/damper_bench"), help="output dir")
    parser.add_argument(
        "--amplitude",
        type=positive_float,
        default=AMPLITUDE,
        help="sine amplitude of the elongation (m)",
    )


def run(args: argparse.Namespace) -> int:
    out = output_dir(args.out)
    bench_study(out, float(args.amplitude))
    print(f"written to {out}")
    return 0
