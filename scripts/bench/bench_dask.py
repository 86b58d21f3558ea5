"""Overhead of the Dask executor against local threads on the same cores, and the projected
wall time of a large study on a cluster.

For each sample count the same Latin hypercube design (six study parameters, S_high, 200 km/h)
runs, alternately, as one ``loco.run_batch`` on local rayon threads and as a campaign on a Dask
``LocalCluster`` of ``--workers`` processes (one rayon thread each, so both use the same cores),
with and without the Parquet sample store, and as a campaign on local threads with the store
(what ``loco reproduce`` does by default). The cluster is started once and its start-up time is
reported apart. The metrics of every run are checked bit-identical to the plain batch's. Besides
wall time, the CPU time of this process and of the worker processes is summed: on a machine
shared with other jobs the wall time also measures their load, the CPU time much less so.

From the measured per-sample cost (core-seconds per run = local wall time × threads / samples)
and the Dask overhead, it projects a Saltelli N = 1024 study (N·(k + 2) = 8192 runs per scenario
for k = 6; 14 336 with the second-order terms) of two scenarios on a
64-core cluster.

    python scripts/bench/bench_dask.py --samples 64 512 --distance 300 --repeat 2
    python scripts/bench/bench_dask.py --samples 64 --distance 500

``--record`` writes the benchmark record the Performance page is generated from (every sample
count's wall and CPU times, the overheads and the projection).
"""

from __future__ import annotations

import argparse
import os
import resource
import tempfile
import time
from typing import Any

import bench_record
import numpy as np

import loco
from loco.campaign import run_campaign
from loco.executors import DaskExecutor, LocalExecutor
from loco.studies.parameters import names
from loco.studies.sampling import latin_hypercube

#: Runs per scenario of Saltelli N = 1024 on six parameters with second-order terms, N·(2k + 2).
SALTELLI_RUNS = 1024 * (2 * 6 + 2)


def _cpu_seconds() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def _cpu_total(dask: DaskExecutor) -> float:
    """CPU seconds of this process and of every worker process so far."""
    return _cpu_seconds() + sum(dask.client.run(_cpu_seconds).values())


def _bench(
    n: int, scenario: loco.Scenario, dask: DaskExecutor, threads: int, repeat: int
) -> tuple[dict[str, float], dict[str, float], loco.BatchResult]:
    """Best wall and CPU seconds of each way of running ``n`` samples."""
    x = latin_hypercube(n, seed=1)
    wall: dict[str, float] = {}
    cpu: dict[str, float] = {}
    reference: loco.BatchResult | None = None
    for _ in range(repeat):
        runs: dict[str, tuple[Any, str | None]] = {
            "local": (None, None),
            "local+store": (LocalExecutor(threads), tempfile.mkdtemp()),
            "dask": (dask, None),
            "dask+store": (dask, tempfile.mkdtemp()),
        }
        for label, (executor, store) in runs.items():
            c, t = _cpu_total(dask), time.perf_counter()
            if executor is None:
                result = loco.run_batch(
                    x, names(), scenario=scenario, threads=threads, progress=False
                )
            else:
                result = run_campaign(
                    x, names(), scenario=scenario, executor=executor, store=store, progress=False
                )
            wall[label] = min(wall.get(label, np.inf), time.perf_counter() - t)
            cpu[label] = min(cpu.get(label, np.inf), _cpu_total(dask) - c)
            reference = reference or result
            assert result.metrics.tobytes() == reference.metrics.tobytes(), label
            assert np.array_equal(result.status, reference.status), label
    assert reference is not None
    return wall, cpu, reference


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, nargs="+", default=[64, 512])
    parser.add_argument("--distance", type=float, default=500.0, help="m per run")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--cluster-cores", type=int, default=64)
    parser.add_argument("--record", action="store_true", help="write the benchmark record")
    args = parser.parse_args()
    threads = args.workers
    figures: dict[str, dict[str, Any]] = {
        "distance": bench_record.figure(args.distance, "m"),
        "cluster_cores": {"value": args.cluster_cores, "unit": ""},
    }
    scenario = loco.Scenario(name="S_high", speed=200 / 3.6, distance=args.distance, seed=1)
    print(
        f"loco {loco.__version__}, {os.cpu_count()} cores, load {os.getloadavg()[0]:.1f}; "
        f"{args.distance:g} m per run; local: {threads} threads; Dask: {args.workers} workers"
    )
    start = time.perf_counter()
    with DaskExecutor(n_workers=args.workers, threads=1) as dask:
        startup = time.perf_counter() - start
        print(f"LocalCluster start-up: {startup:.1f} s")
        figures["startup"] = bench_record.figure(startup, "s", 2)
        for n in args.samples:
            wall, cpu, local = _bench(n, scenario, dask, threads, args.repeat)
            per_sample = cpu["local"] / n
            print(
                f"{n:5d} samples ({local.n_failed} failed), chunk {dask.default_chunk_size(n)}: "
                f"local batch {wall['local']:.1f} s wall, {cpu['local']:.1f} s CPU "
                f"({per_sample:.3f} core-s/run); load {os.getloadavg()[0]:.1f}"
            )
            for label in ("local+store", "dask", "dask+store"):
                print(
                    f"       {label:12s} {wall[label]:7.1f} s wall "
                    f"({wall[label] / wall['local'] - 1:+.1%}), {cpu[label]:7.1f} s CPU "
                    f"({cpu[label] / cpu['local'] - 1:+.1%})"
                )
            overhead = cpu["dask+store"] / cpu["local"] - 1
            runs = 2 * SALTELLI_RUNS
            projected = runs * per_sample / args.cluster_cores * (1 + max(overhead, 0.0))
            print(
                f"       projection: Saltelli N=1024, 2 scenarios ({runs} runs of "
                f"{args.distance:g} m) on {args.cluster_cores} cores: {projected / 60:.1f} min "
                f"(+ cluster start-up)"
            )
            figures[f"{n}.per_run"] = bench_record.figure(per_sample, "core-s")
            figures[f"{n}.chunk"] = {"value": dask.default_chunk_size(n), "unit": ""}
            for label in ("local", "local+store", "dask", "dask+store"):
                figures[f"{n}.{label}.wall"] = bench_record.figure(wall[label], "s")
                figures[f"{n}.{label}.cpu"] = bench_record.figure(cpu[label], "s")
                if label != "local":
                    extra = 100 * (cpu[label] / cpu["local"] - 1)
                    figures[f"{n}.{label}.cpu_overhead"] = bench_record.figure(extra, "%", 2)
            figures[f"{n}.projection"] = bench_record.figure(projected / 60, "min", 2)
    if args.record:
        bench_record.write("bench_dask", figures)


if __name__ == "__main__":
    main()
