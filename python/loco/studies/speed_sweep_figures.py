"""Figures of the speed sweep (:mod:`loco.studies.speed_sweep`): W_y and A_yb against speed with
their 95 % intervals over the tracks, the track-mean PSDs and the PSD peaks at the PSD speed; and
the report paragraph of the sweep."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import loco
from loco.studies.plotting import draw_intervals, draw_spectra, pyplot, save_figure
from loco.studies.quantities import CHANNELS, PEAK_METRICS
from loco.studies.speed_sweep import SWEEP_METRICS, SpeedSweep
from loco.studies.statistics import Interval, track_values_text

__all__ = ["plot_peaks", "plot_psds", "plot_sweep", "sweep_notes"]


def plot_sweep(sweep: SpeedSweep, path: str | Path) -> Path:
    """Save W_y and A_yb against speed as PNG: one line per scenario through the geometric means,
    error bars the 95 % interval over the tracks, failed runs as × at the bottom."""
    plt = pyplot()
    fig, axes = plt.subplots(1, len(SWEEP_METRICS), figsize=(11, 4), layout="constrained")
    for ax, (metric, label) in zip(axes, SWEEP_METRICS, strict=True):
        for scenario in sweep.scenarios:
            i = sweep.scenarios.index(scenario)
            cis = [sweep.interval(scenario, metric, v) for v in sweep.speeds_kmh]
            mean = np.array([c.mean for c in cis])
            err = np.array([[c.mean - c.low, c.high - c.mean] for c in cis]).T
            line = ax.errorbar(sweep.speeds_kmh, mean, yerr=np.nan_to_num(err), marker="o",
                               ms=3, capsize=3, label=scenario)  # fmt: skip
            failed = (sweep.status[i] != 0).any(axis=1) | ~np.isfinite(mean)
            if failed.any():
                ax.plot(
                    sweep.speeds_kmh[failed],
                    np.full(int(failed.sum()), 0.03),
                    "x",
                    color=line.lines[0].get_color(),
                    ms=8,
                    transform=ax.get_xaxis_transform(),
                )
        ax.axvline(sweep.psd_speed_kmh, color="0.7", lw=0.8, ls="--")
        ax.set(
            xlabel="speed (km/h)",
            ylabel=label,
            title=f"{label.split(' ')[0]}, {sweep.damper_label}",
        )
        ax.set_ylim(bottom=0.0)
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.suptitle(
        f"Speed sweep (loco {loco.__version__}): geometric mean and 95 % interval over "
        f"{sweep.n_tracks} tracks; × = the run failed on a track (the mean is that of the others)"
    )
    return save_figure(fig, path)


def plot_psds(sweep: SpeedSweep, path: str | Path, *, fmax: float = 20.0) -> Path:
    """Save the PSDs of A_yc and A_yb at ``psd_speed_kmh`` (one line per scenario) as PNG;
    ``fmax`` is the upper frequency shown, Hz."""
    channels = sweep.settings.get("channels", CHANNELS)
    fig, axes = pyplot().subplots(1, len(channels), figsize=(11, 4), layout="constrained")
    for ax, (label, channel) in zip(axes, channels.items(), strict=True):
        lines = {sc: sweep.spectra.get((sc, label)) for sc in sweep.scenarios}
        title = f"{label} ({channel}), {sweep.psd_speed_kmh:g} km/h, {sweep.damper_label}"
        draw_spectra(ax, lines, label, title, fmax)
    fig.suptitle(
        f"Mean over {sweep.n_tracks} tracks of the per-track PSDs; legend: the tracks' median "
        "dominant frequency and geometric-mean PSD peak"
    )
    return save_figure(fig, path)


def plot_peaks(sweep: SpeedSweep, path: str | Path) -> Path:
    """Save the PSD peaks of A_yc and A_yb at ``psd_speed_kmh`` per scenario as PNG: every
    track, the geometric mean and its 95 % interval."""
    plt = pyplot()
    fig, axes = plt.subplots(1, len(PEAK_METRICS), figsize=(11, 4), layout="constrained")
    i = sweep.speed_index(sweep.psd_speed_kmh)
    for ax, (label, (_, peak)) in zip(axes, PEAK_METRICS.items(), strict=True):
        values = sweep.metric(peak)
        groups = {s: values[k, i] for k, s in enumerate(sweep.scenarios)}
        draw_intervals(ax, groups, f"PSD peak of {label} ((m/s²)²/Hz)",
                       f"{label}, {sweep.psd_speed_kmh:g} km/h, {sweep.damper_label}")  # fmt: skip
    fig.suptitle(f"PSD peaks over {sweep.n_tracks} tracks: geometric mean and 95 % interval")
    return save_figure(fig, path)


def _ci(interval: Interval) -> str:
    return f"{interval.mean:.3g} [{interval.low:.3g}, {interval.high:.3g}]"


def sweep_notes(sweep: SpeedSweep) -> str:
    """The report paragraph of the sweep: W_y and A_yb at the PSD speed (geometric mean and
    interval over the tracks), the dominant frequencies (median and every track's), failures."""
    v = sweep.psd_speed_kmh
    parts = [
        f"{s}: W_y {_ci(sweep.interval(s, 'wy_max', v))}, "
        f"A_yb {_ci(sweep.interval(s, 'ayb_peak_lp', v))} m/s²"
        for s in sweep.scenarios
    ]
    dominant = []
    for s in sweep.scenarios:
        for q, (frequency, _) in PEAK_METRICS.items():
            median, each = sweep.median(s, frequency, v)
            dominant.append(f"{s} {q} {median:.3g} Hz ({track_values_text(each)})")
    n_failed = int((sweep.status != 0).sum())
    notes = (
        f"At {v:g} km/h with {sweep.damper_label}, geometric mean [95 % interval] over "
        f"{sweep.n_tracks} tracks: " + "; ".join(parts) + ". Dominant frequency of the PSD, the "
        "median over the tracks (each track's value): " + "; ".join(dominant) + "."
    )
    if n_failed:
        notes += (
            f" {n_failed} of {sweep.status.size} runs failed (× in the figure, NaN in the CSV)."
        )
    return notes
