"""Step-size convergence of the locomotive model across the study's parameter ranges.

For the nominal vehicle and Latin-hypercube samples of the six SPEC §6 parameters, runs S_low
(W_y) and S_high (A_yb) at 200 km/h over 500 m with the scheme ``--integrator`` (default: the
model's, etdrk4) at the step ``--step`` (default: that scheme's, 2 ms for etdrk4 and 1 ms for
rk4) and with half of it, and prints the relative change of each metric. The issue's criterion:
below 1 % everywhere. `cargo test --release --test parameter_box` checks the nominal vehicle and
two corners of the box on every CI run.

    python scripts/verify/convergence_study.py [--samples 8] [--integrator etdrk4] [--step 2e-3]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from scipy.stats import qmc

import loco
from loco.channels import Metric

RANGES = {  # SPEC §6, SI units
    "K_px": (10e6, 50e6),
    "K_py": (2e6, 10e6),
    "C_sx": (200e3, 1200e3),
    "C_sy": (10e3, 60e3),
    "K_ncsx": (10e6, 50e6),
    "K_ncsy": (10e6, 50e6),
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--samples", type=int, default=8)
    parser.add_argument(
        "--integrator", choices=loco.simulation.INTEGRATORS, default=loco.Scenario.integrator
    )
    parser.add_argument("--step", type=float, default=None, help="s (default: the scheme's)")
    parser.add_argument("--grid", type=int, default=10)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    step = args.step if args.step is not None else loco.simulation.INTEGRATOR_STEPS[args.integrator]

    lower = np.array([r[0] for r in RANGES.values()])
    upper = np.array([r[1] for r in RANGES.values()])
    unit = qmc.LatinHypercube(d=len(RANGES), seed=args.seed).random(args.samples)
    samples = [dict.fromkeys(RANGES, None)] + [
        dict(zip(RANGES, lower + u * (upper - lower), strict=True)) for u in unit
    ]
    worst = {"S_low": 0.0, "S_high": 0.0}
    metric = {"S_low": Metric.WY_MAX, "S_high": Metric.AYB_PEAK_LP}
    start = time.perf_counter()
    for i, sample in enumerate(samples):
        overrides = {k: float(v) for k, v in sample.items() if v is not None}
        vehicle = loco.Locomotive(overrides=overrides)
        for name in ("S_low", "S_high"):
            values = []
            for dt in (step, step / 2):
                scenario = loco.Scenario(
                    name=name,
                    speed=200 / 3.6,
                    distance=500.0,
                    seed=args.seed,
                    integrator=args.integrator,
                    step=dt,
                    fastsim_grid=(args.grid, args.grid),
                )
                values.append(loco.simulate(vehicle, scenario).metrics[metric[name]])
            change = abs(values[1] - values[0]) / abs(values[1])
            worst[name] = max(worst[name], change)
            print(
                f"sample {i:2d} {name:6s} {metric[name]:12s} dt={values[0]:.5f} "
                f"dt/2={values[1]:.5f} change={100 * change:.3f} %",
                flush=True,
            )
    elapsed = time.perf_counter() - start
    print(
        f"worst change: W_y (S_low) {100 * worst['S_low']:.3f} %, "
        f"A_yb (S_high) {100 * worst['S_high']:.3f} % ({elapsed:.0f} s)"
    )


if __name__ == "__main__":
    main()
