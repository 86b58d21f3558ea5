"""The FSD with each valve model on the vehicle, over several track seeds: the measurement behind
the choice of the default trigger (docs/guide/dampers.md, "The FSD's frequency valve").

Runs :func:`loco.studies.fsd_comparison.run_fsd_comparison` (S_low and S_high, 200 km/h, 500 m
after 500 m of lead-in) for YD1, YD2, FSD (rms-frequency trigger) and FSD-H (hydraulic valve) on
each seed, and prints and writes (``--out``) the A_yc / A_yb rms, PSD peak and W_y of every run
and the valve open fraction (time average of 1 - scale factor) per yaw damper and per bogie.

Usage: ``python experiments/fsd_valve_vehicle.py [--seeds 0 1 2 3] [--out out/fsd_valve_vehicle]``.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import pandas as pd

from loco import dampers
from loco.channels import Metric
from loco.studies import fsd_comparison as fc

LAWS = {"YD1": dampers.YD1, "YD2": dampers.YD2, "FSD": dampers.FSD, "FSD-H": dampers.FSD_HYDRAULIC}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, nargs="+", default=[0, 1, 2, 3])
    parser.add_argument("--out", type=Path, default=Path("out/fsd_valve_vehicle"))
    args = parser.parse_args()
    tables, openings = [], []
    for seed in args.seeds:
        cmp = fc.run_fsd_comparison(fc.FsdComparisonStage(seed=seed, damper_set=LAWS))
        tables.append(cmp.table().assign(seed=seed))
        openings.append(fc.valve_open_fractions(cmp).assign(seed=seed))
    table = pd.concat(tables, ignore_index=True)
    opening = pd.concat(openings, ignore_index=True)
    pd.set_option("display.width", 200)
    print(
        table.pivot_table(
            index=["scenario", "damper"], columns="seed", values=["rms", "psd_peak", Metric.WY_MAX]
        )
        .round(3)
        .to_string()
    )
    bogies = opening[opening["valve"] == opening["bogie"]]
    print(
        bogies.pivot_table(
            index=["scenario", "damper", "bogie"], columns="seed", values="open_fraction"
        )
        .round(3)
        .to_string()
    )
    args.out.mkdir(parents=True, exist_ok=True)
    table.to_csv(args.out / "fsd_valve_vehicle_summary.csv", index=False)
    opening.to_csv(args.out / "fsd_valve_vehicle_open_fraction.csv", index=False)
    print(f"written to {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
