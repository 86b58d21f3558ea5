"""``loco reproduce``: the whole study of SPEC §6 from one command, and its report.

The stages, their sizes and what they write are described in :mod:`loco.studies.reproduce`
and :mod:`loco.studies.sizes`; this module parses the command line and runs them.
"""

from __future__ import annotations

import argparse
import contextlib
import time
from pathlib import Path

import loco
from loco.commands.arguments import (
    UsageError,
    add_integrator_argument,
    non_negative_int,
    output_dir,
    positive_int,
)
from loco.executors import executor_from_options
from loco.studies.reproduce import reproduce
from loco.studies.sizes import FULL, PRESETS, QUICK

NAME = "reproduce"
HELP = "run the whole reference study (every figure and table) and write a Markdown report"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    size = parser.add_mutually_exclusive_group()
    size.add_argument(
        "--quick",
        dest="preset",
        action="store_const",
        const="quick",
        help=f"reduced sample counts, about 12 min on 2 cores (default; ~{QUICK.runs()} runs)",
    )
    size.add_argument(
        "--full",
        dest="preset",
        action="store_const",
        const="full",
        help=f"the reference study's own sizes (~{FULL.runs()} runs)",
    )
    size.add_argument(
        "--tiny", dest="preset", action="store_const", const="tiny", help=argparse.SUPPRESS
    )
    parser.set_defaults(preset="quick")
    parser.add_argument(
        "--out",
        type=Path,
        default=Path("results/reproduce"),
        help="output directory (default results/reproduce)",
    )
    parser.add_argument(
        "--threads",
        type=positive_int,
        default=None,
        help="simulation threads (default: all cores); results do not depend on it",
    )
    parser.add_argument(
        "--seed",
        type=non_negative_int,
        default=0,
        help="seed of the track, the sample designs and NSGA-II (default 0)",
    )
    add_integrator_argument(parser)
    parser.add_argument(
        "--workers",
        type=positive_int,
        default=None,
        help="run the simulations on a Dask LocalCluster of this many worker processes "
        "(needs pip install 'loco[distributed]')",
    )
    parser.add_argument(
        "--scheduler",
        default=None,
        help="run the simulations on the Dask scheduler at this address, e.g. tcp://host:8786 "
        "(default: $DASK_SCHEDULER_ADDRESS if set)",
    )
    parser.add_argument(
        "--chunk-size",
        type=positive_int,
        default=None,
        help="samples per chunk (one batch on a worker, stored when it finishes)",
    )
    parser.add_argument(
        "--force", action="store_true", help="rerun finished stages and their stored samples too"
    )
    parser.add_argument(
        "--no-progress",
        dest="progress",
        action="store_false",
        help="no progress bars (stage lines are still printed)",
    )


def _command_line(args: argparse.Namespace) -> str:
    """The command that reproduces this run (the options that change its results or its place)."""
    parts = ["loco", NAME, f"--{args.preset}", "--out", str(args.out), "--seed", str(args.seed)]
    if args.integrator != loco.Scenario.integrator:
        parts += ["--integrator", args.integrator]
    return " ".join(parts)


def run(args: argparse.Namespace) -> int:
    sizes = PRESETS[args.preset]
    start = time.perf_counter()
    output_dir(args.out)
    try:
        executor = executor_from_options(
            workers=args.workers, scheduler=args.scheduler, threads=args.threads
        )
    except (ImportError, OSError, loco.LocoError) as e:
        raise UsageError(str(e)) from None
    with contextlib.closing(executor):
        report = reproduce(
            sizes,
            args.out,
            threads=args.threads,
            seed=args.seed,
            integrator=args.integrator,
            force=args.force,
            progress=args.progress,
            command=_command_line(args),
            executor=executor,
            chunk_size=args.chunk_size,
        )
    print(f"done in {time.perf_counter() - start:.0f} s; report: {report.resolve()}")
    print(f"the report as a page: {report.with_suffix('.html').resolve()}")
    return 0
