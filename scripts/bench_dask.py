"""Overhead of the Dask executor against local threads on the same cores, and the projected
wall time of a large study on a cluster.

For each sample count the same Latin hypercube design (six study parameters, S_high, 200 km/h)
runs, alternately, as one ``loco.run_batch`` on local rayon threads and as a campaign on a Dask
``LocalCluster`` of ``--workers`` processes (one rayon thread each, so both use the same cores),
with and without the Parquet sample store. The cluster is started once and its start-up time is
reported apart. The metrics of every Dask run are checked bit-identical to the local ones.

From the measured per-sample cost (core-seconds per run = local wall time × threads / samples)
and the Dask overhead, it projects a Saltelli N = 1024 study (N·(k + 2) = 8192 runs per scenario
for k = 6; 14 336 with the second-order terms, as issue 15 counts it) of two scenarios on a
64-core cluster.

    python scripts/bench_dask.py --samples 64 512 --distance 300 --repeat 2
    python scripts/bench_dask.py --samples 64 --distance 500
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time

import numpy as np

import loco
from loco.campaign import run_campaign
from loco.executors import DaskExecutor
from loco.studies.parameters import names
from loco.studies.sampling import latin_hypercube

#: Runs per scenario of Saltelli N = 1024 on six parameters with second-order terms, N·(2k + 2).
SALTELLI_RUNS = 1024 * (2 * 6 + 2)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, nargs="+", default=[64, 512])
    parser.add_argument("--distance", type=float, default=500.0, help="m per run")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--cluster-cores", type=int, default=64)
    args = parser.parse_args()
    threads = args.workers
    scenario = loco.Scenario(scenario="S_high", speed=200 / 3.6, distance=args.distance, seed=1)
    print(
        f"loco {loco.__version__}, {os.cpu_count()} cores, load {os.getloadavg()[0]:.1f}; "
        f"{args.distance:g} m per run; local: {threads} threads; Dask: {args.workers} workers"
    )
    start = time.perf_counter()
    with DaskExecutor(n_workers=args.workers, threads=1) as dask:
        startup = time.perf_counter() - start
        print(f"LocalCluster start-up: {startup:.1f} s")
        for n in args.samples:
            x = latin_hypercube(n, seed=1)
            best: dict[str, float] = {}
            for _ in range(args.repeat):
                t = time.perf_counter()
                local = loco.run_batch(x, names(), scenario=scenario, threads=threads,
                                       progress=False)  # fmt: skip
                best["local"] = min(best.get("local", np.inf), time.perf_counter() - t)
                for label, store in (("dask", None), ("dask+store", tempfile.mkdtemp())):
                    t = time.perf_counter()
                    remote = run_campaign(x, names(), scenario=scenario, executor=dask,
                                          store=store, progress=False)  # fmt: skip
                    best[label] = min(best.get(label, np.inf), time.perf_counter() - t)
                    assert remote.metrics.tobytes() == local.metrics.tobytes(), label
                    assert np.array_equal(remote.status, local.status), label
            per_sample = best["local"] * threads / n
            print(
                f"{n:5d} samples: local {best['local']:7.1f} s ({per_sample:.3f} core-s/run, "
                f"{local.n_failed} failed), dask {best['dask']:7.1f} s "
                f"({best['dask'] / best['local'] - 1:+.1%}), "
                f"dask+store {best['dask+store']:7.1f} s "
                f"({best['dask+store'] / best['local'] - 1:+.1%}); chunk "
                f"{dask.default_chunk_size(n)} samples"
            )
            overhead = best["dask+store"] / best["local"] - 1
            runs = 2 * SALTELLI_RUNS
            wall = runs * per_sample / args.cluster_cores * (1 + max(overhead, 0.0))
            print(
                f"       projection: Saltelli N=1024, 2 scenarios ({runs} runs of "
                f"{args.distance:g} m) on {args.cluster_cores} cores: {wall / 60:.1f} min "
                f"(+ cluster start-up)"
            )


if __name__ == "__main__":
    main()
