"""Morris screening of every ranged input of the default vehicle (``loco.uncertainty.morris``):
the damping of the S_low carbody mode and the S_high bogie mode with YD1 and YD2 and the two
linear critical speeds, 20 trajectories on a 4-level grid, seed 0, on a process pool.

Writes into ``--out`` (default ``docs/screening``): ``morris.csv`` (μ*, μ, σ and the 95 %
bootstrap interval of μ* per input and output), ``morris_outputs.csv`` (every point's outputs,
in the order of ``loco.uncertainty.morris_samples`` with these settings, so that a test can
re-evaluate a few points and re-run the analysis: the committed table is what the model gives
now), ``morris.json`` (settings, loco version, wall time, the workers'
CPU time) and ``morris.png`` (μ* against σ, the five largest inputs of each output named).
Usage: ``python scripts/docs/morris_screening.py [--out docs/screening] [--workers 2]``.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import pandas as pd

import loco
from loco import uncertainty

#: The screening's settings (the docs' table was made with these).
TRAJECTORIES = 20
LEVELS = 4
SEED = 0


def analyse_samples(out: Path, table: pd.DataFrame, outputs: list[str]) -> pd.DataFrame:
    """The screening table and figure from the outputs file in ``out`` (the points are the
    sampler's, from the settings)."""
    y = pd.read_csv(out / "morris_outputs.csv")[outputs].to_numpy()
    x = uncertainty.morris_samples(None, outputs, TRAJECTORIES, SEED, LEVELS)
    result = uncertainty.analyse(table, x, y, outputs, SEED)
    result.to_csv(out / "morris.csv", index=False, float_format="%.6g")
    uncertainty.plot_morris(result, path=out / "morris.png")
    return result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("docs/screening"))
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument(
        "--analyse-only",
        action="store_true",
        help="re-analyse the outputs file in --out (morris_outputs.csv) without running the model",
    )
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    vehicle = loco.Locomotive.default()
    outputs = list(uncertainty.OUTPUTS)
    table = uncertainty.screened_inputs(uncertainty.ranges(vehicle), outputs)
    if args.analyse_only:
        analyse_samples(args.out, table, outputs)
        return
    samples: dict[int, list[float]] = {}
    start = time.perf_counter()
    with ProcessPoolExecutor(max_workers=args.workers) as pool:
        result = uncertainty.morris(
            vehicle,
            outputs,
            trajectories=TRAJECTORIES,
            seed=SEED,
            executor=pool,
            levels=LEVELS,
            on_row=lambda i, values: samples.__setitem__(i, values),
        )
    wall = time.perf_counter() - start
    # The workers' CPU time: the wall time the screening takes on an idle machine with as many
    # cores as workers is about this over the workers.
    cpu = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu_s = cpu.ru_utime + cpu.ru_stime
    frame = pd.DataFrame([samples[i] for i in range(len(samples))], columns=outputs)
    frame.to_csv(args.out / "morris_outputs.csv", index=False, float_format="%.17g")
    # The committed table is the analysis of the committed samples (as --analyse-only makes it).
    analysed = analyse_samples(args.out, table, outputs)
    pd.testing.assert_frame_equal(analysed, result, check_exact=False, rtol=1e-9)
    meta = {
        "loco_version": loco.__version__,
        "trajectories": TRAJECTORIES,
        "levels": LEVELS,
        "seed": SEED,
        "inputs": len(table),
        "samples": len(frame),
        "outputs": outputs,
        "workers": args.workers,
        "wall_time_s": round(wall, 1),
        "worker_cpu_time_s": round(cpu_s, 1),
    }
    (args.out / "morris.json").write_text(json.dumps(meta, indent=2) + "\n", encoding="utf-8")
    print(
        f"{len(frame)} samples of {len(table)} inputs in {wall:.0f} s on {args.workers} "
        f"workers ({cpu_s:.0f} s of worker CPU time)"
    )


if __name__ == "__main__":
    main()
