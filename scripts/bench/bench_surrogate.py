"""Time of the surrogate selection on a study's training samples (the surrogate stage's fits).

Loads the training tables (``monte_carlo.csv`` and ``surrogate_samples.csv`` of a ``loco
reproduce`` output), runs :func:`loco.studies.surrogate.select_surrogates` as the
surrogate stage does (every candidate, 5 folds, the nested cross-validation) on ``--jobs``
processes and prints the wall time, the CPU time of every process and a SHA-256 of every score,
held-out prediction and fitted model's prediction at the samples (the same hash before and
after a change means the same numbers). To compare two versions of the code on a shared
machine, alternate them (``PYTHONPATH`` pointing at each) several times and compare medians:

    python scripts/bench/bench_surrogate.py --out /tmp/quick

``--record`` writes the benchmark record the Performance page is generated from.
"""

from __future__ import annotations

import argparse
import hashlib
import resource
import time
from pathlib import Path

import bench_record
import numpy as np
from joblib.externals.loky import get_reusable_executor

from loco.studies.parameter_study import load_monte_carlo
from loco.studies.surrogate import select_surrogates


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True, help="a loco reproduce output")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--no-nested", action="store_true")
    parser.add_argument("--record", action="store_true", help="write the benchmark record")
    args = parser.parse_args()
    tables = [args.out / "monte_carlo/monte_carlo.csv"]
    tables += [p for p in [args.out / "surrogate_samples/surrogate_samples.csv"] if p.exists()]
    parts = [load_monte_carlo(p) for p in tables]
    x = np.vstack([p[0] for p in parts])
    y = np.vstack([p[1] for p in parts])
    start = time.perf_counter()
    selections = select_surrogates(x, y, nested=not args.no_nested, n_jobs=args.jobs)
    seconds = time.perf_counter() - start
    # The pool's processes are reaped only when it shuts down: then their CPU time is counted.
    get_reusable_executor().shutdown(wait=True)
    cpu = sum(
        u.ru_utime + u.ru_stime
        for u in (
            resource.getrusage(resource.RUSAGE_SELF),
            resource.getrusage(resource.RUSAGE_CHILDREN),
        )
    )
    digest = hashlib.sha256()
    for sel in selections:
        for score in sel.scores.values():
            digest.update(score.r2_folds.tobytes() + score.predictions.tobytes())
        for model in sel.models.values():
            digest.update(np.asarray(model.predict(x)).tobytes())
        if sel.nested is not None:
            digest.update(sel.nested.r2_folds.tobytes() + " ".join(sel.nested.chosen).encode())
    print(
        f"{len(x)} samples, {args.jobs} jobs: {seconds:.1f} s wall, {cpu:.1f} s CPU, "
        f"results {digest.hexdigest()[:16]}"
    )
    if args.record:
        figures = {
            "samples": {"value": len(x), "unit": ""},
            "jobs": {"value": args.jobs, "unit": ""},
            "wall": bench_record.figure(seconds, "s"),
            "cpu": bench_record.figure(cpu, "s"),
        }
        bench_record.write("bench_surrogate", figures)


if __name__ == "__main__":
    main()
