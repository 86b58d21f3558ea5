"""Campaign overhead: one design as one native batch and as a local campaign in chunks.

A campaign hands the native side its samples a chunk at a time (what a Dask worker gets, and what
``loco reproduce`` runs locally); whatever a chunk rebuilds that one batch builds once (the
contact table, the tabulated FASTSIM, the propagators), the cores left idle at each chunk's end
and the store's writes between chunks are the campaign's overhead. Runs the design
(``--samples`` Latin-hypercube samples of the six study parameters, S_high, 200 km/h, 500 m, the
default scheme, the creep model ``--creep``) ``--repeat`` times each way on ``--threads``
threads, alternating, and prints the median wall time of each, the paired ratio, the share of
the cores busy (CPU time over wall time × threads) and the samples running on average (their
wall times summed over the run's: below the thread count, cores waited between samples).
``--store`` keeps the campaign's samples in a temporary store as ``loco reproduce`` does;
``--chunk-size 0`` takes the executor's default. ``--mode batch`` or ``--mode campaign`` runs
one way once and prints its times (to alternate two versions of the code, ``PYTHONPATH``
pointing at each).

    python scripts/bench/bench_campaign.py --samples 256 --chunk-size 0 --store --repeat 3

``--record`` writes the benchmark record the Performance page is generated from.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from collections.abc import Callable

import bench_record

import loco
from loco.campaign import run_campaign
from loco.simulation import RUN_STATISTICS
from loco.studies.parameters import names
from loco.studies.sampling import latin_hypercube


def timed(way: Callable[[], loco.BatchResult]) -> tuple[float, float, float]:
    """Wall and CPU time (every thread of this process) of one run, and the samples' wall times
    summed: over the run's wall time, the samples running on average, which other processes
    on a shared machine slow down alike."""
    start, cpu = time.perf_counter(), time.process_time()
    result = way()
    assert result.n_failed == 0, result.failures()
    sample_seconds = float(result.statistics[:, RUN_STATISTICS.index("wall_time")].sum())
    return time.perf_counter() - start, time.process_time() - cpu, sample_seconds


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=48)
    parser.add_argument("--chunk-size", type=int, default=8)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--store", action="store_true")
    parser.add_argument("--mode", choices=("both", "batch", "campaign"), default="both")
    parser.add_argument("--creep", choices=loco.simulation.CREEP_MODELS, default="fastsim")
    parser.add_argument("--record", action="store_true", help="write the benchmark record")
    args = parser.parse_args()
    params = latin_hypercube(args.samples, seed=1)
    scenario = loco.Scenario(
        name="S_high", speed=200 / 3.6, distance=500.0, seed=1, creep=args.creep
    )

    def batch() -> loco.BatchResult:
        return loco.run_batch(
            params, names(), scenario=scenario, threads=args.threads, progress=False
        )

    def campaign() -> loco.BatchResult:
        with tempfile.TemporaryDirectory() as store:
            return run_campaign(
                params, names(), scenario=scenario, chunk_size=args.chunk_size or None,
                threads=args.threads, progress=False, store=store if args.store else None,
            )  # fmt: skip

    ways = {"batch": batch, "campaign": campaign}
    if args.mode != "both":
        wall, cpu, running = timed(ways[args.mode])
        busy = cpu / (wall * args.threads)
        print(
            f"{args.mode}: {wall:.2f} s wall, {cpu:.2f} s CPU, {busy:.1%} busy, "
            f"{running / wall:.3f} samples running on average"
        )
        return
    runs: dict[str, list[tuple[float, float, float]]] = {name: [] for name in ways}
    for _ in range(args.repeat):
        for name, way in ways.items():
            runs[name].append(timed(way))
    print(f"{args.samples} samples, {args.threads} threads, store: {args.store}")
    for name, times in runs.items():
        wall = statistics.median(w for w, _, _ in times)
        busy = statistics.median(c / (w * args.threads) for w, c, _ in times)
        running = statistics.median(r / w for w, _, r in times)
        print(f"{name:9s} median {wall:.2f} s wall, {busy:.1%} of the cores busy, "
              f"{running:.3f} samples running on average")  # fmt: skip
    pairs = zip(runs["batch"], runs["campaign"], strict=True)
    ratio = statistics.median(c[0] / b[0] for b, c in pairs)
    print(f"campaign / batch, median of paired ratios: {ratio:.3f}")
    if args.record:
        figures = {
            "samples": {"value": args.samples, "unit": ""},
            "chunks": {"value": -(-args.samples // args.chunk_size) if args.chunk_size else 0,
                       "unit": ""},
            "ratio": bench_record.figure(ratio, "×"),
        }  # fmt: skip
        for name, times in runs.items():
            wall = statistics.median(w for w, _, _ in times)
            figures[f"{name}_wall"] = bench_record.figure(wall, "s")
        bench_record.write("bench_campaign", figures)


if __name__ == "__main__":
    main()
