"""The criterion benches' record: every bench's median time from ``target/criterion``.

Run the benches first, then record what they measured:

    cargo bench -p loco-core
    python scripts/bench/record_criterion.py

Each bench's figure is criterion's estimate of the median time per iteration, with the bounds of
its 95 % confidence interval, in nanoseconds, keyed by the bench's full id (``group/function``).
Benches whose results are older than ``--since-hours`` are left out with a warning, so that one
record never mixes two sessions' runs.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import bench_record

CRITERION = bench_record.ROOT / "target" / "criterion"


def median_estimates(directory: Path, since_hours: float) -> dict[str, dict[str, float | str]]:
    """Every bench under ``directory``: full id → median and its interval, ns."""
    figures: dict[str, dict[str, float | str]] = {}
    oldest = time.time() - since_hours * 3600.0
    for estimates_path in sorted(directory.glob("**/new/estimates.json")):
        benchmark = json.loads((estimates_path.parent / "benchmark.json").read_text("utf-8"))
        full_id = benchmark["full_id"]
        if estimates_path.stat().st_mtime < oldest:
            print(f"left out (older than {since_hours} h): {full_id}", file=sys.stderr)
            continue
        median = json.loads(estimates_path.read_text("utf-8"))["median"]
        interval = median["confidence_interval"]
        figures[full_id] = {
            "value": float(f"{median['point_estimate']:.4g}"),
            "low": float(f"{interval['lower_bound']:.4g}"),
            "high": float(f"{interval['upper_bound']:.4g}"),
            "unit": "ns",
        }
    return figures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--since-hours", type=float, default=12.0)
    parser.add_argument("--criterion", type=Path, default=CRITERION)
    args = parser.parse_args()
    figures = median_estimates(args.criterion, args.since_hours)
    if not figures:
        sys.exit(f"no criterion results under {args.criterion}: run `cargo bench -p loco-core`")
    bench_record.write("criterion", figures, command="cargo bench -p loco-core")


if __name__ == "__main__":
    main()
