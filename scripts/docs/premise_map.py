"""The premise map of the default vehicle (``loco.studies.premise_modes``): the carbody and bogie
modes at 200 km/h over conicity 0.01–0.15 for a cone on a knife-edge rail and a cone on CN60,
and the real wheel/rail pairs, each with yaw damping 100–1000 kN·s/m; and the two modes over
speed with YD1 and YD2.

Writes into ``--out`` (default ``docs/screening``): ``premise_map.csv``, ``premise_speed.csv``,
``premise_cells.csv`` (where the premise and its reverse hold) and ``premise_map.png``.
Usage: ``python scripts/docs/premise_modes.py [--out docs/screening] [--workers 2]``.
"""

from __future__ import annotations

import argparse
import os
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from loco.studies import premise_modes as pm


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("docs/screening"))
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    with ProcessPoolExecutor(max_workers=args.workers) as pool:
        result = pm.premise_map(executor=pool)
        sweep = pm.speed_sweep(executor=pool)
    wall = time.perf_counter() - start
    result.to_csv(args.out / "premise_map.csv", index=False, float_format="%.6g")
    sweep.to_csv(args.out / "premise_speed.csv", index=False, float_format="%.6g")
    cells = pm.premise_cells(result)
    cells.to_csv(args.out / "premise_cells.csv", index=False, float_format="%.6g")
    pm.plot_premise_map(result, sweep, path=args.out / "premise_map.png")
    print(f"{len(result) // 2 + len(sweep) // 2} eigen analyses in {wall:.0f} s")
    print(cells[cells["premise"] | cells["reverse"]].to_string(index=False))


if __name__ == "__main__":
    main()
