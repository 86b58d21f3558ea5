"""Checked command-line values of the ``loco`` subcommands: a bad value is a usage error.

The ``type=`` functions below make argparse refuse a value the way it refuses an unknown option
(``loco reproduce: error: argument --threads: ...``, exit code 2, no traceback). Output
directories are checked by :func:`output_dir` before a command does any work: a path on a file,
under a file or where nothing can be written is refused at once, not after the run.
"""

from __future__ import annotations

import argparse
import math
import os
from pathlib import Path

from loco.directories import directory_problem
from loco.field_types import MAX_WHOLE
from loco.simulation import INTEGRATOR_STEPS, INTEGRATORS, Scenario

__all__ = [
    "UsageError",
    "add_integrator_argument",
    "existing_file",
    "finite_float",
    "non_negative_int",
    "output_dir",
    "positive_float",
    "positive_int",
    "thread_count",
]


class UsageError(Exception):
    """A command-line value refused after parsing (an output path); ``loco`` prints it as a usage
    error of the subcommand and exits with code 2."""


def _integer(text: str) -> int:
    try:
        return int(text, 10)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number, got {text!r}") from None


def positive_int(text: str) -> int:
    """A whole number >= 1 (thread, worker and chunk counts)."""
    n = _integer(text)
    if n < 1:
        raise argparse.ArgumentTypeError(f"must be >= 1, got {n}")
    return n


def thread_count(text: str) -> int:
    """A thread count from 0 (one per core) to 1024, as the core's batch takes it."""
    n = _integer(text)
    if not 0 <= n <= 1024:
        raise argparse.ArgumentTypeError(f"must be in 0..1024, got {n}")
    return n


def existing_file(text: str) -> Path:
    """The path of a file that exists (an input file: vehicle, study, samples, curve)."""
    path = Path(text)
    if not path.is_file():
        raise argparse.ArgumentTypeError(f"no such file: {text!r}")
    return path


def non_negative_int(text: str) -> int:
    """A whole number >= 0 (seeds), at most what a scenario setting takes
    (:data:`loco.field_types.MAX_WHOLE`)."""
    n = _integer(text)
    if n < 0:
        raise argparse.ArgumentTypeError(f"must be >= 0, got {n}")
    if n > MAX_WHOLE:
        raise argparse.ArgumentTypeError(f"must be <= {MAX_WHOLE}, got {n}")
    return n


def finite_float(text: str) -> float:
    """A finite real number."""
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(x):
        raise argparse.ArgumentTypeError(f"must be finite, got {text!r}")
    return x


def positive_float(text: str) -> float:
    """A finite real number > 0 (speeds, amplitudes, frequencies)."""
    x = finite_float(text)
    if x <= 0.0:
        raise argparse.ArgumentTypeError(f"must be > 0, got {text!r}")
    return x


def output_dir(path: str | Path, option: str = "--out") -> Path:
    """``path`` as an output directory that exists and takes files, created if missing.

    Raises :class:`UsageError` naming ``option`` when it is a file, lies under a file, or cannot
    be created or written (read-only place, no permission). The check writes and removes a probe
    file, so it holds for any user (root included) and any file system (read-only mounts)."""
    out = Path(path)
    problem = directory_problem(out)
    if problem is not None:
        kind, reason = problem
        if kind == "file":
            raise UsageError(f"argument {option}: {reason}")
        raise UsageError(f"argument {option}: cannot write into {out}: {reason}")
    if not os.access(out, os.W_OK | os.X_OK):
        raise UsageError(f"argument {option}: cannot write into {out}: permission denied")
    return out


def add_integrator_argument(parser: argparse.ArgumentParser) -> None:
    """``--integrator``: the scheme of every run, at its own step (the core's default when left
    out)."""
    default = Scenario.integrator
    steps = ", ".join(f"{n} {INTEGRATOR_STEPS[n] * 1e3:g} ms" for n in INTEGRATORS)
    parser.add_argument(
        "--integrator",
        choices=INTEGRATORS,
        default=default,
        help=f"integration scheme of every run, at its own step ({steps}; default {default}); "
        "etdrk4 stays within 0.5 %% of rk4 over the study's parameter box",
    )
