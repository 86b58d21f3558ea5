"""Speed sweep of SPEC §6.1: W_y and A_yb against speed for S_low, S_norm and S_high with the YD2
yaw damper, and the PSDs of A_yc and A_yb at 200 km/h.

One ``loco.run_batch`` per (scenario, speed) with the tracks as samples
(:func:`loco.studies.seeds.run_over_tracks`): track ``j`` is ChaCha stream ``j`` of the track seed,
the same at every speed and in every scenario, over the same recorded ``distance``. Every quantity
is positive and given as its geometric mean over the tracks with the 95 % interval of the logs
taken back, the dominant frequencies as the median with every track's value
(:mod:`loco.studies.statistics`); the PSDs at ``psd_speed_kmh`` are the track means of the
per-track Welch PSDs.

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
from typing import Any, ClassVar

import numpy as np
import numpy.typing as npt
import pandas as pd

import loco
from loco import dampers
from loco.channels import Metric
from loco.studies import captions as figure_captions
from loco.studies.plotting import Spectrum
from loco.studies.quantities import (
    A_YB,
    A_YC,
    CHANNELS,
    METRIC_CHANNELS,
    PEAK_METRICS,
    RMS_METRICS,
    SCENARIOS,
    spectrum,
)
from loco.studies.report import StudyRecord, save_json, save_table
from loco.studies.seeds import run_over_tracks
from loco.studies.stages import Demand, Runtime, Stage
from loco.studies.statistics import Interval, geometric_interval, median_values, track_values_text

__all__ = [
    "A_YB",
    "A_YC",
    "CHANNELS",
    "METRIC_CHANNELS",
    "PEAK_METRICS",
    "RMS_METRICS",
    "SCENARIOS",
    "SpeedSweep",
    "SpeedSweepStage",
    "run_speed_sweep",
    "save_speed_sweep",
    "spectrum",
]

FloatArray = npt.NDArray[np.float64]

#: Metrics plotted against speed: (metric name, axis label).
SWEEP_METRICS: tuple[tuple[str, str], ...] = (
    (Metric.WY_MAX, "W_y (Sperling, lateral)"),
    (Metric.AYB_PEAK_LP, "A_yb peak, 10 Hz low-pass (m/s²)"),
)


@dataclass(frozen=True)
class SpeedSweep:
    """Metrics of every (scenario, speed, track) and the track-mean spectra at ``psd_speed_kmh``.

    ``metrics`` has shape (scenarios, speeds, tracks, metrics), NaN where a run failed
    (``status`` != 0, reason in ``messages[scenario][speed][track]``). ``spectra[(scenario,
    label)]`` holds the track-mean PSD of A_yc or A_yb at ``psd_speed_kmh`` (absent when every
    run there failed); track ``j`` is stream ``j`` of the track seed (:mod:`loco.studies.seeds`).
    """

    scenarios: tuple[str, ...]
    speeds_kmh: FloatArray
    metric_names: list[str]
    metrics: FloatArray
    status: npt.NDArray[np.int64]
    messages: list[list[list[str]]]
    psd_speed_kmh: float
    spectra: dict[tuple[str, str], Spectrum]
    settings: dict[str, Any] = field(default_factory=dict)
    seconds: float = 0.0

    @property
    def n_tracks(self) -> int:
        """Tracks run per (scenario, speed)."""
        return int(self.metrics.shape[2])

    def metric(self, name: str) -> FloatArray:
        """One metric, shape (scenarios, speeds, tracks)."""
        return np.asarray(self.metrics[..., self.metric_names.index(name)], dtype=np.float64)

    def speed_index(self, speed_kmh: float) -> int:
        """Index of the sweep speed nearest ``speed_kmh`` (km/h)."""
        return int(np.abs(self.speeds_kmh - speed_kmh).argmin())

    def interval(self, scenario: str, metric: str, speed_kmh: float) -> Interval:
        """Geometric mean and 95 % interval over the tracks
        (:func:`loco.studies.statistics.geometric_interval`) of ``metric``, a positive quantity,
        for ``scenario`` at the sweep speed nearest ``speed_kmh``."""
        i, j = self.scenarios.index(scenario), self.speed_index(speed_kmh)
        return geometric_interval(self.metric(metric)[i, j])

    def at(self, scenario: str, metric: str, speed_kmh: float) -> float:
        """Geometric mean over the tracks of ``metric`` for ``scenario`` at the sweep speed
        nearest ``speed_kmh``."""
        return self.interval(scenario, metric, speed_kmh).mean

    def median(self, scenario: str, metric: str, speed_kmh: float) -> tuple[float, list[float]]:
        """Median over the tracks of ``metric`` (a dominant frequency) and each track's value."""
        i, j = self.scenarios.index(scenario), self.speed_index(speed_kmh)
        return median_values(self.metric(metric)[i, j])

    def to_frame(self) -> pd.DataFrame:
        """One row per (scenario, speed, track): speed in km/h and m/s, status, message, every
        metric."""
        rows = []
        for i, scenario in enumerate(self.scenarios):
            for j, v in enumerate(self.speeds_kmh):
                for k in range(self.n_tracks):
                    row: dict[str, Any] = {
                        "scenario": scenario,
                        "speed_kmh": v,
                        "speed_mps": v / 3.6,
                        "track": k,
                        "status": int(self.status[i, j, k]),
                        "message": self.messages[i][j][k],
                    }
                    row.update(zip(self.metric_names, self.metrics[i, j, k].tolist(), strict=True))
                    rows.append(row)
        return pd.DataFrame(rows)

    def summary_frame(self) -> pd.DataFrame:
        """W_y and A_yb (the :data:`SWEEP_METRICS`) per scenario and speed: the geometric mean
        over the tracks (``geomean``) and its 95 % interval (``low``, ``high``; the t interval of
        the logs taken back, never below zero), and the number of tracks that finished."""
        rows = []
        for scenario in self.scenarios:
            for v in self.speeds_kmh:
                row: dict[str, Any] = {"scenario": scenario, "speed_kmh": v}
                for metric, label in SWEEP_METRICS:
                    ci = self.interval(scenario, metric, v)
                    name = label.split(" ")[0]
                    row.update({f"{name} geomean": ci.mean, f"{name} low": ci.low,
                                f"{name} high": ci.high})  # fmt: skip
                row["n_tracks"] = ci.n
                rows.append(row)
        return pd.DataFrame(rows)

    def psd_frame(self) -> pd.DataFrame:
        """The track-mean spectra as a tidy table: scenario, quantity, channel, frequency_hz,
        psd."""
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
        """Dominant frequency (Hz) and PSD peak ((m/s²)²/Hz) of each quantity at
        ``psd_speed_kmh`` (the core's run metrics :data:`PEAK_METRICS`): the dominant frequency's
        median over the tracks (``dominant_hz``) and every track's value (``dominant_hz_tracks``,
        in track order, a dash for a failed run); the PSD peak's geometric mean (``psd_peak``)
        and its 95 % interval (``psd_peak_low``, ``psd_peak_high``)."""
        rows = []
        for s in self.scenarios:
            for q, (frequency, peak) in PEAK_METRICS.items():
                row: dict[str, Any] = {"scenario": s, "quantity": q}
                row["speed_kmh"] = self.psd_speed_kmh
                median, each = self.median(s, frequency, self.psd_speed_kmh)
                row.update({"dominant_hz": median, "dominant_hz_tracks": track_values_text(each)})
                ci = self.interval(s, peak, self.psd_speed_kmh)
                row.update({"psd_peak": ci.mean, "psd_peak_low": ci.low,
                            "psd_peak_high": ci.high})  # fmt: skip
                row["n_tracks"] = ci.n
                rows.append(row)
        return pd.DataFrame(rows)


@dataclass(frozen=True)
class SpeedSweepStage(Stage):
    """The sweep's inputs (stage ``speed_sweep`` of ``loco reproduce``): for each scenario and
    speed (``speeds_kmh`` plus ``psd_speed_kmh``) one batch over tracks ``0 … n_tracks-1``.

    Parameters
    ----------
    speeds_kmh : sequence of float
        Running speeds, km/h; ``psd_speed_kmh`` is added when missing.
    scenarios : sequence of str
        Scenario names of :data:`loco.simulation.SCENARIOS`.
    psd_speed_kmh : float
        Speed of the PSDs, km/h (SPEC: 200).
    distance : float
        Recorded track length at every speed, m (the simulated time is distance / speed; the
        metrics need at least 5 s).
    lead_in : float
        Track run before the recorded ``distance`` and not recorded, m.
    seed : int
        Track irregularity seed; track ``j`` is its ChaCha stream ``j``, the same at every speed
        and in every scenario.
    n_tracks : int
        Tracks per (scenario, speed); the tables give their mean and 95 % interval.
    vehicle : Locomotive, optional
        Default: the embedded locomotive.
    yaw_damper : Damper, optional
        Yaw damper law (SPEC: YD2); None keeps the vehicle file's.
    integrator : str
        Integration scheme of every run (:data:`loco.simulation.INTEGRATORS`), at its own step.
    """

    name: ClassVar[str] = "speed_sweep"
    speeds_kmh: Sequence[float]
    scenarios: Sequence[str] = SCENARIOS
    psd_speed_kmh: float = 200.0
    distance: float = 500.0
    lead_in: float = 0.0
    seed: int = 0
    n_tracks: int = 1
    vehicle: loco.Locomotive | None = None
    yaw_damper: dampers.Damper | None = dampers.YD2
    integrator: str = loco.Scenario.integrator

    def speeds(self) -> FloatArray:
        """The speeds run, km/h: ``speeds_kmh`` and ``psd_speed_kmh``, sorted, once each."""
        given = np.asarray(self.speeds_kmh, dtype=np.float64)
        return np.unique(np.append(given, self.psd_speed_kmh))

    def settings(self) -> dict[str, Any]:
        """The sweep's settings as its JSON file and report show them."""
        n, seed, damper = self.n_tracks, self.seed, self.yaw_damper
        return {
            "loco_version": loco.__version__,
            "scenarios": list(self.scenarios),
            "speeds_kmh": self.speeds().tolist(),
            "psd_speed_kmh": self.psd_speed_kmh,
            "distance_m": self.distance,
            "lead_in_m": self.lead_in,
            "track_seed": seed,
            "n_tracks": n,
            "tracks": f"ChaCha streams 0-{n - 1} of track seed {seed}",
            "integrator": self.integrator,
            "yaw_damper": None if damper is None else dampers.describe(damper),
            "yaw_damper_label": dampers.label(damper),
            "vehicle_overrides": {} if self.vehicle is None else dict(self.vehicle.overrides),
            "channels": dict(CHANNELS),
        }

    def demand(self) -> Demand:
        """One run per (scenario, speed, track)."""
        n = len(self.scenarios) * self.n_tracks
        length = self.lead_in + self.distance
        return sum((Demand.runs(n, length, v / 3.6) for v in self.speeds()), Demand())

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """Run the sweep and save it into ``out_dir`` (:func:`save_speed_sweep`)."""
        return save_speed_sweep(run_speed_sweep(self, runtime), out_dir)


def run_speed_sweep(stage: SpeedSweepStage, runtime: Runtime | None = None) -> SpeedSweep:
    """Run the sweep ``stage`` describes, with ``runtime``'s threads and progress bars
    (default: all cores, bars shown)."""
    runtime = runtime or Runtime()
    start = time.perf_counter()
    speeds = stage.speeds()
    values, status, messages = [], [], []
    spectra: dict[tuple[str, str], Spectrum] = {}
    names: list[str] = []
    peak_specs = tuple((q, CHANNELS[q], PEAK_METRICS[q]) for q in CHANNELS)
    for name in stage.scenarios:
        rows = []
        for v in speeds:
            scenario = loco.Scenario(
                name=name,
                speed=v / 3.6,
                distance=stage.distance,
                lead_in=stage.lead_in,
                seed=stage.seed,
                yaw_damper=stage.yaw_damper,
                integrator=stage.integrator,
            )
            runs = run_over_tracks(
                scenario,
                stage.n_tracks,
                vehicle=stage.vehicle,
                threads=runtime.threads,
                progress=runtime.progress,
                spectra=peak_specs if v == stage.psd_speed_kmh else (),
            )
            names = runs.metric_names
            rows.append(runs)
            for label, sp in runs.spectra.items():
                spectra[(name, label)] = sp
        values.append(np.stack([r.metrics for r in rows]))
        status.append(np.stack([r.status for r in rows]))
        messages.append([r.messages for r in rows])
    return SpeedSweep(
        scenarios=tuple(stage.scenarios),
        speeds_kmh=speeds,
        metric_names=names,
        metrics=np.stack(values),
        status=np.stack(status),
        messages=messages,
        psd_speed_kmh=stage.psd_speed_kmh,
        spectra=spectra,
        settings=stage.settings(),
        seconds=time.perf_counter() - start,
    )


def save_speed_sweep(sweep: SpeedSweep, out_dir: str | Path) -> StudyRecord:
    """Write the figures, tables and settings of ``sweep`` into ``out_dir``; return the record.

    Files: ``speed_sweep.png``, ``speed_sweep_psd.png``, ``speed_sweep_peaks.png``,
    ``speed_sweep_summary.csv`` (W_y and A_yb per speed and scenario, geometric mean and 95 %
    interval over the tracks), ``speed_sweep.csv`` (every metric of every run),
    ``speed_sweep_peaks.csv`` (dominant frequency: median and each track's; PSD peak: geometric
    mean and interval; :meth:`SpeedSweep.peaks_frame`), ``speed_sweep_psd.csv`` (the
    track-mean spectra) and ``speed_sweep.json`` (loco version and settings).
    """
    from loco.studies.speed_sweep_figures import plot_peaks, plot_psds, plot_sweep, sweep_notes

    start = time.perf_counter()
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    figures = [
        plot_sweep(sweep, out / "speed_sweep.png"),
        plot_psds(sweep, out / "speed_sweep_psd.png"),
        plot_peaks(sweep, out / "speed_sweep_peaks.png"),
    ]
    tables = [
        save_table(sweep.summary_frame(), out / "speed_sweep_summary.csv"),
        save_table(sweep.to_frame(), out / "speed_sweep.csv"),
        save_table(sweep.peaks_frame(), out / "speed_sweep_peaks.csv"),
        save_table(sweep.psd_frame(), out / "speed_sweep_psd.csv"),
        save_json(sweep.settings, out / "speed_sweep.json"),
    ]
    notes = sweep_notes(sweep)
    return StudyRecord(
        name=out.name,
        title=f"Speed sweep with the {sweep.damper_label} yaw damper (SPEC §6.1)",
        figures=figures,
        tables=tables,
        parameters={k: v for k, v in sweep.settings.items() if k != "yaw_damper"},
        seconds=sweep.seconds + time.perf_counter() - start,
        notes=notes,
        captions=figure_captions.SPEED_SWEEP,
    )
