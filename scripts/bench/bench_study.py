"""Wall time of the whole study, ``loco reproduce``, and of the damper bench, ``loco damper-bench``.

Runs ``loco reproduce --<preset> --threads <threads>`` into a fresh directory (``--out``, default
a temporary one; an existing stage would be skipped, so the directory must not hold a run) and
times it, with every stage's own time from its stage record; then times ``loco damper-bench``.
``--record`` writes the benchmark record ``study_<preset>`` the Performance page is generated from.

    python scripts/bench/bench_study.py --preset quick --threads 2 --record
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import bench_record


def timed(command: list[str]) -> float:
    """Wall seconds of ``command``, which must succeed."""
    start = time.perf_counter()
    subprocess.run(command, check=True)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", choices=("quick", "full"), default="quick")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--out", type=Path, default=None, help="the run's directory (new)")
    parser.add_argument("--record", action="store_true", help="write the benchmark record")
    args = parser.parse_args()
    # The command installed with the package, beside this interpreter.
    loco_cli = [str(Path(sys.executable).with_name("loco"))]
    with tempfile.TemporaryDirectory() as scratch:
        out = args.out or Path(scratch) / "study"
        if out.exists() and any(out.iterdir()):
            sys.exit(f"{out} is not empty: its finished stages would be skipped")
        reproduce = [*loco_cli, "reproduce", f"--{args.preset}", "--out", str(out)]
        wall = timed([*reproduce, "--threads", str(args.threads)])
        stages = {}
        for record in sorted(out.glob("*/stage.json")):
            data = json.loads(record.read_text(encoding="utf-8"))["record"]
            stages[data["name"]] = data["seconds"]
        bench = timed([*loco_cli, "damper-bench", "--out", str(Path(scratch) / "bench")])
    print(f"loco reproduce --{args.preset}: {wall:.1f} s wall")
    for name, seconds in sorted(stages.items(), key=lambda s: -s[1]):
        print(f"  {name:20s} {seconds:7.1f} s")
    print(f"loco damper-bench: {bench:.1f} s wall")
    if args.record:
        figures: dict[str, dict[str, Any]] = {
            "threads": {"value": args.threads, "unit": ""},
            "wall": bench_record.figure(wall, "s"),
            "damper_bench": bench_record.figure(bench, "s"),
        }
        for name, seconds in stages.items():
            figures[f"stage.{name}"] = bench_record.figure(seconds, "s")
        bench_record.write(f"study_{args.preset}", figures)


if __name__ == "__main__":
    main()
