"""Speed sweep of SPEC §6.1: W_y and A_yb against speed for S_low, S_norm and S_high with the YD2
yaw damper, and the PSDs of A_yc and A_yb at 200 km/h.

One ``loco.run_batch`` per scenario, one row per speed (the batch's ``speed`` column, m/s), all on
the same synthesised track (``seed``) over the same ``distance``; the time histories of the row at
``psd_speed_kmh`` are kept for the PSDs.

Quantities (names of the package's channels and metrics):

- W_y: Sperling lateral ride index, metric ``wy_max`` (largest 5 s segment index);
- A_yb: bogie frame lateral acceleration above the leading wheelset, 10 Hz low-passed peak,
  metric ``ayb_peak_lp`` (m/s²), channel ``frame1_ay_wheelset1``;
- A_yc: carbody floor lateral acceleration above the leading bogie, channel
  ``carbody_floor_ay_front`` (m/s²).
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
import pandas as pd

import loco
from loco import dampers, metrics
from loco.studies.report import StudyRecord, save_json, save_table

__all__ = [
    "A_YB",
    "A_YC",
    "SCENARIOS",
    "SpeedSweep",
    "plot_psds",
    "plot_sweep",
    "run_speed_sweep",
    "save_speed_sweep",
]

FloatArray = npt.NDArray[np.float64]

#: The three wheel states of SPEC §2.
SCENARIOS: tuple[str, ...] = ("S_low", "S_norm", "S_high")
#: (label, channel) of the carbody floor lateral acceleration A_yc.
A_YC: tuple[str, str] = ("A_yc", "carbody_floor_ay_front")
#: (label, channel) of the bogie frame lateral acceleration A_yb.
A_YB: tuple[str, str] = ("A_yb", "frame1_ay_wheelset1")
#: Metrics plotted against speed: (metric name, axis label).
SWEEP_METRICS: tuple[tuple[str, str], ...] = (
    ("wy_max", "W_y (Sperling, lateral)"),
    ("ayb_peak_lp", "A_yb peak, 10 Hz low-pass (m/s²)"),
)


@dataclass(frozen=True)
class Spectrum:
    """Welch PSD of one channel of one run and its peak (by :mod:`loco.metrics`)."""

    frequency: FloatArray
    """Frequencies, Hz."""
    density: FloatArray
    """PSD, (m/s²)²/Hz."""
    dominant_hz: float
    """Frequency of the PSD peak (above 0.2 Hz), Hz."""
    peak: float
    """PSD at the peak, (m/s²)²/Hz."""


def spectrum(signal: FloatArray, fs: float) -> Spectrum:
    """The :class:`Spectrum` of ``signal`` (m/s²) sampled at ``fs`` (Hz), by :mod:`loco.metrics`."""
    f, p = metrics.psd(signal, fs)
    dom = metrics.dominant_frequency(signal, fs)
    return Spectrum(f, p, dom.frequency, dom.peak)


@dataclass(frozen=True)
class SpeedSweep:
    """Metrics of every (scenario, speed) and the spectra at ``psd_speed_kmh``.

    ``metrics`` has shape (scenarios, speeds, metrics), NaN where a run failed (``status`` != 0,
    reason in ``messages``). ``spectra[(scenario, label)]`` holds the PSD of A_yc or A_yb at
    ``psd_speed_kmh`` (absent when that run failed).
    """

    scenarios: tuple[str, ...]
    speeds_kmh: FloatArray
    metric_names: list[str]
    metrics: FloatArray
    status: npt.NDArray[np.int64]
    messages: list[list[str]]
    psd_speed_kmh: float
    spectra: dict[tuple[str, str], Spectrum]
    settings: dict[str, Any] = field(default_factory=dict)
    seconds: float = 0.0

    def metric(self, name: str) -> FloatArray:
        """One metric, shape (scenarios, speeds)."""
        return np.asarray(self.metrics[:, :, self.metric_names.index(name)], dtype=np.float64)

    def at(self, scenario: str, metric: str, speed_kmh: float) -> float:
        """Value of ``metric`` for ``scenario`` at the sweep speed nearest ``speed_kmh``."""
        j = int(np.abs(self.speeds_kmh - speed_kmh).argmin())
        return float(self.metric(metric)[self.scenarios.index(scenario), j])

    def to_frame(self) -> pd.DataFrame:
        """One row per (scenario, speed): speed in km/h and m/s, status, message, every metric."""
        rows = []
        for i, scenario in enumerate(self.scenarios):
            for j, v in enumerate(self.speeds_kmh):
                row: dict[str, Any] = {"scenario": scenario, "speed_kmh": v, "speed_mps": v / 3.6}
                row["status"] = int(self.status[i, j])
                row["message"] = self.messages[i][j]
                row.update(zip(self.metric_names, self.metrics[i, j].tolist(), strict=True))
                rows.append(row)
        return pd.DataFrame(rows)

    def summary_frame(self) -> pd.DataFrame:
        """W_y and A_yb (the :data:`SWEEP_METRICS`) per speed, one column per scenario."""
        frame = pd.DataFrame({"speed_kmh": self.speeds_kmh})
        for metric, label in SWEEP_METRICS:
            for i, scenario in enumerate(self.scenarios):
                frame[f"{label.split(' ')[0]} {scenario}"] = self.metric(metric)[i]
        return frame

    def psd_frame(self) -> pd.DataFrame:
        """The spectra as a tidy table: scenario, quantity, channel, frequency_hz, psd."""
        channels = dict((A_YC, A_YB))
        frames = [
            pd.DataFrame(
                {
                    "scenario": s,
                    "quantity": q,
                    "channel": channels[q],
                    "frequency_hz": sp.frequency,
                    "psd": sp.density,
                }
            )
            for (s, q), sp in self.spectra.items()
        ]
        return pd.concat(frames, ignore_index=True) if frames else pd.DataFrame()

    def peaks_frame(self) -> pd.DataFrame:
        """Dominant frequency (Hz) and PSD peak ((m/s²)²/Hz) of each spectrum."""
        return pd.DataFrame(
            [
                {
                    "scenario": s,
                    "quantity": q,
                    "speed_kmh": self.psd_speed_kmh,
                    "dominant_hz": sp.dominant_hz,
                    "psd_peak": sp.peak,
                }
                for (s, q), sp in self.spectra.items()
            ]
        )


def run_speed_sweep(
    speeds_kmh: Sequence[float],
    *,
    scenarios: Sequence[str] = SCENARIOS,
    psd_speed_kmh: float = 200.0,
    distance: float = 500.0,
    seed: int = 0,
    vehicle: loco.Locomotive | None = None,
    yaw_damper: dampers.Damper | None = dampers.YD2,
    threads: int | None = None,
    progress: bool = True,
) -> SpeedSweep:
    """Run the sweep: for each scenario one batch over ``speeds_kmh`` (plus ``psd_speed_kmh``).

    Parameters
    ----------
    speeds_kmh : sequence of float
        Running speeds, km/h; ``psd_speed_kmh`` is added when missing.
    scenarios : sequence of str
        Scenario names of :data:`loco.simulation.SCENARIOS`.
    psd_speed_kmh : float
        Speed of the PSDs, km/h (SPEC: 200).
    distance : float
        Track length run at every speed, m (the simulated time is distance / speed; the metrics
        need at least 5 s).
    seed : int
        Track irregularity seed, shared by every run.
    vehicle : Locomotive, optional
        Default: the embedded locomotive.
    yaw_damper : Damper, optional
        Yaw damper law (SPEC: YD2); None keeps the vehicle file's.
    threads : int, optional
        Threads of ``loco.run_batch`` (default: all cores).
    progress : bool
        Show the batch progress bar.
    """
    start = time.perf_counter()
    speeds = np.unique(np.append(np.asarray(speeds_kmh, dtype=np.float64), psd_speed_kmh))
    psd_row = int(np.flatnonzero(speeds == psd_speed_kmh)[0])
    values, status, messages = [], [], []
    spectra: dict[tuple[str, str], Spectrum] = {}
    names: list[str] = []
    for name in scenarios:
        scenario = loco.Scenario(
            scenario=name,
            speed=psd_speed_kmh / 3.6,
            distance=distance,
            seed=seed,
            yaw_damper=yaw_damper,
        )
        batch = loco.run_batch(
            (speeds / 3.6)[:, None],
            ["speed"],
            vehicle=vehicle,
            scenario=scenario,
            threads=threads,
            seed=seed,
            progress=progress,
            histories=(psd_row,),
        )
        names = list(batch.metric_names)
        values.append(np.asarray(batch.metrics, dtype=np.float64))
        status.append(np.asarray(batch.status, dtype=np.int64))
        messages.append([str(m) for m in batch.messages])
        history = batch.histories.get(psd_row)
        if history is not None:
            for label, channel in (A_YC, A_YB):
                spectra[(name, label)] = spectrum(history.channel(channel), history.sampling_rate)
    settings = {
        "loco_version": loco.__version__,
        "scenarios": list(scenarios),
        "speeds_kmh": speeds.tolist(),
        "psd_speed_kmh": psd_speed_kmh,
        "distance_m": distance,
        "track_seed": seed,
        "yaw_damper": None
        if yaw_damper is None
        else {"kind": yaw_damper.kind, **yaw_damper.parameters()},
        "vehicle_overrides": {} if vehicle is None else dict(vehicle.overrides),
        "channels": dict((A_YC, A_YB)),
    }
    return SpeedSweep(
        scenarios=tuple(scenarios),
        speeds_kmh=speeds,
        metric_names=names,
        metrics=np.stack(values),
        status=np.stack(status),
        messages=messages,
        psd_speed_kmh=psd_speed_kmh,
        spectra=spectra,
        settings=settings,
        seconds=time.perf_counter() - start,
    )


def plot_sweep(sweep: SpeedSweep, path: str | Path) -> Path:
    """Save W_y and A_yb against speed (one line per scenario, failed runs as ×) as PNG."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(SWEEP_METRICS), figsize=(11, 4), layout="constrained")
    for ax, (metric, label) in zip(axes, SWEEP_METRICS, strict=True):
        values = sweep.metric(metric)
        for i, scenario in enumerate(sweep.scenarios):
            (line,) = ax.plot(sweep.speeds_kmh, values[i], marker="o", ms=3, label=scenario)
            failed = (sweep.status[i] != 0) | ~np.isfinite(values[i])
            if failed.any():
                ax.plot(
                    sweep.speeds_kmh[failed],
                    np.full(int(failed.sum()), 0.03),
                    "x",
                    color=line.get_color(),
                    ms=8,
                    transform=ax.get_xaxis_transform(),
                )
        ax.axvline(sweep.psd_speed_kmh, color="0.7", lw=0.8, ls="--")
        ax.set(xlabel="speed (km/h)", ylabel=label, title=f"{label.split(' ')[0]}, YD2")
        ax.set_ylim(bottom=0.0)
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.suptitle(f"Speed sweep (loco {loco.__version__}; × = failed run or too short a record)")
    out = Path(path)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return out


def draw_spectra(
    ax: Any, lines: Mapping[str, Spectrum | None], label: str, title: str, fmax: float
) -> None:
    """Draw PSDs on a log axis up to ``fmax`` (Hz), one line per name with its dominant frequency
    and PSD peak in the legend; ``label`` names the signal (e.g. A_yc). None entries are skipped
    (failed runs)."""
    for name, sp in lines.items():
        if sp is None:
            continue
        shown = (sp.frequency > 0) & (sp.frequency <= fmax)
        ax.semilogy(
            sp.frequency[shown],
            sp.density[shown],
            label=f"{name}: {sp.dominant_hz:.2f} Hz, {sp.peak:.3g}",
        )
    ax.set(
        xlabel="frequency (Hz)",
        ylabel=f"PSD of {label} ((m/s²)²/Hz)",
        xlim=(0, fmax),
        title=title,
    )
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(title="dominant frequency, PSD peak", fontsize=8)


def plot_psds(sweep: SpeedSweep, path: str | Path, *, fmax: float = 20.0) -> Path:
    """Save the PSDs of A_yc and A_yb at ``psd_speed_kmh`` (one line per scenario) as PNG;
    ``fmax`` is the upper frequency shown, Hz."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4), layout="constrained")
    for ax, (label, channel) in zip(axes, (A_YC, A_YB), strict=True):
        lines = {sc: sweep.spectra.get((sc, label)) for sc in sweep.scenarios}
        title = f"{label} ({channel}), {sweep.psd_speed_kmh:g} km/h, YD2"
        draw_spectra(ax, lines, label, title, fmax)
    out = Path(path)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return out


def save_speed_sweep(sweep: SpeedSweep, out_dir: str | Path) -> StudyRecord:
    """Write the figures, tables and settings of ``sweep`` into ``out_dir``; return the record.

    Files: ``speed_sweep.png``, ``speed_sweep_psd.png``, ``speed_sweep_summary.csv`` (W_y and
    A_yb per speed and scenario), ``speed_sweep.csv`` (every metric of every run),
    ``speed_sweep_peaks.csv`` (dominant frequency and PSD peak), ``speed_sweep_psd.csv`` (the
    spectra) and ``speed_sweep.json`` (loco version and settings).
    """
    start = time.perf_counter()
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    figures = [
        plot_sweep(sweep, out / "speed_sweep.png"),
        plot_psds(sweep, out / "speed_sweep_psd.png"),
    ]
    tables = [
        save_table(sweep.summary_frame(), out / "speed_sweep_summary.csv"),
        save_table(sweep.to_frame(), out / "speed_sweep.csv"),
        save_table(sweep.peaks_frame(), out / "speed_sweep_peaks.csv"),
        save_table(sweep.psd_frame(), out / "speed_sweep_psd.csv"),
        save_json(sweep.settings, out / "speed_sweep.json"),
    ]
    v = sweep.psd_speed_kmh
    parts = [
        f"{s}: W_y {sweep.at(s, 'wy_max', v):.2f}, A_yb {sweep.at(s, 'ayb_peak_lp', v):.2f} m/s²"
        for s in sweep.scenarios
    ]
    n_failed = int((sweep.status != 0).sum())
    notes = f"At {v:g} km/h with YD2: " + "; ".join(parts) + "."
    if n_failed:
        notes += (
            f" {n_failed} of {sweep.status.size} runs failed (× in the figure, NaN in the CSV)."
        )
    return StudyRecord(
        name=out.name,
        title="Speed sweep with the YD2 yaw damper (SPEC §6.1)",
        figures=figures,
        tables=tables,
        parameters={k: v for k, v in sweep.settings.items() if k != "yaw_damper"},
        seconds=sweep.seconds + time.perf_counter() - start,
        notes=notes,
    )
