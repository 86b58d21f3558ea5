"""Figures of the yaw damper comparison (:mod:`loco.studies.fsd_comparison`): time histories and
valve states on track 0, track-mean PSDs, and the per-track values with their geometric means and
95 % intervals; the wide table of the time histories behind the first figure; and the report
paragraph of the comparison."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

import loco
from loco.studies.fsd_tables import (
    CASES,
    JUDGED_BY,
    VALVE_SUFFIX,
    FsdComparison,
    valve_channels,
    valve_open_fractions,
)
from loco.studies.plotting import draw_intervals, draw_spectra, pyplot, save_figure
from loco.studies.statistics import Ranking

__all__ = [
    "comparison_notes",
    "histories_frame",
    "plot_peaks",
    "plot_psds",
    "plot_time_histories",
    "plot_valves",
]


def plot_time_histories(cmp: FsdComparison, path: str | Path) -> Path:
    """Save A_yc (S_low) and A_yb (S_high) against time, one panel per damper, as PNG."""
    plt = pyplot()
    fig, axes = plt.subplots(
        len(CASES),
        len(cmp.dampers),
        figsize=(4 * len(cmp.dampers), 6.5),
        sharex=True,
        sharey="row",
        squeeze=False,
        layout="constrained",
    )
    for r, (scenario, label, channel) in enumerate(CASES):
        for c, name in enumerate(cmp.dampers):
            ax = axes[r, c]
            result = cmp.results.get((scenario, name))
            if result is None:
                ax.text(0.5, 0.5, "run failed", ha="center", transform=ax.transAxes)
            else:
                ax.plot(result.time, result.channel(channel), lw=0.5, color=f"C{c}")
            ax.set_title(f"{label}, {scenario}, {name}")
            ax.grid(True, alpha=0.3)
            if c == 0:
                ax.set_ylabel(f"{label} (m/s²)")
            if r == len(CASES) - 1:
                ax.set_xlabel("time (s)")
    fig.suptitle(f"{cmp.settings.get('speed_kmh', 0.0):g} km/h, track 0 (loco {loco.__version__})")
    return save_figure(fig, path)


def plot_psds(cmp: FsdComparison, path: str | Path, *, fmax: float = 20.0) -> Path:
    """Save the PSDs of A_yc (S_low) and A_yb (S_high), dampers overlaid, as PNG (0 to ``fmax``
    Hz)."""
    plt = pyplot()
    spectra = cmp.spectra()
    fig, axes = plt.subplots(1, len(CASES), figsize=(11, 4), layout="constrained")
    for ax, (scenario, label, channel) in zip(axes, CASES, strict=True):
        lines = {name: spectra.get((scenario, name)) for name in cmp.dampers}
        draw_spectra(ax, lines, label, f"{label} ({channel}), {scenario}", fmax)
    fig.suptitle(
        f"Mean over {cmp.n_tracks} tracks of the per-track PSDs; legend: the tracks' median "
        "dominant frequency and geometric-mean PSD peak"
    )
    return save_figure(fig, path)


def plot_valves(cmp: FsdComparison, path: str | Path, *, damper: str = "FSD") -> Path:
    """Save the valve state (0 open … 1 closed) of every yaw damper of the ``damper`` runs on
    each scenario against time, one row per yaw damper, as PNG."""
    plt = pyplot()
    runs = [(s, cmp.results.get((s, damper))) for s, _, _ in CASES]
    names = next((valve_channels(r) for _, r in runs if r is not None), [])
    fig, axes = plt.subplots(
        max(1, len(names)),
        len(runs),
        figsize=(11, 1.3 * len(names) + 1.5),
        sharex=True,
        squeeze=False,
        layout="constrained",
    )
    for c, (scenario, result) in enumerate(runs):
        for r, channel in enumerate(names):
            ax = axes[r, c]
            if result is not None:
                ax.fill_between(result.time, result.channel(channel), step="mid", alpha=0.6)
            ax.set_ylim(-0.1, 1.1)
            ax.set_yticks([0, 1], ["open", "closed"])
            ax.set_title(f"{scenario}: {channel.removesuffix(VALVE_SUFFIX)}", fontsize=9)
        axes[-1, c].set_xlabel("time (s)")
    fig.suptitle(
        f"{damper} frequency valve state on track 0 (0 open: low damping; 1 closed: high damping)"
    )
    return save_figure(fig, path)


def plot_peaks(cmp: FsdComparison, path: str | Path) -> Path:
    """Save, per scenario, the PSD peak of its quantity and the metric that judges it
    (:data:`JUDGED_BY`) for every damper as PNG: every track, the geometric mean and its 95 %
    interval."""
    plt = pyplot()
    fig, axes = plt.subplots(2, len(CASES), figsize=(11, 7), squeeze=False, layout="constrained")
    for c, (scenario, label, _) in enumerate(CASES):
        for r, (column, ylabel) in enumerate(
            (("psd_peak", f"PSD peak of {label} ((m/s²)²/Hz)"),
             (JUDGED_BY[scenario], JUDGED_BY[scenario]))
        ):  # fmt: skip
            groups = {d: cmp.values(scenario, d, column) for d in cmp.dampers}
            draw_intervals(axes[r, c], groups, ylabel, f"{scenario}: {ylabel.split(' (')[0]}")
    fig.suptitle(
        f"Yaw dampers over {cmp.n_tracks} tracks (the same for every damper): geometric mean "
        "and 95 % interval"
    )
    return save_figure(fig, path)


def histories_frame(cmp: FsdComparison) -> pd.DataFrame:
    """Wide table on the common time axis: each case's quantity per damper, the valve channels."""
    columns: dict[str, Any] = {}
    for scenario, label, channel in CASES:
        for name in cmp.dampers:
            result = cmp.results.get((scenario, name))
            if result is None:
                continue
            columns.setdefault("time_s", result.time)
            columns[f"{scenario}_{name}_{label}"] = result.channel(channel)
            if cmp.has_valve(name):
                for v in valve_channels(result):
                    columns[f"{scenario}_{name}_{v}"] = result.channel(v)
    length = min((len(v) for v in columns.values()), default=0)
    return pd.DataFrame({k: np.asarray(v)[:length] for k, v in columns.items()})


def comparison_notes(cmp: FsdComparison, summary: pd.DataFrame, rankings: list[Ranking]) -> str:
    """The report paragraph of the comparison: the PSD peaks per case (``summary``,
    :meth:`FsdComparison.table`), the ``rankings``, the valves' open fractions, the failures."""
    lead_in = cmp.settings.get("lead_in_m", 0.0)
    peaks = "; ".join(
        f"{row.scenario} {row.damper}: {row.quantity} dominant {row.dominant_hz:.2f} Hz "
        f"({row.dominant_hz_tracks}), "
        f"PSD peak {row.psd_peak:.3g} [{row.psd_peak_low:.3g}, {row.psd_peak_high:.3g}] "
        "(m/s²)²/Hz"
        for row in summary.itertuples()
    )
    notes = (
        f"Recorded after {lead_in:g} m of lead-in (start transients settled), on "
        f"{cmp.n_tracks} tracks, the same for every damper; dominant frequency the median (each "
        f"track's), PSD peak the geometric mean [95 % interval]: {peaks}.\n\n"
        "**Rankings** (lower is better; `<` a significant step, `≈` none):\n\n"
        + "\n".join(f"- {r.statement()}." for r in rankings)
    )
    openings = valve_open_fractions(cmp)
    bogies = openings[openings["valve"] == openings["bogie"]]
    notes += ". Valve open fraction (1 - mean scale factor) by bogie: " + "; ".join(
        f"{r.scenario} {r.damper} {r.bogie} {r.open_fraction:.2f}" for r in bogies.itertuples()
    )
    if cmp.errors:
        notes += "\n\nFailed: " + "; ".join(f"{s} {d}: {m}" for (s, d), m in cmp.errors.items())
    return notes
