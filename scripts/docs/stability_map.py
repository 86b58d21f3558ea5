"""Stability map: linear critical speed against equivalent conicity for YD1, YD2 and the FSD with
its valve fixed open (c1) and fixed closed (c2).

The conicity sweep uses a conical wheel on a knife-edge rail (``loco.critical_speed(...,
conicity=)``: Δr = 2·conicity·y exactly); the three built-in wheel/rail pairs of the study
(S_low, S_norm, S_high, real profiles) are added as points at their EN 15302 equivalent conicity
(3 mm). The FSD with a fixed valve is its damping module, c1 = 200 or c2 = 800 kN·s/m with
k = 15 kN/mm and m = 15 kg: the linearisation keeps the valve's scale factor at its start value
(checked: the open FSD gives the critical speed of a 200 kN·s/m, 15 kN/mm Maxwell element,
240.6 km/h at conicity 0.3, to the bisection tolerance). Nonlinear critical speeds at the three
scenarios are optional (``--nonlinear``: a speed ramp-down from 300 km/h after the core's default
disturbance, about a minute; ``inf`` when the vehicle does not hunt at 300 km/h); they add the FSD
with its working valve, both triggers (:data:`WORKING_VALVE`), whose valve moves in the ramp.

Writes ``stability_map.png``, ``stability_map.csv`` (conicity sweep), ``stability_map_wheels.csv``
(built-in pairs) and ``stability_map.json`` (loco version and settings) into ``--out``.
Usage:
``python scripts/docs/stability_map.py [--out out/stability_map] [--points 16] [--nonlinear]``.
"""

from __future__ import annotations

import argparse
import json
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pandas as pd

import loco
from loco import dampers
from loco.conicity import equivalent_conicity
from loco.studies.plotting import pyplot, save_figure

#: The yaw damper laws of the map, by name. The linearisation holds the FSD's discrete state
#: at its start value, so ``start_closed`` fixes the valve open (c1) or closed (c2).
LAWS: dict[str, dampers.Damper] = {
    "YD1": dampers.YD1,
    "YD2": dampers.YD2,
    "FSD open (c1)": dampers.fsd(start_closed=False),
    "FSD closed (c2)": dampers.fsd(start_closed=True),
}
#: In a time simulation the FSD's trigger moves its valve, so the nonlinear critical speed of the
#: FSD with a fixed valve uses its damping module as a Maxwell element (c1 or c2 with k; the
#: 15 kg equivalent mass left out, a relative effect m·ω²/k of 10⁻³ at 5 Hz).
_FSD = dampers.FSD.parameters()
FIXED_VALVE: dict[str, dampers.Damper] = {
    "FSD open (c1)": dampers.maxwell(
        float(_FSD["low_damping"] or 0.0), float(_FSD["equivalent_stiffness"] or 0.0)
    ),
    "FSD closed (c2)": dampers.maxwell(
        float(_FSD["high_damping"] or 0.0), float(_FSD["equivalent_stiffness"] or 0.0)
    ),
}
#: The FSD with its valve working (nonlinear only: its linear critical speed is the closed
#: valve's, the linearisation holding the valve in its start state), by trigger.
WORKING_VALVE: dict[str, dampers.Damper] = {
    "FSD (rms-frequency valve)": dampers.FSD,
    "FSD-H (hydraulic valve)": dampers.FSD_HYDRAULIC,
}
#: Study scenarios and their wheel/rail pairs (``vehicle/scenarios/scenario.rs``).
PAIRS = {"S_low": "jm3-thin-flange", "S_norm": "jm3-new", "S_high": "jm3-worn"}
HIGH = 150.0  # m/s: top of the bisection (540 km/h); inf above it
RAMP_START = 300.0 / 3.6  # m/s: start of the nonlinear ramp-down


def scenario(yaw_damper: dampers.Damper, name: str | None = None) -> loco.Scenario:
    return loco.Scenario(
        name=name or "S_norm", speed=200 / 3.6, distance=100.0, yaw_damper=yaw_damper
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("out/stability_map"))
    parser.add_argument("--points", type=int, default=16, help="conicities in 0.02-0.8")
    parser.add_argument("--nonlinear", action="store_true", help="add ramp-down critical speeds")
    args = parser.parse_args()
    start = time.perf_counter()
    vehicle = loco.Locomotive.default()
    conicities = np.geomspace(0.02, 0.8, args.points)
    rows = []
    for name, law in LAWS.items():
        for c in conicities:
            try:
                v, error = (
                    loco.critical_speed(vehicle, scenario(law), high=HIGH, conicity=float(c)),
                    "",
                )
            except loco.ContactError as e:
                # The cone on knife-edge pair's contact table cannot be built at every conicity.
                v, error = float("nan"), str(e)
            rows.append(
                {
                    "damper": name,
                    "conicity": float(c),
                    "critical_speed_kmh": v * 3.6,
                    "error": error,
                }
            )
            print(f"{name:>16} conicity {c:.3f}: {v * 3.6:.0f} km/h {error[:60]}", flush=True)
    sweep = pd.DataFrame(rows)
    wheel_laws = {**LAWS, **(WORKING_VALVE if args.nonlinear else {})}
    jobs = [(pair, wheel, name) for pair, wheel in PAIRS.items() for name in wheel_laws]
    conicity = {pair: equivalent_conicity(wheel, "cn60") for pair, wheel in PAIRS.items()}

    def wheel_row(job: tuple[str, str, str]) -> dict[str, object]:
        pair, wheel, name = job
        law = wheel_laws[name]
        row: dict[str, object] = {
            "scenario": pair,
            "wheel": wheel,
            "conicity": conicity[pair],
            "damper": name,
        }
        row["linear_kmh"] = loco.critical_speed(vehicle, scenario(law, pair), high=HIGH) * 3.6
        if args.nonlinear:
            fixed = FIXED_VALVE.get(name, law)
            s = loco.Scenario(name=pair, speed=RAMP_START, distance=100.0, yaw_damper=fixed)
            try:
                ramp = loco.stability.ramp_down(vehicle, s)
                row["nonlinear_kmh"] = ramp.critical_speed * 3.6
                row["nonlinear_outcome"] = ramp.outcome
                # The hunting amplitude in the last window at the start speed (the settled limit
                # cycle, or what is left of the disturbance when it died out), m → mm.
                held = np.asarray(ramp.amplitude)[np.asarray(ramp.speed) >= RAMP_START - 1e-9]
                row["start_amplitude_mm"] = float(held[-1]) * 1e3 if len(held) else float("nan")
            except loco.SimulationError as e:
                row["nonlinear_kmh"], row["nonlinear_error"] = float("nan"), str(e)
        print(f"{pair} ({conicity[pair]:.3f}) {name}: {row}", flush=True)
        return row

    # The rows on two threads (the core releases the GIL); the numbers do not depend on it.
    with ThreadPoolExecutor(2) as pool:
        wheel_rows = list(pool.map(wheel_row, jobs))
    wheels = pd.DataFrame(wheel_rows)
    args.out.mkdir(parents=True, exist_ok=True)
    sweep.to_csv(args.out / "stability_map.csv", index=False)
    wheels.to_csv(args.out / "stability_map_wheels.csv", index=False)
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 5), layout="constrained")
    cap = HIGH * 3.6
    for i, name in enumerate(LAWS):
        g = sweep[sweep["damper"] == name]
        v = g["critical_speed_kmh"].clip(upper=cap)
        ax.plot(g["conicity"], v, "o-", ms=3, color=f"C{i}", label=name)
        stable = g["critical_speed_kmh"] == np.inf
        ax.plot(g["conicity"][stable], v[stable], "^", ms=7, color=f"C{i}")
        w = wheels[wheels["damper"] == name]
        ax.plot(
            w["conicity"], w["linear_kmh"].clip(upper=cap), "s", ms=8, mfc="none", color=f"C{i}"
        )
        if "nonlinear_kmh" in w:
            # Nonlinear (ramp-down) critical speeds beside the linear squares.
            ax.plot(
                w["conicity"] * 1.04,
                w["nonlinear_kmh"].clip(upper=cap),
                "x",
                ms=8,
                color=f"C{i}",
                label="nonlinear (ramp-down), all dampers" if i == 0 else None,
            )
    for k, name in enumerate(WORKING_VALVE):
        w = wheels[wheels["damper"] == name]
        if len(w):
            ax.plot(
                w["conicity"] * 1.08,
                w["nonlinear_kmh"].clip(upper=cap),
                "P*"[k % 2],
                ms=9,
                color=f"C{len(LAWS) + k}",
                label=f"{name}, nonlinear",
            )
    for pair, g in wheels.groupby("scenario"):
        ax.annotate(str(pair), (g["conicity"].iloc[0], cap * 1.02), fontsize=8, ha="center")
    failed = sweep[sweep["error"] != ""]["conicity"]
    if len(failed):
        ax.axvspan(
            failed.min(), conicities.max(), color="0.85", label="cone pair: no contact table"
        )
    ax.axhline(200.0, color="k", lw=0.6, ls=":", label="200 km/h")
    ax.set(
        xscale="log",
        xlabel="equivalent conicity (–)",
        ylabel="linear critical speed (km/h)",
        title="Cone on knife-edge rail (lines), built-in wheels on CN60 (squares: linear,\n"
        f"crosses: nonlinear ramp-down); triangles: stable up to {HIGH * 3.6:.0f} km/h",
    )
    ax.title.set_fontsize(9)
    ax.set_xticks([0.02, 0.05, 0.1, 0.2, 0.5, 0.8], ["0.02", "0.05", "0.1", "0.2", "0.5", "0.8"])
    ax.minorticks_off()
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save_figure(fig, args.out / "stability_map.png")
    settings = {
        "loco_version": loco.__version__,
        "conicities": conicities.tolist(),
        "high_mps": HIGH,
        "dampers": {n: dampers.describe(d) for n, d in wheel_laws.items()},
        "seconds": time.perf_counter() - start,
    }
    (args.out / "stability_map.json").write_text(json.dumps(settings, indent=2))
    print(f"written to {args.out} in {settings['seconds']:.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
