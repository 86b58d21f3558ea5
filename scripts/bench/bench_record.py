"""Benchmark records: what one benchmark measured, written by the benchmark itself.

A record is ``docs/performance/records/<bench>.json``: the command that produced it, the day and
machine it ran on, the version of the code, and its figures (each a value with its unit). The
Performance page's table is generated from these records by ``scripts/docs/performance_docs.py``,
so no figure on it is typed. Every benchmark script takes ``--record`` to write its record;
``scripts/bench/record_criterion.py`` writes the criterion benches' record from
``target/criterion``.
"""

from __future__ import annotations

import datetime
import json
import os
import platform
import subprocess
import sys
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]
#: Where records are written; ``LOCO_BENCH_RECORDS`` names another folder (a trial run's).
RECORDS = Path(os.environ.get("LOCO_BENCH_RECORDS", ROOT / "docs" / "performance" / "records"))


def machine() -> dict[str, Any]:
    """The processor's model and the cores this process may use."""
    model = platform.processor() or platform.machine()
    cpuinfo = Path("/proc/cpuinfo")
    if cpuinfo.exists():
        for line in cpuinfo.read_text(encoding="utf-8").splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    return {"cpu": model, "cores": cores, "system": platform.system()}


def code_version() -> str:
    """The commit the code was built from, ``+changes`` when the work tree differs from it."""
    try:
        commit = subprocess.run(
            ["git", "rev-parse", "--short=12", "HEAD"],
            cwd=ROOT, capture_output=True, text=True, check=True,
        ).stdout.strip()  # fmt: skip
        dirty = subprocess.run(
            ["git", "status", "--porcelain", "--untracked-files=no", "--", "crates", "python"],
            cwd=ROOT, capture_output=True, text=True, check=True,
        ).stdout.strip()  # fmt: skip
    except (OSError, subprocess.CalledProcessError):
        return "unknown"
    return commit + ("+changes" if dirty else "")


def figure(value: float, unit: str, digits: int = 3) -> dict[str, Any]:
    """One measured figure, rounded to ``digits`` significant digits."""
    return {"value": float(f"{value:.{digits}g}"), "unit": unit}


def write(bench: str, figures: dict[str, dict[str, Any]], command: str | None = None) -> Path:
    """Write the record of ``bench`` with ``figures`` (name → :func:`figure`); ``command``
    defaults to this process's own command line."""
    if command is None:
        script = Path(sys.argv[0]).resolve()
        shown = script.relative_to(ROOT) if script.is_relative_to(ROOT) else script
        command = " ".join(["python", str(shown), *[a for a in sys.argv[1:] if a != "--record"]])
    record = {
        "bench": bench,
        "command": command,
        "measured": datetime.date.today().isoformat(),
        "machine": machine(),
        "code": code_version(),
        "figures": figures,
    }
    RECORDS.mkdir(parents=True, exist_ok=True)
    path = RECORDS / f"{bench}.json"
    path.write_text(json.dumps(record, indent=1, sort_keys=False) + "\n", encoding="utf-8")
    print(f"record written: {path}")
    return path


def load(bench: str, directory: Path = RECORDS) -> dict[str, Any]:
    """The record of ``bench``."""
    path = directory / f"{bench}.json"
    data: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
    if data["bench"] != bench:
        raise ValueError(f"{path}: bench {data['bench']!r} in a file named {bench!r}")
    return data
