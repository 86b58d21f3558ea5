"""A direct Saltelli design on the simulator, timed: N = 1024 on both objectives.

Runs the study's Sobol' analysis directly on the simulator (no surrogate): Saltelli's design of
``--base`` N base samples over the six SPEC §6 parameters, with the second-order rows by default
(N·(2k + 2) = 14 336 runs per objective for N = 1024, k = 6), for W_y on S_low and A_yb on
S_high at the study's 200 km/h over 500 m, exactly as ``loco reproduce``'s sensitivity stage
evaluates them (:class:`loco.studies.parameter_study.StudySetup`). Every batch runs as a campaign
on local threads with its finished samples in a Parquet store (``--store``, default a temporary
directory), as ``loco reproduce`` runs its stages, so a rerun after a kill simulates only what
is missing. Prints and writes (``--out``, JSON) the runs, the wall and CPU time, the runs per
second and the first- and total-order indices with their 95 % half-widths.

    python scripts/verify/saltelli_direct.py --base 1024 --threads 2 --out saltelli_1024.json

``--record`` writes the benchmark record the Performance page is generated from.
"""

from __future__ import annotations

import argparse
import json
import resource
import sys
import tempfile
import time
from pathlib import Path

from loco import campaign
from loco.executors import LocalExecutor
from loco.studies.parameter_study import StudySetup, labels
from loco.studies.parameters import names
from loco.studies.sampling import saltelli_block_size
from loco.studies.sobol import sobol_direct
from loco.studies.stages import Runtime

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "bench"))
import bench_record


def _cpu_seconds() -> float:
    """CPU time of this process and its finished children, s (the simulations run in threads
    of this process)."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--base", type=int, default=1024, help="Saltelli base samples N")
    parser.add_argument(
        "--first-order-only",
        action="store_true",
        help="leave out the second-order rows (N·(k + 2) runs per objective)",
    )
    parser.add_argument("--threads", type=int, default=None, help="default: every core")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--store", type=Path, default=None, help="campaign stores (kept)")
    parser.add_argument("--out", type=Path, default=None, help="JSON summary")
    parser.add_argument("--record", action="store_true", help="write the benchmark record")
    args = parser.parse_args()
    second_order = not args.first_order_only
    per_objective = args.base * saltelli_block_size(len(names()), second_order)
    metrics = labels()
    print(
        f"Saltelli N = {args.base} ({'with' if second_order else 'without'} second order): "
        f"{per_objective} runs per objective, {per_objective * len(metrics)} in all"
    )
    with tempfile.TemporaryDirectory() as scratch:
        store = args.store or Path(scratch)
        setup = StudySetup(track_seed=args.seed)
        runtime = Runtime(threads=args.threads)
        start, cpu0 = time.perf_counter(), _cpu_seconds()
        with campaign.using(LocalExecutor(args.threads), store):
            indices = sobol_direct(
                setup.evaluator(runtime),
                metrics,
                n_base=args.base,
                seed=args.seed,
                calc_second_order=second_order,
            )
        wall, cpu = time.perf_counter() - start, _cpu_seconds() - cpu0
    runs = per_objective * len(metrics)
    summary = {
        "base": args.base,
        "second_order": second_order,
        "runs": runs,
        "threads": args.threads,
        "wall_s": wall,
        "cpu_s": cpu,
        "runs_per_s": runs / wall,
        "indices": {
            s.metric: {
                "dropped_base_samples": s.n_dropped,
                "parameters": list(s.parameters),
                "S1": s.S1.tolist(),
                "S1_conf": s.S1_conf.tolist(),
                "ST": s.ST.tolist(),
                "ST_conf": s.ST_conf.tolist(),
            }
            for s in indices
        },
    }
    print(f"{runs} runs in {wall:.0f} s wall ({wall / 60:.1f} min), {cpu:.0f} s CPU")
    for s in indices:
        ranked = sorted(zip(s.ST, s.ST_conf, s.parameters, strict=True), reverse=True)
        line = ", ".join(f"{n} {st:.3f}±{c:.3f}" for st, c, n in ranked)
        print(f"{s.metric}: ST {line} ({s.n_dropped} base samples dropped)")
    if args.out:
        args.out.write_text(json.dumps(summary, indent=2) + "\n")
    if args.record:
        figures = {
            "base": {"value": args.base, "unit": ""},
            "runs": {"value": runs, "unit": ""},
            "threads": {"value": args.threads, "unit": ""},
            "wall": bench_record.figure(wall / 60, "min"),
            "cpu": bench_record.figure(cpu, "s"),
        }
        bench_record.write("saltelli_direct", figures)


if __name__ == "__main__":
    main()
