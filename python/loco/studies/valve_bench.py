"""Bench of the FSD's frequency valve: the rms-frequency estimator against the hydraulic valve.

Three pieces, written next to the damper bench (SPEC §6.5) by ``loco damper-bench`` and
``loco reproduce``:

- the valve state against time at 1 Hz and 4 Hz (scale factor, auxiliary piston travel, force:
  the "teeth" of the force while the valve opens and closes within each stroke);
- the hydraulic valve's opening band against stroke amplitude (its cut-off f_c grows with the
  amplitude; the estimator's threshold f_p does not);
- a two-tone bench: a 1.2 Hz stroke of the reference amplitude plus a 5–12 Hz dither of growing
  amplitude, the valve open fraction (time average of 1 - scale factor over the last
  :data:`TAIL_S` s) for each trigger: up to what dither the valve still opens.
"""

from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from loco import dampers
from loco.studies.plotting import pyplot, save_figure
from loco.studies.report import save_table

#: The FSD with each trigger, by the trigger's name (:data:`loco.dampers.TRIGGERS`).
VALVES: dict[str, dampers.Damper] = {
    dampers.TRIGGERS[0]: dampers.FSD,
    "hydraulic": dampers.FSD_HYDRAULIC,
}
#: Frequency of the slow stroke of the two-tone bench, Hz (the S_low carbody sway).
SWAY_HZ = 1.2
#: Dither frequencies, Hz.
DITHER_HZ = (5.0, 8.0, 12.0)
#: Dither amplitude over the stroke amplitude.
DITHER_RATIOS = (0.0, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0)
#: Duration of a two-tone run and the final part averaged, s.
DURATION_S = 14.0
TAIL_S = 8.0
#: Stroke amplitudes of the opening-band curve, m: from below the smallest stroke at which the
#: reference-sized valve opens at all (about 0.15 mm) through its 0.26 mm reference to hunting
#: strokes.
AMPLITUDES_M = tuple(float(a) for a in np.geomspace(0.05e-3, 8e-3, 32))


def open_fraction(result: dampers.BenchResult, tail_s: float = TAIL_S) -> float:
    """Time average of 1 - scale factor (1 fully open, 0 closed) over the last ``tail_s`` s."""
    last = result.time >= result.time[-1] - tail_s
    return float(np.mean(1.0 - result.scale_factor[last]))


def two_tone(
    stroke: float,
    dither_hz: float,
    ratio: float,
    *,
    duration: float = DURATION_S,
    rate: float = 2000.0,
) -> tuple[np.ndarray, np.ndarray]:
    """Time (s) and elongation (m): ``stroke``·(sin 2π·1.2t + ``ratio``·sin 2π·f_d t)."""
    t = np.arange(0.0, duration, 1.0 / rate)
    x = stroke * np.sin(2 * np.pi * SWAY_HZ * t) + ratio * stroke * np.sin(
        2 * np.pi * dither_hz * t
    )
    return t, x


@dataclass(frozen=True)
class ValveBench:
    """Results of :func:`run_valve_bench` (tables, ready to save and plot)."""

    stroke_m: float
    histories: pd.DataFrame
    band: pd.DataFrame
    dither: pd.DataFrame


def run_valve_bench(
    stroke: float = dampers.REFERENCE_STROKE_AMPLITUDE, *, threads: int | None = None
) -> ValveBench:
    """Runs the three benches at the stroke amplitude ``stroke`` (m). The two-tone runs, each
    its own bench, share ``threads`` threads (None: one per core; the native bench releases the
    GIL), and the opening band's amplitudes the native side's threads: the results do not
    depend on either."""
    histories = []
    for name, damper in VALVES.items():
        for f in (1.0, 4.0):
            r = dampers.bench(
                damper, f, stroke, int(8 * f) + 4, steps_per_cycle=2000, samples_per_cycle=200
            )
            histories.append(
                pd.DataFrame(
                    {
                        "trigger": name,
                        "frequency_hz": f,
                        "time_s": r.time,
                        "displacement_m": r.displacement,
                        "force_n": r.force,
                        "scale_factor": r.scale_factor,
                        "valve_volume_m3": r.valve_volume,
                    }
                )
            )
    lower, upper = dampers.valve_opening_band(dampers.FSD_HYDRAULIC, AMPLITUDES_M)
    band = pd.DataFrame({"amplitude_m": AMPLITUDES_M, "lower_hz": lower, "cutoff_hz": upper})
    cases = [
        (name, damper, fd, ratio)
        for name, damper in VALVES.items()
        for fd in DITHER_HZ
        for ratio in DITHER_RATIOS
    ]

    def fraction(case: tuple[str, dampers.Damper, float, float]) -> float:
        _, damper, fd, ratio = case
        return open_fraction(dampers.bench_recorded(damper, *two_tone(stroke, fd, ratio)))

    with ThreadPoolExecutor(max_workers=threads or os.cpu_count() or 1) as pool:
        fractions = list(pool.map(fraction, cases))
    rows = [
        {
            "trigger": name,
            "dither_hz": fd,
            "dither_ratio": ratio,
            "dither_velocity_ratio": ratio * fd / SWAY_HZ,
            "open_fraction": f,
        }
        for (name, _, fd, ratio), f in zip(cases, fractions, strict=True)
    ]
    return ValveBench(stroke, pd.concat(histories, ignore_index=True), band, pd.DataFrame(rows))


def largest_opening_dither(bench: ValveBench, threshold: float = 0.05) -> pd.DataFrame:
    """Per trigger and dither frequency: the largest dither ratio of the grid at which the valve
    is still open at least ``threshold`` of the time (NaN if never)."""
    d = bench.dither
    rows = []
    for (name, fd), g in d.groupby(["trigger", "dither_hz"], sort=False):
        opening = g[g["open_fraction"] >= threshold]["dither_ratio"]
        rows.append(
            {
                "trigger": name,
                "dither_hz": fd,
                "largest_opening_ratio": float(opening.max()) if len(opening) else np.nan,
                "open_fraction_without_dither": float(
                    g[g["dither_ratio"] == 0.0]["open_fraction"].iloc[0]
                ),
            }
        )
    return pd.DataFrame(rows)


def plot_valve_states(bench: ValveBench, path: Path) -> Path:
    """Force, scale factor and (hydraulic) piston travel against time, 1 and 4 Hz."""
    plt = pyplot()
    fig, axes = plt.subplots(3, 2, figsize=(12, 8), sharex="col", layout="constrained")
    h = bench.histories
    opening = float(dampers.FSD_HYDRAULIC.parameters()["opening_volume"] or 1.0)
    for c, f in enumerate((1.0, 4.0)):
        for i, name in enumerate(VALVES):
            g = h[(h["trigger"] == name) & (h["frequency_hz"] == f)]
            axes[0, c].plot(g["time_s"], g["force_n"] / 1e3, lw=0.7, label=name, color=f"C{i}")
            axes[1, c].plot(g["time_s"], g["scale_factor"], lw=0.8, label=name, color=f"C{i}")
            if name == "hydraulic":
                axes[2, c].plot(g["time_s"], g["valve_volume_m3"] / opening, lw=0.8, color=f"C{i}")
        axes[2, c].axhline(1.0, color="k", lw=0.5, ls="--")
        axes[2, c].axhline(-1.0, color="k", lw=0.5, ls="--")
        axes[0, c].set(title=f"{f:g} Hz, {bench.stroke_m * 1e3:.2f} mm", ylabel="force (kN)")
        axes[1, c].set(ylabel="scale factor (0 open, 1 closed)")
        axes[2, c].set(ylabel="aux. piston travel / opening stroke", xlabel="time (s)")
        axes[0, c].legend(fontsize=8)
    for ax in np.ravel(axes):
        ax.grid(True, alpha=0.3)
    fig.suptitle("FSD frequency valve on the bench: rms-frequency estimate vs hydraulic valve")
    return save_figure(fig, path)


def plot_band(bench: ValveBench, path: Path) -> Path:
    """Cut-off (and lower opening limit) of the hydraulic valve against stroke amplitude."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.5, 4.5), layout="constrained")
    b = bench.band
    x = b["amplitude_m"] * 1e3
    ax.fill_between(x, b["lower_hz"], b["cutoff_hz"], alpha=0.25, label="hydraulic: opens")
    ax.plot(x, b["cutoff_hz"], label="hydraulic cut-off f_c")
    ax.axhline(2.0, color="C1", ls="--", label="rms-frequency f_p (±10 % hysteresis)")
    ax.axvline(bench.stroke_m * 1e3, color="k", lw=0.6, ls=":", label="reference stroke")
    ax.set(xscale="log", yscale="log", xlabel="stroke amplitude (mm)", ylabel="frequency (Hz)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    return save_figure(fig, path)


def plot_dither(bench: ValveBench, path: Path) -> Path:
    """Open fraction against dither ratio, one panel per dither frequency, both triggers."""
    plt = pyplot()
    fig, axes = plt.subplots(
        1, len(DITHER_HZ), figsize=(12, 3.8), sharey=True, layout="constrained"
    )
    d = bench.dither
    for ax, fd in zip(axes, DITHER_HZ, strict=True):
        for i, name in enumerate(VALVES):
            g = d[(d["trigger"] == name) & (d["dither_hz"] == fd)]
            ax.plot(g["dither_ratio"], g["open_fraction"], "o-", color=f"C{i}", label=name)
        ax.set(
            title=f"{SWAY_HZ:g} Hz stroke + {fd:g} Hz dither",
            xlabel="dither amplitude / stroke amplitude",
        )
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("valve open fraction (mean of 1 - s)")
    axes[0].legend(fontsize=8)
    return save_figure(fig, path)


def save_valve_bench(bench: ValveBench, out: Path) -> tuple[list[Path], list[Path]]:
    """Figures and tables of the valve bench in ``out``: (figures, tables)."""
    figures = [
        plot_valve_states(bench, out / "valve_states.png"),
        plot_band(bench, out / "valve_cutoff_vs_amplitude.png"),
        plot_dither(bench, out / "valve_two_tone.png"),
    ]
    tables = [
        save_table(bench.histories, out / "valve_states.csv"),
        save_table(bench.band, out / "valve_cutoff_vs_amplitude.csv"),
        save_table(bench.dither, out / "valve_two_tone.csv"),
        save_table(largest_opening_dither(bench), out / "valve_two_tone_limits.csv"),
    ]
    return figures, tables
