"""``loco batch STUDY SAMPLES``: a batch of runs from a study file and a CSV of samples.

The study file (TOML) gives the vehicle, the scenario and the outputs; the samples CSV has a
header of parameter names (vehicle keys, the study names ``K_px`` … ``K_ncsy``, or ``speed``)
and one row of SI values per sample. The core reads both, runs the batch and writes the files,
the same code and the same numbers, bit for bit, as the ``loco-batch`` binary and
:func:`loco.run_batch`. ``examples/study.toml`` with ``examples/samples.csv`` is a worked
example; the format is described in the batches guide.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from loco import _loco
from loco.batch import _ProgressBar
from loco.commands.arguments import existing_file, thread_count

NAME = "batch"
HELP = "a batch of runs from a study file (TOML) and a samples CSV: metrics CSV, time histories"

EPILOG = """\
files written:
  OUTPUT                   one row per sample: sample, its parameters (SI), every metric, the
                           run statistics, status (ok, diverged, ...) and message
  <stem>_history_<i>.csv   time (s) and the study's channels of each sample in
                           [output] histories
"""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.epilog = EPILOG
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument(
        "study", type=existing_file, help="study file (TOML): vehicle, scenario, outputs"
    )
    parser.add_argument(
        "samples",
        type=existing_file,
        help="samples (CSV): parameter names, one row of SI values per sample",
    )
    parser.add_argument(
        "-o", "--output", type=Path, default=Path("metrics.csv"), help="metrics file to write (CSV)"
    )
    parser.add_argument(
        "-t",
        "--threads",
        type=thread_count,
        default=0,
        help="worker threads (0: one per core); the results do not depend on it",
    )
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar")


class _StudyProgress:
    """A progress bar opened once the core knows how many samples the study has."""

    def __init__(self) -> None:
        self.bar: _ProgressBar | None = None

    def update(self, done: int, failed: int, total: int) -> None:
        if self.bar is None and total > 0:
            self.bar = _ProgressBar(total)
        if self.bar is not None:
            self.bar.update(done, failed)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


def run(args: argparse.Namespace) -> int:
    progress = None if args.quiet else _StudyProgress()
    start = time.perf_counter()
    try:
        n, statuses, metrics_file, histories = _loco.run_study_file(
            args.study,
            args.samples,
            args.output,
            threads=args.threads,
            progress=progress.update if progress else None,
        )
    finally:
        if progress is not None:
            progress.close()
    seconds = time.perf_counter() - start
    ended = ", ".join(f"{count} {name}" for name, count in statuses)
    print(
        f"loco batch: {n} samples in {seconds:.2f} s ({n / seconds:.2f} runs/s): {ended}; "
        f"wrote {metrics_file}" + (f" and {len(histories)} time histories" if histories else ""),
        file=sys.stderr,
    )
    return 0
