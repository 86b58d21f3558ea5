"""Cost of a curved run against a straight one (same vehicle, speed, distance, perfect track).

Usage: python experiments/curve_cost.py [repeats]. Prints the best wall time of each and the ratio.
"""

from __future__ import annotations

import sys
import time

import loco

SPEED = 28.08  # m/s: balances 100 mm cant at R = 1200 m
CURVE = [
    {"kind": "straight", "length_m": 10.0},
    {"kind": "transition", "length_m": 60.0},
    {
        "kind": "curve",
        "length_m": 1000.0,
        "radius_m": 1200.0,
        "cant_mm": 100.0,
        "direction": "left",
    },
]


def best(curve: object, repeats: int) -> tuple[float, float]:
    times = []
    evaluations = 0.0
    for _ in range(repeats):
        scenario = loco.Scenario(
            name="S_norm", speed=SPEED, distance=300.0, track="perfect", curve=curve
        )
        started = time.perf_counter()
        result = loco.simulate(loco.Locomotive(), scenario)
        times.append(time.perf_counter() - started)
        evaluations = result.statistics["rhs_evaluations"]
    return min(times), evaluations


def main() -> None:
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    straight, n_straight = best(None, repeats)
    curved, n_curved = best(CURVE, repeats)
    print(f"straight: {straight:.3f} s ({n_straight:.0f} evaluations)")
    print(f"curved:   {curved:.3f} s ({n_curved:.0f} evaluations)")
    print(f"ratio:    {curved / straight:.3f}")


if __name__ == "__main__":
    main()
