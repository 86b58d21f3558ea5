"""The verdict's probability (``loco.studies.premise_probability``): ``--n`` plausible
locomotives, each with YD1, YD2, FSD and FSD-H on its S_low pair and on S_high, 500 m at
200 km/h after the lead-in on ``--tracks`` tracks; the share with the premise, the FSD inside
it, and which inputs decide it.

Writes into ``--out`` (default ``docs/screening``): ``plausible.csv`` (inputs, pair, the judging
metric of every case, whether the premise holds), ``plausible_fraction.csv``,
``plausible_fsd.csv``, ``plausible_importance.csv``, ``plausible_advantage.csv`` (which inputs
decide each FSD's advantage) and ``plausible.json`` (settings, the classifier's held-out accuracy,
wall and CPU time). ``--store DIR`` keeps finished runs there
(a rerun after an interruption does only what is missing).
Usage: ``python scripts/docs/premise_probability.py [--n 200] [--tracks 2] [--store DIR]``.
"""

from __future__ import annotations

import argparse
import json
import resource
import time
from pathlib import Path

from loco.studies import premise_probability as pp
from loco.studies.plausible import advantage_sensitivity, premise_sensitivity


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("docs/screening"))
    parser.add_argument("--n", type=int, default=200)
    parser.add_argument("--tracks", type=int, default=2)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--store", type=Path, default=None)
    parser.add_argument("--no-progress", action="store_true")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    result = pp.run_plausible(
        args.n, args.seed, n_tracks=args.tracks, store=args.store, progress=not args.no_progress
    )
    wall = time.perf_counter() - start
    usage = resource.getrusage(resource.RUSAGE_SELF)
    frame = pp.to_frame(result)
    frame.to_csv(args.out / "plausible.csv", index=False, float_format="%.6g")
    summary = pp.summarise(result)
    summary["fraction"].to_csv(
        args.out / "plausible_fraction.csv", index=False, float_format="%.4g"
    )
    summary["fsd"].to_csv(args.out / "plausible_fsd.csv", index=False, float_format="%.4g")
    sens = premise_sensitivity(result, seed=args.seed)
    advantage_sensitivity(result, seed=args.seed).to_csv(
        args.out / "plausible_advantage.csv", index=False, float_format="%.4g"
    )
    sens["importance"].to_csv(
        args.out / "plausible_importance.csv", index=False, float_format="%.4g"
    )
    meta = {
        **result.settings,
        "failed_runs": result.failed,
        "classifier_accuracy": sens["accuracy"],
        "majority_share": sens["majority"],
        "wall_time_s": round(wall, 1),
        "cpu_time_s": round(usage.ru_utime + usage.ru_stime, 1),
    }
    (args.out / "plausible.json").write_text(json.dumps(meta, indent=2) + "\n", encoding="utf-8")
    print(summary["fraction"].to_string(index=False))
    print(summary["fsd"].to_string(index=False))
    print(sens["importance"].head(10).to_string(index=False))
    print(json.dumps(meta, indent=2))


if __name__ == "__main__":
    main()
