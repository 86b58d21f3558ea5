"""S_low and S_high at 200 km/h with the YD2 yaw damper: carbody floor (A_yc) and bogie frame
(A_yb) lateral accelerations and their PSDs, saved as ``ride_and_stability.png``.

    python examples/ride_and_stability.py [--out DIR]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import loco
import loco.dampers
import loco.metrics

#: Run metric of the dominant frequency of each quantity (Hz).
DOMINANT_HZ = {"A_yc": "ayc_dominant_hz", "A_yb": "ayb_f0_hz"}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", type=Path, default=Path("."))
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)

    vehicle = loco.Locomotive.default()
    channels = loco._loco.metric_channels()  # the channels the core computes the metrics from
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), constrained_layout=True)
    for row, (name, label) in enumerate([("S_low", "A_yc"), ("S_high", "A_yb")]):
        channel = channels[label]
        scenario = loco.Scenario(name=name, speed=200 / 3.6, yaw_damper=loco.dampers.YD2)
        result = loco.simulate(vehicle, scenario)
        signal = result.channel(channel)
        f, p = loco.metrics.psd(signal, result.sampling_rate)
        peak = result.metrics[DOMINANT_HZ[label]]  # the core's PSD peak search
        axes[row, 0].plot(result.time, signal, lw=0.6)
        axes[row, 0].set(xlabel="time (s)", ylabel=f"{label} (m/s²)", title=f"{name}, YD2")
        axes[row, 1].semilogy(f, p)
        axes[row, 1].set(
            xlabel="frequency (Hz)", ylabel=f"PSD of {label} ((m/s²)²/Hz)", xlim=(0, 20)
        )
        axes[row, 1].set_title(f"dominant {peak:.2f} Hz")
        print(
            f"{name}: W_y = {result.metrics['wy_max']:.2f}, "
            f"A_yb peak = {result.metrics['ayb_peak_lp']:.2f} m/s², {label} dominant {peak:.2f} Hz"
        )
    fig.savefig(args.out / "ride_and_stability.png", dpi=120)


if __name__ == "__main__":
    main()
