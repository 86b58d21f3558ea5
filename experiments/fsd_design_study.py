"""FSD design study outside ``loco reproduce``: the ``fsd_design`` stage
(:mod:`loco.studies.fsd_design`) at a preset's sizes or at sizes given here.

Usage: ``python experiments/fsd_design_study.py [--preset quick] [--pop N] [--gens N]
[--tracks N] [--conicities 0.02 0.1 ...] [--out out/fsd_design]``. Writes the stage's files
(population, front, conicity sweep, critical speeds, ``fsd_design.png``, ``fsd_design.json``
with the run time) into ``--out``.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import time
from pathlib import Path

from loco.studies import fsd_design


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", choices=sorted(fsd_design.SIZES), default="quick")
    parser.add_argument("--pop", type=int, default=None)
    parser.add_argument("--gens", type=int, default=None)
    parser.add_argument("--tracks", type=int, default=None)
    parser.add_argument("--conicities", type=float, nargs="+", default=None)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--out", type=Path, default=Path("out/fsd_design"))
    args = parser.parse_args()
    sizes = fsd_design.SIZES[args.preset]
    changes = {
        "pop_size": args.pop,
        "n_gen": args.gens,
        "n_tracks": args.tracks,
        "conicities": tuple(args.conicities) if args.conicities else None,
    }
    sizes = dataclasses.replace(sizes, **{k: v for k, v in changes.items() if v is not None})
    start = time.perf_counter()
    record = fsd_design.run_fsd_design(sizes, args.out, seed=args.seed, threads=args.threads)
    print(record.notes)
    print(f"written to {args.out} in {time.perf_counter() - start:.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
