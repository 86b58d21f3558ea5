"""Speed sweep of SPEC §6.1: W_y and A_yb against speed for S_low, S_norm and S_high with the YD2
yaw damper, and the PSDs of A_yc and A_yb at 200 km/h.

One ``loco.run_batch`` per scenario, one row per speed (the batch's ``speed`` column, m/s), all on
the same synthesised track (``seed``) over the same ``distance``; the time histories of the row at
``psd_speed_kmh`` are kept for the PSDs.

Quantities (names of the package's channels and metrics):

- W_y: Sperling lateral ride index, metric ``wy_max`` (largest 5 s segment index);
- A_yb: bogie frame lateral acceleration above the leading wheelset, 10 Hz low-passed peak,
  metric ``ayb_peak_lp`` (m/s²), channel ``METRIC_CHANNELS["A_yb"]``;
- A_yc: carbody floor lateral acceleration above the leading bogie, channel
  ``METRIC_CHANNELS["A_yc"]`` (m/s²).

The channels are those the core computes the metrics from (``loco._loco.metric_channels()``).
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
import pandas as pd

import loco
from loco import _loco, dampers, metrics
from loco.studies.plotting import Spectrum, draw_spectra, pyplot, save_figure
from loco.studies.report import StudyRecord, save_json, save_table

__all__ = [
    "A_YB",
    "A_YC",
    "CHANNELS",
    "METRIC_CHANNELS",
    "PEAK_METRICS",
    "RMS_METRICS",
    "SCENARIOS",
    "SpeedSweep",
    "plot_psds",
    "plot_sweep",
    "run_speed_sweep",
    "save_speed_sweep",
    "spectrum",
]

FloatArray = npt.NDArray[np.float64]

#: The three wheel states of SPEC §2.
SCENARIOS: tuple[str, ...] = ("S_low", "S_norm", "S_high")
#: Channel of each quantity whose metrics the core computes (``A_yc``, ``A_zc``, ``A_yb``), as the
#: core names it.
METRIC_CHANNELS: dict[str, str] = dict(_loco.metric_channels())
#: (label, channel) of the carbody floor lateral acceleration A_yc.
A_YC: tuple[str, str] = ("A_yc", METRIC_CHANNELS["A_yc"])
#: (label, channel) of the bogie frame lateral acceleration A_yb.
A_YB: tuple[str, str] = ("A_yb", METRIC_CHANNELS["A_yb"])
#: Channel of each quantity of the sweep's spectra.
CHANNELS: dict[str, str] = dict((A_YC, A_YB))
#: Metrics plotted against speed: (metric name, axis label).
SWEEP_METRICS: tuple[tuple[str, str], ...] = (
    ("wy_max", "W_y (Sperling, lateral)"),
    ("ayb_peak_lp", "A_yb peak, 10 Hz low-pass (m/s²)"),
)


#: Run metrics (the core's) of the PSD peak of each quantity: (dominant frequency Hz, PSD peak
#: (m/s²)²/Hz). A_yc is searched over 0.2-20 Hz, A_yb over the EN 14363 f0 band.
PEAK_METRICS: dict[str, tuple[str, str]] = {
    "A_yc": ("ayc_dominant_hz", "ayc_psd_peak"),
    "A_yb": ("ayb_f0_hz", "ayb_psd_peak"),
}
#: Run metric of the rms of each quantity, m/s².
RMS_METRICS: dict[str, str] = {"A_yc": "ayc_rms", "A_yb": "ayb_rms"}


def spectrum(result: loco.SimulationResult, quantity: str) -> Spectrum:
    """The :class:`Spectrum` of ``quantity`` (``"A_yc"`` or ``"A_yb"``) of a run: the Welch PSD of
    its channel by :func:`loco.metrics.psd` (for the curves), its peak from the run's metrics
    (:data:`PEAK_METRICS`)."""
    f, p = metrics.psd(result.channel(CHANNELS[quantity]), result.sampling_rate)
    frequency, peak = PEAK_METRICS[quantity]
    return Spectrum(f, p, result.metrics[frequency], result.metrics[peak])


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
        channels = self.settings.get("channels", CHANNELS)
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

    @property
    def damper_label(self) -> str:
        """Name of the yaw damper of the sweep (e.g. ``YD2``), from the settings."""
        return str(self.settings.get("yaw_damper_label", "yaw damper"))

    def peaks_frame(self) -> pd.DataFrame:
        """Dominant frequency (Hz) and PSD peak ((m/s²)²/Hz) of each spectrum (the core's run
        metrics :data:`PEAK_METRICS`)."""
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
            for label in CHANNELS:
                spectra[(name, label)] = spectrum(history, label)
    settings = {
        "loco_version": loco.__version__,
        "scenarios": list(scenarios),
        "speeds_kmh": speeds.tolist(),
        "psd_speed_kmh": psd_speed_kmh,
        "distance_m": distance,
        "track_seed": seed,
        "yaw_damper": None if yaw_damper is None else dampers.describe(yaw_damper),
        "yaw_damper_label": dampers.label(yaw_damper),
        "vehicle_overrides": {} if vehicle is None else dict(vehicle.overrides),
        "channels": dict(CHANNELS),
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
    plt = pyplot()
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
        ax.set(
            xlabel="speed (km/h)",
            ylabel=label,
            title=f"{label.split(' ')[0]}, {sweep.damper_label}",
        )
        ax.set_ylim(bottom=0.0)
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.suptitle(f"Speed sweep (loco {loco.__version__}; × = failed run or too short a record)")
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
    return save_figure(fig, path)


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
    notes = f"At {v:g} km/h with {sweep.damper_label}: " + "; ".join(parts) + "."
    if n_failed:
        notes += (
            f" {n_failed} of {sweep.status.size} runs failed (× in the figure, NaN in the CSV)."
        )
    return StudyRecord(
        name=out.name,
        title=f"Speed sweep with the {sweep.damper_label} yaw damper (SPEC §6.1)",
        figures=figures,
        tables=tables,
        parameters={k: v for k, v in sweep.settings.items() if k != "yaw_damper"},
        seconds=sweep.seconds + time.perf_counter() - start,
        notes=notes,
    )
