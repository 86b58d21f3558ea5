"""Measure the yaw damper stroke of the S_low carbody sway: the reference stroke amplitude of the
hydraulic FSD frequency valve (``crates/loco-core/src/dampers/frequency_valve.rs``).

Runs S_low at 200 km/h with YD1 yaw dampers (the damping the FSD should have on the sway) on the
default synthetic track, and rebuilds each yaw damper's elongation from its recorded force: a
Maxwell element ``F = k·(x - x_d)``, ``ẋ_d = F/c`` gives ``x = F/k + (1/c)·∫F dt`` exactly (the
integration constant is the static length, removed with the mean). The sway stroke is the part of
the elongation in the sway band (default 0.5–2 Hz: below f_p = 2 Hz, above the valve's lowest
opening frequency f_p/4), band-passed with a zero-phase Butterworth filter; its amplitude is
given as a sine's, √2·rms. Prints one line per yaw damper and the median, and writes a JSON file
with the numbers and settings (``--out``).

Usage: ``python experiments/fsd_reference_stroke.py [--seed 0] [--distance 500] [--out FILE]``.
Re-run it after changes to the vehicle or track model and pass the new median to
``loco.dampers.fsd(trigger="hydraulic", reference_stroke_amplitude=...)``.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np
from scipy import integrate, signal

import loco
from loco import dampers


def yaw_damper_strokes(result: loco.SimulationResult, damping: float, stiffness: float) -> dict:
    """Elongation (m) of every yaw damper, rebuilt from its force channel."""
    strokes = {}
    for name in result.channel_names:
        if name.startswith("yaw_damper") and name.endswith("_force"):
            force = np.asarray(result.channel(name))
            x = (
                force / stiffness
                + integrate.cumulative_trapezoid(force, result.time, initial=0.0) / damping
            )
            strokes[name.removesuffix("_force")] = x - np.mean(x)
    return strokes


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--speed-kmh", type=float, default=200.0)
    parser.add_argument("--distance", type=float, default=500.0)
    parser.add_argument("--lead-in", type=float, default=100.0)
    parser.add_argument("--band", type=float, nargs=2, default=(0.5, 2.0), help="sway band, Hz")
    parser.add_argument("--out", type=Path, default=Path("out/fsd_reference_stroke.json"))
    args = parser.parse_args()
    p = dampers.YD1.parameters()
    damping, stiffness = float(p["damping"]), float(p["series_stiffness"])
    scenario = loco.Scenario(
        name="S_low",
        speed=args.speed_kmh / 3.6,
        distance=args.distance,
        lead_in=args.lead_in,
        seed=args.seed,
        yaw_damper=dampers.YD1,
    )
    result = loco.simulate(loco.Locomotive.default(), scenario)
    fs = 1.0 / float(np.median(np.diff(result.time)))
    sos = signal.butter(4, args.band, btype="bandpass", fs=fs, output="sos")
    rows = {}
    for name, x in yaw_damper_strokes(result, damping, stiffness).items():
        sway = signal.sosfiltfilt(sos, x)
        rows[name] = {
            "sway_amplitude_m": float(np.sqrt(2.0) * np.std(sway)),
            "total_rms_m": float(np.std(x)),
            "sway_rms_m": float(np.std(sway)),
        }
        print(
            f"{name}: sway amplitude {rows[name]['sway_amplitude_m'] * 1e3:.3f} mm "
            f"(sway rms {np.std(sway) * 1e3:.3f} mm, total rms {np.std(x) * 1e3:.3f} mm)"
        )
    if not rows:
        raise SystemExit("no yaw damper force channels in the run")
    median = float(np.median([r["sway_amplitude_m"] for r in rows.values()]))
    print(f"median sway stroke amplitude: {median * 1e3:.3f} mm")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    record = {
        "loco_version": loco.__version__,
        "scenario": "S_low",
        "speed_kmh": args.speed_kmh,
        "distance_m": args.distance,
        "lead_in_m": args.lead_in,
        "track_seed": args.seed,
        "yaw_damper": dampers.describe(dampers.YD1),
        "band_hz": list(args.band),
        "dampers": rows,
        "median_sway_amplitude_m": median,
    }
    args.out.write_text(json.dumps(record, indent=2))
    print(f"written to {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
