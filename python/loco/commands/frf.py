"""``loco frf``: the frequency response of the linearised vehicle to track irregularities and its
output PSDs on a random track (the linear stochastic method; :mod:`loco.track_response`).

Writes ``frf.png`` (|H| and phase per output, each with its unit; couplings at the numerical
noise of the symmetric model are left out of the figure and named on it), ``frf_psd.png``
(output PSDs), ``frf.csv`` (frequency, output, input, real and imaginary part, |H| and phase),
``frf_psd.csv`` (frequency, output, PSD), ``frf_summary.csv`` (rms per output and W_y, with
units) and ``frf_parameters.json`` (loco version and every setting).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd

import loco
from loco import dampers
from loco.commands.arguments import UsageError, output_dir, positive_float, positive_int
from loco.studies.report import save_json, save_table
from loco.track_response import DEFAULT_OUTPUTS, INPUTS

NAME = "frf"
HELP = "frequency response of the linearised vehicle to track irregularities and output PSDs"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--out", type=Path, default=Path("out/frf"), help="output directory")
    parser.add_argument("--scenario", default="S_low", choices=list(loco.simulation.SCENARIOS))
    parser.add_argument(
        "--damper", default="YD2", choices=sorted(dampers.PRESETS), help="yaw damper preset"
    )
    parser.add_argument("--speed", type=positive_float, default=200.0, help="running speed (km/h)")
    parser.add_argument("--inputs", nargs="+", default=list(INPUTS), help="irregularity channels")
    parser.add_argument(
        "--outputs", nargs="+", default=list(DEFAULT_OUTPUTS), help="recorded channel names"
    )
    parser.add_argument("--f-min", type=positive_float, default=0.1, help="lowest frequency (Hz)")
    parser.add_argument("--f-max", type=positive_float, default=20.0, help="highest frequency (Hz)")
    parser.add_argument("--n", type=positive_int, default=200, help="number of frequencies")
    parser.add_argument("--spectrum", default="cn-hsr", help="track spectrum of the PSDs")
    parser.add_argument("--vehicle", type=Path, default=None, help="vehicle TOML file")


def run(args: argparse.Namespace) -> int:
    if args.f_max <= args.f_min:
        raise UsageError(f"argument --f-max: must exceed --f-min ({args.f_min:g} Hz)")
    out = output_dir(args.out)
    vehicle = (
        loco.Locomotive.default()
        if args.vehicle is None
        else loco.Locomotive.from_toml(args.vehicle)
    )
    scenario = loco.Scenario(
        name=args.scenario,
        speed=float(args.speed) / 3.6,
        yaw_damper=dampers.PRESETS[args.damper],
        spectrum=args.spectrum,
    )
    f = np.linspace(float(args.f_min), float(args.f_max), int(args.n))
    h = loco.frequency_response(vehicle, scenario, args.inputs, args.outputs, f)
    psd = loco.response_psd(vehicle, scenario, args.outputs, f)
    h.plot(out / "frf.png")
    psd.plot(out / "frf_psd.png")
    rows = [
        {
            "frequency_hz": f[k],
            "output": o,
            "input": i,
            "real": h.h[a, b, k].real,
            "imag": h.h[a, b, k].imag,
            "abs": abs(h.h[a, b, k]),
            "phase_deg": float(np.degrees(np.angle(h.h[a, b, k]))),
        }
        for a, o in enumerate(h.outputs)
        for b, i in enumerate(h.inputs)
        for k in range(len(f))
    ]
    save_table(pd.DataFrame(rows), out / "frf.csv")
    save_table(
        pd.DataFrame(
            [
                {"frequency_hz": f[k], "output": o, "psd": psd.psd[a, k]}
                for a, o in enumerate(psd.outputs)
                for k in range(len(f))
            ]
        ),
        out / "frf_psd.csv",
    )
    summary = [
        {"quantity": f"rms_{o}", "value": v, "unit": psd.units.get(o, "")}
        for o, v in psd.rms.items()
    ]
    summary.append({"quantity": "W_y", "value": psd.sperling_lateral, "unit": "–"})
    summary.append(
        {"quantity": "least_damping_ratio", "value": psd.least_damping_ratio, "unit": "–"}
    )
    save_table(pd.DataFrame(summary), out / "frf_summary.csv")
    save_json(
        {
            "loco_version": loco.__version__,
            "scenario": args.scenario,
            "damper": args.damper,
            "speed_kmh": float(args.speed),
            "inputs": list(args.inputs),
            "outputs": list(args.outputs),
            "frequencies_hz": [float(args.f_min), float(args.f_max), int(args.n)],
            "spectrum": args.spectrum,
            "vehicle": None if args.vehicle is None else str(args.vehicle),
        },
        out / "frf_parameters.json",
    )
    for row in summary:
        print(f"{row['quantity']}: {row['value']:.4g} {row['unit']}")
    if not psd.stable:
        print("warning: the linear model is unstable here; the spectra are not a steady state")
    print(f"written to {out}")
    return 0
