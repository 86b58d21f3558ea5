"""Campaign overhead: one design as one native batch and as a local campaign in chunks.

A campaign hands the native side one chunk at a time (what a Dask worker gets, and what
``loco reproduce`` runs locally); whatever a chunk rebuilds that one batch builds once (the
contact table, the tabulated FASTSIM, the propagators) is the campaign's overhead. Runs the
design (``--samples`` Latin-hypercube samples of the six study parameters, S_high, 200 km/h,
500 m, the default scheme, the creep model ``--creep``) ``--repeat`` times each way on
``--threads`` threads and prints the best wall time of each. ``--mode batch`` or
``--mode campaign`` runs one way once (for ``farm-bench``).

    python scripts/bench_campaign.py --samples 48 --chunk-size 8
"""

from __future__ import annotations

import argparse
import time

import loco
from loco.campaign import run_campaign
from loco.studies.parameters import names
from loco.studies.sampling import latin_hypercube


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=48)
    parser.add_argument("--chunk-size", type=int, default=8)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--mode", choices=("both", "batch", "campaign"), default="both")
    parser.add_argument("--creep", choices=loco.simulation.CREEP_MODELS, default="fastsim")
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
        return run_campaign(
            params, names(), scenario=scenario, chunk_size=args.chunk_size,
            threads=args.threads, progress=False,
        )  # fmt: skip

    ways = {"batch": batch, "campaign": campaign}
    if args.mode != "both":
        result = ways[args.mode]()
        assert result.n_failed == 0, result.failures()
        return
    best = {}
    for name, way in ways.items():
        times = []
        for _ in range(args.repeat):
            start = time.perf_counter()
            result = way()
            times.append(time.perf_counter() - start)
            assert result.n_failed == 0, result.failures()
        best[name] = min(times)
    chunks = -(-args.samples // args.chunk_size)
    print(f"{args.samples} samples, {args.threads} threads")
    print(f"one batch:               {best['batch']:.2f} s")
    print(f"campaign, {chunks} chunks of {args.chunk_size}: {best['campaign']:.2f} s")
    extra = best["campaign"] - best["batch"]
    print(f"overhead:                {extra:+.2f} s ({extra / chunks:+.3f} s per chunk)")


if __name__ == "__main__":
    main()
