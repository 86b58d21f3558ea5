"""Yaw damper comparison of SPEC §6.6: the locomotive with YD1, YD2 and FSD yaw dampers on S_low
and S_high at 200 km/h.

Six cases (scenario, damper), each one ``loco.run_batch`` over the same synthesised tracks (the
tracks as samples, :mod:`loco.studies.seeds`; common random numbers, so the dampers are compared
by paired tests, :mod:`loco.studies.statistics`). Outputs: the time histories (track 0) and
track-mean Welch PSDs of the carbody floor lateral acceleration A_yc on S_low (low-conicity carbody
sway) and of the bogie frame lateral acceleration A_yb on S_high (high-conicity bogie hunting); the
dominant frequency and PSD peak of each (the core's run metrics,
:data:`loco.studies.speed_sweep.PEAK_METRICS`), W_y and A_yb as the mean and 95 % interval over the
tracks, with the per-track values; whether each ranking of the dampers is significant; and the
state of the FSD frequency valves over time (channels ``*_valve``: 0 open, low damping c1;
1 closed, high damping c2).
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, ClassVar

import pandas as pd

import loco
from loco import dampers
from loco.contact_pairs import ContactPair
from loco.studies import captions as figure_captions
from loco.studies.fsd_tables import (
    CARBODY_CYCLE_COLUMNS,
    CASES,
    DAMPERS,
    JUDGED_BY,
    LIMIT_CYCLE_COLUMNS,
    STABILITY_FLAGS,
    SUMMARY_COLUMNS,
    VALVE_FRACTION,
    FsdComparison,
    valve_channels,
    valve_closed_fraction,
    valve_open_fractions,
)
from loco.studies.quantities import PEAK_METRICS
from loco.studies.report import StudyRecord, save_json, save_table
from loco.studies.seeds import run_over_tracks
from loco.studies.stages import Demand, Runtime, Stage

__all__ = [
    "CARBODY_CYCLE_COLUMNS",
    "CASES",
    "DAMPERS",
    "JUDGED_BY",
    "LIMIT_CYCLE_COLUMNS",
    "STABILITY_FLAGS",
    "SUMMARY_COLUMNS",
    "FsdComparison",
    "FsdComparisonStage",
    "run_fsd_comparison",
    "save_fsd_comparison",
    "valve_channels",
    "valve_closed_fraction",
    "valve_open_fractions",
]

#: Track run before the recorded section, m. The FSD starts in its defined state (valve closed,
#: high damping) and its trigger needs a few cycles of the slow carbody sway to open the valve:
#: at 200 km/h on S_low that took 3–7 s (170–390 m) from the start of the run. 500 m of lead-in
#: compares the dampers in their steady regime, every damper on the same track and section.
LEAD_IN = 500.0


def _dampers() -> dict[str, dampers.Damper]:
    return dict(DAMPERS)


@dataclass(frozen=True)
class FsdComparisonStage(Stage):
    """The comparison's inputs (stage ``fsd_comparison`` of ``loco reproduce``): every damper of
    ``damper_set`` on S_low and S_high, each on tracks ``0 … n_tracks-1`` (one batch per case,
    the tracks as samples).

    Parameters
    ----------
    speed_kmh : float
        Running speed, km/h (SPEC: 200).
    distance : float
        Recorded track length, m (the metrics need at least 5 s of record).
    lead_in : float
        Track run before the recorded ``distance`` and not recorded, m (:data:`LEAD_IN`).
    seed : int
        Track irregularity seed; track ``j`` is its ChaCha stream ``j``, the same for every
        damper (common random numbers: the paired tests of :meth:`FsdComparison.rankings`).
    n_tracks : int
        Tracks per case; the table gives the mean and 95 % interval over them.
    vehicle : Locomotive, optional
        Default: the embedded locomotive.
    damper_set : mapping of str to Damper
        Yaw damper laws by name (default :data:`DAMPERS`).
    integrator : str
        Integration scheme of every run (:data:`loco.simulation.INTEGRATORS`), at its own step.
    s_low_pair : ContactPair, optional
        The wheel/rail pair of the low-conicity case (default: the study's S_low).
    """

    name: ClassVar[str] = "fsd_comparison"
    speed_kmh: float = 200.0
    distance: float = 500.0
    lead_in: float = LEAD_IN
    seed: int = 0
    n_tracks: int = 1
    vehicle: loco.Locomotive | None = None
    damper_set: Mapping[str, dampers.Damper] = field(default_factory=_dampers)
    integrator: str = loco.Scenario.integrator
    s_low_pair: ContactPair | None = None

    def settings(self) -> dict[str, Any]:
        """The comparison's settings as its JSON file and report show them."""
        n, seed = self.n_tracks, self.seed
        return {
            "loco_version": loco.__version__,
            "speed_kmh": self.speed_kmh,
            "distance_m": self.distance,
            "lead_in_m": self.lead_in,
            "track_seed": seed,
            "n_tracks": n,
            "tracks": f"ChaCha streams 0-{n - 1} of track seed {seed}",
            "integrator": self.integrator,
            "cases": [list(c) for c in CASES],
            "dampers": {k: dampers.describe(d) for k, d in self.damper_set.items()},
            "vehicle_overrides": {} if self.vehicle is None else dict(self.vehicle.overrides),
            "s_low_pair": None if self.s_low_pair is None else self.s_low_pair.label,
        }

    def demand(self) -> Demand:
        """One run per (case, damper, track)."""
        n = len(CASES) * len(self.damper_set) * self.n_tracks
        return Demand.runs(n, self.lead_in + self.distance, self.speed_kmh / 3.6)

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """Run the comparison and save it into ``out_dir`` (:func:`save_fsd_comparison`)."""
        return save_fsd_comparison(run_fsd_comparison(self, runtime), out_dir)


def run_fsd_comparison(stage: FsdComparisonStage, runtime: Runtime | None = None) -> FsdComparison:
    """Run the comparison ``stage`` describes (``runtime``: threads and progress bars, default
    all cores and no bars).

    A run that fails (divergence, derailment) is flagged with its message and left out of the
    statistics, so one unstable configuration does not lose the others.
    """
    runtime = runtime or Runtime(progress=False)
    start = time.perf_counter()
    runs = {}
    for scenario_name, label, channel in CASES:
        pair = stage.s_low_pair if scenario_name == "S_low" else None
        where: dict[str, Any] = (
            {"name": scenario_name}
            if pair is None
            else {"wheel": pair.wheel, "rail": pair.rail, "rail_inclination": pair.inclination}
        )
        for name, law in stage.damper_set.items():
            scenario = loco.Scenario(
                **where,
                speed=stage.speed_kmh / 3.6,
                distance=stage.distance,
                lead_in=stage.lead_in,
                seed=stage.seed,
                yaw_damper=law,
                integrator=stage.integrator,
            )
            runs[(scenario_name, name)] = run_over_tracks(
                scenario,
                stage.n_tracks,
                vehicle=stage.vehicle,
                threads=runtime.threads,
                progress=runtime.progress,
                spectra=((label, channel, PEAK_METRICS[label]),),
                keep_first=True,
                derived={VALVE_FRACTION: valve_closed_fraction},
            )
    return FsdComparison(
        damper_laws=dict(stage.damper_set),
        runs=runs,
        settings=stage.settings(),
        seconds=time.perf_counter() - start,
    )


def save_fsd_comparison(cmp: FsdComparison, out_dir: str | Path) -> StudyRecord:
    """Write figures, tables and settings into ``out_dir``; return the record.

    Files: ``fsd_time_histories.png`` and ``fsd_valve.png`` (track 0; and
    ``fsd_valve_hydraulic.png`` for FSD-H), ``fsd_psd.png`` (track-mean PSDs), ``fsd_peaks.png``
    (per-track values, geometric means and 95 % intervals), ``fsd_summary.csv`` (per case:
    geometric mean and interval, median dominant frequency, :meth:`FsdComparison.table`),
    ``fsd_tracks.csv`` (every track), ``fsd_rankings.csv`` (the paired tests),
    ``fsd_valve_open_fraction.csv`` (track 0), ``fsd_psd.csv``, ``fsd_time_histories.csv`` and
    ``fsd_comparison.json`` (loco version and settings).
    """
    from loco.studies.fsd_figures import (
        comparison_notes,
        histories_frame,
        plot_peaks,
        plot_psds,
        plot_time_histories,
        plot_valves,
    )

    start = time.perf_counter()
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    figures = [
        plot_time_histories(cmp, out / "fsd_time_histories.png"),
        plot_psds(cmp, out / "fsd_psd.png"),
        plot_peaks(cmp, out / "fsd_peaks.png"),
        plot_valves(cmp, out / "fsd_valve.png"),
        *(
            [plot_valves(cmp, out / "fsd_valve_hydraulic.png", damper="FSD-H")]
            if "FSD-H" in cmp.damper_laws
            else []
        ),
    ]
    summary = cmp.table()
    spectra = cmp.spectra()
    psd = [
        pd.DataFrame({"scenario": s, "damper": d, "frequency_hz": sp.frequency, "psd": sp.density})
        for (s, d), sp in spectra.items()
    ]
    rankings = cmp.rankings()
    tables = [
        save_table(summary, out / "fsd_summary.csv"),
        save_table(cmp.rankings_frame(), out / "fsd_rankings.csv"),
        save_table(cmp.tracks_frame(), out / "fsd_tracks.csv"),
        save_table(
            pd.concat(psd, ignore_index=True) if psd else pd.DataFrame(), out / "fsd_psd.csv"
        ),
        save_table(histories_frame(cmp), out / "fsd_time_histories.csv"),
        save_table(valve_open_fractions(cmp), out / "fsd_valve_open_fraction.csv"),
        save_json(cmp.settings, out / "fsd_comparison.json"),
    ]
    notes = comparison_notes(cmp, summary, rankings)
    return StudyRecord(
        name=out.name,
        title="YD1, YD2 and FSD yaw dampers on S_low and S_high (SPEC §6.6)",
        figures=figures,
        tables=tables,
        parameters={k: v for k, v in cmp.settings.items() if k != "dampers"},
        seconds=cmp.seconds + time.perf_counter() - start,
        notes=notes,
        captions=figure_captions.FSD_COMPARISON,
    )
