"""The damper comparison's runs and their tables: the dampers and cases compared, the per-track
columns the report and the verdict read, :class:`FsdComparison` (every case on every track, its
tables, spectra and rankings) and the FSD valves' open fractions. The stage that runs it is
:mod:`loco.studies.fsd_comparison`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt
import pandas as pd

import loco
from loco import dampers
from loco.channels import ChannelKind, Metric
from loco.studies.plotting import Spectrum
from loco.studies.quantities import A_YB, A_YC, PEAK_METRICS, RMS_METRICS
from loco.studies.seeds import TrackRuns
from loco.studies.statistics import (
    Ranking,
    geometric_interval,
    mean_interval,
    median_values,
    rank,
    track_values_text,
)

__all__ = [
    "CARBODY_CYCLE_COLUMNS",
    "CASES",
    "DAMPERS",
    "JUDGED_BY",
    "LIMIT_CYCLE_COLUMNS",
    "POSITIVE_COLUMNS",
    "STABILITY_FLAGS",
    "SUMMARY_COLUMNS",
    "VALVE_FRACTION",
    "VALVE_SUFFIX",
    "FsdComparison",
    "valve_channels",
    "valve_closed_fraction",
    "valve_open_fractions",
]

#: The yaw dampers compared (SPEC §4), and the FSD with the hydraulic frequency valve (FSD-H).
DAMPERS: dict[str, dampers.Damper] = dampers.COMPARED
#: (scenario, quantity label, channel): A_yc judges S_low, A_yb judges S_high.
CASES: tuple[tuple[str, str, str], ...] = (("S_low", *A_YC), ("S_high", *A_YB))
SCENARIO_QUANTITY: dict[str, str] = {s: q for s, q, _ in CASES}
FloatArray = npt.NDArray[np.float64]
#: Suffix the core gives the frequency-valve channels (stripped to name the valve in tables; the
#: channels themselves are selected by kind, :func:`valve_channels`).
VALVE_SUFFIX = "_valve"


#: Metric by which each scenario judges a yaw damper (SPEC §5): W_y on S_low, A_yb on S_high.
JUDGED_BY: dict[str, str] = {"S_low": Metric.WY_MAX, "S_high": Metric.AYB_PEAK_LP}
#: The bogie instability flags (core run metrics, 0/1): EN 14363 sliding rms over its limit, GB/T
#: 8 m/s² peaks in 6 cycles.
STABILITY_FLAGS: tuple[str, ...] = (Metric.AYB_EN_UNSTABLE, Metric.AYB_GBT_UNSTABLE)
#: The bogie frame's limit cycle (core run metrics: the flag, its frequency and amplitude) and the
#: EN 14363 sliding rms with its limit, which say whether a hunting bogie is within that limit.
LIMIT_CYCLE_COLUMNS: tuple[str, ...] = (
    Metric.AYB_LIMIT_CYCLE,
    Metric.AYB_CYCLE_HZ,
    Metric.AYB_CYCLE_AMPLITUDE,
    Metric.AYB_EN_RMS,
    Metric.AYB_EN_LIMIT,
)
#: The carbody's limit cycle (core run metrics: the flag, its frequency and amplitude): the
#: carbody hunting of the study's premise, which the verdict names on S_low.
CARBODY_CYCLE_COLUMNS: tuple[str, ...] = (
    Metric.AYC_LIMIT_CYCLE,
    Metric.AYC_CYCLE_HZ,
    Metric.AYC_CYCLE_AMPLITUDE,
)
#: Fraction of the record the valves were closed (from the valve channels, not a core metric).
VALVE_FRACTION = "valve_closed_fraction"
#: Per-track columns of the comparison's tables: ``rms``, ``dominant_hz`` and ``psd_peak`` are the
#: core's run metrics of the case's quantity (:data:`RMS_METRICS`, :data:`PEAK_METRICS`), then two
#: run metrics under their own names, the valve fraction (:meth:`FsdComparison.values`) and the
#: two bogie instability flags (0/1 per track, their mean the fraction of tracks flagged), then
#: the bogie frame's and the carbody's limit-cycle columns (the report's verdict,
#: :mod:`loco.studies.verdict`, reads them).
SUMMARY_COLUMNS: tuple[str, ...] = (
    "rms",
    "dominant_hz",
    "psd_peak",
    *JUDGED_BY.values(),
    VALVE_FRACTION,
    *STABILITY_FLAGS,
    *LIMIT_CYCLE_COLUMNS,
    *CARBODY_CYCLE_COLUMNS,
)
#: Summary columns of positive quantities, given as the geometric mean over the tracks and its
#: interval (:func:`loco.studies.statistics.geometric_interval`); ``dominant_hz`` is given as the
#: median with every track's value; the others (fractions, flags, limit-cycle columns, which can
#: be zero) as the arithmetic mean and its t interval.
POSITIVE_COLUMNS: tuple[str, ...] = ("rms", "psd_peak", *JUDGED_BY.values())


@dataclass(frozen=True)
class FsdComparison:
    """Every (scenario, damper) run on tracks ``0 … n-1`` (:mod:`loco.studies.seeds`).

    ``runs`` holds the per-track metrics and the track-mean spectrum of each case; ``results``
    the time history on track 0 (None when it failed, with its message in ``errors``), for the
    time-history and valve figures.
    """

    damper_laws: dict[str, dampers.Damper]
    """The yaw damper laws compared, by name (in order)."""
    runs: dict[tuple[str, str], TrackRuns]
    settings: dict[str, Any] = field(default_factory=dict)
    seconds: float = 0.0

    @property
    def dampers(self) -> tuple[str, ...]:
        """Names of the yaw dampers compared, in order."""
        return tuple(self.damper_laws)

    @property
    def n_tracks(self) -> int:
        """Tracks per case."""
        return min((r.n_tracks for r in self.runs.values()), default=0)

    @property
    def results(self) -> dict[tuple[str, str], loco.SimulationResult | None]:
        """Time history of each case on track 0 (None when that run failed)."""
        return {k: r.first for k, r in self.runs.items()}

    @property
    def errors(self) -> dict[tuple[str, str], str]:
        """Why runs failed, by case: the messages of its failed tracks."""
        out = {}
        for key, r in self.runs.items():
            failed = [f"track {i}: {m}" for i, m in enumerate(r.messages) if r.status[i] != 0]
            if failed:
                out[key] = "; ".join(failed)
        return out

    def has_valve(self, damper: str) -> bool:
        """Whether the yaw damper law ``damper`` has a frequency valve (an FSD)."""
        law = self.damper_laws.get(damper)
        return law is not None and law.kind == "fsd"

    def spectra(self) -> dict[tuple[str, str], Spectrum]:
        """Track-mean spectrum of each case's quantity (A_yc on S_low, A_yb on S_high), by
        (scenario, damper); its dominant frequency and peak are the track means of the run
        metrics."""
        return {
            key: r.spectra[SCENARIO_QUANTITY[key[0]]]
            for key, r in self.runs.items()
            if SCENARIO_QUANTITY[key[0]] in r.spectra
        }

    def values(self, scenario: str, damper: str, column: str) -> FloatArray:
        """Per-track values of a :data:`SUMMARY_COLUMNS` entry for one case, shape (n,)."""
        runs = self.runs[(scenario, damper)]
        label = SCENARIO_QUANTITY[scenario]
        metric = {
            "rms": RMS_METRICS[label],
            "dominant_hz": PEAK_METRICS[label][0],
            "psd_peak": PEAK_METRICS[label][1],
        }.get(column, column)
        if column == VALVE_FRACTION and not self.has_valve(damper):
            return np.full(runs.n_tracks, np.nan)
        return runs.values(metric)

    def table(self) -> pd.DataFrame:
        """One row per (scenario, damper): the quantity, and of its rms (m/s²), dominant
        frequency (Hz), PSD peak ((m/s²)²/Hz) (the core's run metrics), W_y and A_yb peak, and
        the fraction of time the yaw damper valves were closed (FSD only, NaN for dampers without
        a valve) a value over the tracks (column named as the quantity) and its 95 % interval
        (``_low``, ``_high``): for the positive :data:`POSITIVE_COLUMNS` the geometric mean, for
        the others the mean; the dominant frequency as the median over the tracks with every
        track's value (``dominant_hz_tracks``) instead of an interval; the number of tracks that
        finished, and why the others failed."""
        errors = self.errors
        rows = []
        for scenario, label, channel in CASES:
            for name in self.dampers:
                row: dict[str, Any] = {
                    "scenario": scenario,
                    "damper": name,
                    "quantity": label,
                    "channel": channel,
                }
                for column in SUMMARY_COLUMNS:
                    values = self.values(scenario, name, column)
                    if column == "dominant_hz":
                        median, each = median_values(values)
                        row.update({column: median, f"{column}_tracks": track_values_text(each)})
                        continue
                    positive = column in POSITIVE_COLUMNS
                    ci = geometric_interval(values) if positive else mean_interval(values)
                    row.update({column: ci.mean, f"{column}_low": ci.low,
                                f"{column}_high": ci.high})  # fmt: skip
                row["n_tracks"] = int(np.count_nonzero(self.runs[(scenario, name)].status == 0))
                row["error"] = errors.get((scenario, name), "")
                rows.append(row)
        return pd.DataFrame(rows)

    def tracks_frame(self) -> pd.DataFrame:
        """The numbers behind the statistics: one row per (scenario, damper, track)."""
        rows = []
        for (scenario, name), runs in self.runs.items():
            for i in range(runs.n_tracks):
                row: dict[str, Any] = {"scenario": scenario, "damper": name, "track": i,
                                       "status": int(runs.status[i])}  # fmt: skip
                for column in SUMMARY_COLUMNS:
                    row[column] = float(self.values(scenario, name, column)[i])
                row["message"] = runs.messages[i]
                rows.append(row)
        return pd.DataFrame(rows)

    def rankings(self) -> list[Ranking]:
        """Per scenario, the dampers ranked by the PSD peak of its quantity and by the metric
        that judges it (:data:`JUDGED_BY`), with paired tests over the shared tracks."""
        out = []
        for scenario, label, _ in CASES:
            for column, name in (("psd_peak", f"PSD peak of {label}"),
                                 (JUDGED_BY[scenario], JUDGED_BY[scenario])):  # fmt: skip
                values = {d: self.values(scenario, d, column) for d in self.dampers}
                out.append(rank(values, label=scenario, metric=name))
        return out

    def rankings_frame(self) -> pd.DataFrame:
        """Every pairwise test of :meth:`rankings`: scenario, metric, pair, geometric-mean ratio
        with its 95 % interval, p values (t, Holm-adjusted, Wilcoxon), significance, and the
        ranking and whether it is significant."""
        return pd.DataFrame([row for r in self.rankings() for row in r.rows()])


def valve_open_fractions(cmp: FsdComparison) -> pd.DataFrame:
    """Per (scenario, FSD law, yaw damper): the valve open fraction, the time average of
    1 - scale factor (1 always open, low damping; 0 always closed), and the bogie of the damper;
    plus one row per bogie (``valve`` = ``bogieN``) averaging its two dampers."""
    rows = []
    for (scenario, name), result in cmp.results.items():
        if result is None or not cmp.has_valve(name):
            continue
        for channel in valve_channels(result):
            bogie = next((b for b in ("bogie1", "bogie2") if b in channel), "")
            opening = 1.0 - float(np.mean(result.channel(channel)))
            rows.append((scenario, name, channel.removesuffix(VALVE_SUFFIX), bogie, opening))
    table = pd.DataFrame(rows, columns=["scenario", "damper", "valve", "bogie", "open_fraction"])
    per_bogie = pd.DataFrame(
        table.groupby(["scenario", "damper", "bogie"], as_index=False, sort=False)[
            "open_fraction"
        ].mean()
    )
    per_bogie["valve"] = per_bogie["bogie"]
    frames: list[pd.DataFrame] = [table, pd.DataFrame(per_bogie[list(table.columns)])]
    return pd.concat(frames, ignore_index=True)


def valve_channels(result: loco.SimulationResult) -> list[str]:
    """Names of the yaw damper valve channels of a run (0 open … 1 closed)."""
    return result.channels_of_kind(ChannelKind.DAMPER_VALVE)


def valve_closed_fraction(result: loco.SimulationResult) -> float:
    """Fraction of the record the yaw damper valves of a run were closed (mean over the valves;
    NaN without valve channels)."""
    channels = valve_channels(result)
    return float(np.mean([result.channel(c) for c in channels])) if channels else np.nan
