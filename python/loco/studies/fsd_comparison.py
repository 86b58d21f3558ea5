"""Yaw damper comparison of SPEC §6.6: the locomotive with YD1, YD2 and FSD yaw dampers on S_low
and S_high at 200 km/h.

Six runs of :func:`loco.simulate` (in parallel threads: the simulator releases the GIL), all on
the same synthesised track. Outputs: the time histories and Welch PSDs of the carbody floor
lateral acceleration A_yc on S_low (low-conicity carbody sway) and of the bogie frame lateral
acceleration A_yb on S_high (high-conicity bogie hunting), the dominant frequency and PSD peak of
each (the core's run metrics, :data:`loco.studies.speed_sweep.PEAK_METRICS`), and the state of
the FSD frequency valves over time (channels ``*_valve``: 0 open, low damping c1; 1 closed,
high damping c2).
"""

from __future__ import annotations

import os
import time
from collections.abc import Mapping
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

import loco
from loco import dampers
from loco.studies.plotting import Spectrum, draw_spectra, pyplot, save_figure
from loco.studies.report import StudyRecord, save_json, save_table
from loco.studies.speed_sweep import A_YB, A_YC, RMS_METRICS, spectrum

__all__ = [
    "CASES",
    "DAMPERS",
    "FsdComparison",
    "plot_psds",
    "plot_time_histories",
    "plot_valves",
    "run_fsd_comparison",
    "save_fsd_comparison",
    "valve_open_fractions",
]

#: The yaw dampers compared (SPEC §4), and the FSD with the hydraulic frequency valve (FSD-H).
DAMPERS: dict[str, dampers.Damper] = {**dampers.PRESETS, "FSD-H": dampers.FSD_HYDRAULIC}
#: (scenario, quantity label, channel): A_yc judges S_low, A_yb judges S_high.
CASES: tuple[tuple[str, str, str], ...] = (("S_low", *A_YC), ("S_high", *A_YB))
SCENARIO_QUANTITY: dict[str, str] = {s: q for s, q, _ in CASES}
#: Suffix of the frequency-valve channels of the yaw dampers.
VALVE_SUFFIX = "_valve"


@dataclass(frozen=True)
class FsdComparison:
    """Runs keyed by (scenario, damper name); a failed run is None with its message in
    ``errors``."""

    damper_laws: dict[str, dampers.Damper]
    """The yaw damper laws compared, by name (in order)."""
    results: dict[tuple[str, str], loco.SimulationResult | None]
    errors: dict[tuple[str, str], str]
    settings: dict[str, Any] = field(default_factory=dict)
    seconds: float = 0.0
    _spectra: dict[tuple[str, str], Spectrum] = field(
        default_factory=dict, init=False, repr=False, compare=False
    )

    @property
    def dampers(self) -> tuple[str, ...]:
        """Names of the yaw dampers compared, in order."""
        return tuple(self.damper_laws)

    def has_valve(self, damper: str) -> bool:
        """Whether the yaw damper law ``damper`` has a frequency valve (an FSD)."""
        law = self.damper_laws.get(damper)
        return law is not None and law.kind == "fsd"

    def spectra(self) -> dict[tuple[str, str], Spectrum]:
        """Spectrum of each case's quantity (A_yc on S_low, A_yb on S_high), by (scenario,
        damper): the PSD curve by :func:`loco.metrics.psd`, its peak from the run's metrics.
        Computed once, on the first call."""
        if not self._spectra:
            for scenario, label, _ in CASES:
                for name in self.dampers:
                    result = self.results.get((scenario, name))
                    if result is not None:
                        self._spectra[(scenario, name)] = spectrum(result, label)
        return self._spectra

    def table(self) -> pd.DataFrame:
        """One row per (scenario, damper): the quantity, its rms (m/s²), dominant frequency (Hz),
        PSD peak ((m/s²)²/Hz) (all three the core's run metrics), W_y and A_yb peak of the run,
        the fraction of time the yaw damper valves were closed (FSD only, NaN for dampers without
        a valve), and the error message of a failed run."""
        spectra = self.spectra()
        rows = []
        for scenario, label, channel in CASES:
            for name in self.dampers:
                result = self.results.get((scenario, name))
                row: dict[str, Any] = {
                    "scenario": scenario,
                    "damper": name,
                    "quantity": label,
                    "channel": channel,
                }
                if result is None:
                    row["error"] = self.errors.get((scenario, name), "")
                    rows.append(row)
                    continue
                sp = spectra[(scenario, name)]
                valves = [result.channel(c) for c in valve_channels(result)]
                valves = valves if self.has_valve(name) else []
                row.update(
                    rms=result.metrics[RMS_METRICS[label]],
                    dominant_hz=sp.dominant_hz,
                    psd_peak=sp.peak,
                    wy_max=result.metrics["wy_max"],
                    ayb_peak_lp=result.metrics["ayb_peak_lp"],
                    valve_closed_fraction=float(np.mean(valves)) if valves else np.nan,
                    error="",
                )
                rows.append(row)
        return pd.DataFrame(rows)


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
    return [c for c in result.channel_names if c.endswith(VALVE_SUFFIX)]


#: Track run before the recorded section, m. The FSD starts in its defined state (valve closed,
#: high damping) and its trigger needs a few cycles of the slow carbody sway to open the valve:
#: at 200 km/h on S_low that took 3–7 s (170–390 m) from the start of the run. 500 m of lead-in
#: compares the dampers in their steady regime, every damper on the same track and section.
LEAD_IN = 500.0


def run_fsd_comparison(
    *,
    speed_kmh: float = 200.0,
    distance: float = 500.0,
    lead_in: float = LEAD_IN,
    seed: int = 0,
    vehicle: loco.Locomotive | None = None,
    damper_set: Mapping[str, dampers.Damper] = DAMPERS,
    threads: int | None = None,
) -> FsdComparison:
    """Run every damper of ``damper_set`` on S_low and S_high.

    Parameters
    ----------
    speed_kmh : float
        Running speed, km/h (SPEC: 200).
    distance : float
        Recorded track length, m (the metrics need at least 5 s of record).
    lead_in : float
        Track run before the recorded ``distance`` and not recorded, m (:data:`LEAD_IN`).
    seed : int
        Track irregularity seed, the same for every run.
    vehicle : Locomotive, optional
        Default: the embedded locomotive.
    damper_set : mapping of str to Damper
        Yaw damper laws by name (default YD1, YD2, FSD).
    threads : int, optional
        Runs at once (default: all cores).

    A run that fails with :class:`loco.SimulationError` (divergence, derailment) is kept as
    None with its message, so one unstable configuration does not lose the others.
    """
    start = time.perf_counter()
    vehicle = vehicle if vehicle is not None else loco.Locomotive.default()
    keys = [(s, name) for s, _, _ in CASES for name in damper_set]

    def one(key: tuple[str, str]) -> tuple[loco.SimulationResult | None, str]:
        scenario = loco.Scenario(
            scenario=key[0],
            speed=speed_kmh / 3.6,
            distance=distance,
            lead_in=lead_in,
            seed=seed,
            yaw_damper=damper_set[key[1]],
        )
        try:
            return loco.simulate(vehicle, scenario), ""
        except loco.SimulationError as e:
            return None, f"{type(e).__name__}: {e}"

    workers = max(1, min(len(keys), threads or os.cpu_count() or 1))
    with ThreadPoolExecutor(max_workers=workers) as pool:
        outcomes = list(pool.map(one, keys))
    settings = {
        "loco_version": loco.__version__,
        "speed_kmh": speed_kmh,
        "distance_m": distance,
        "lead_in_m": lead_in,
        "track_seed": seed,
        "cases": [list(c) for c in CASES],
        "dampers": {n: dampers.describe(d) for n, d in damper_set.items()},
        "vehicle_overrides": dict(vehicle.overrides),
    }
    return FsdComparison(
        damper_laws=dict(damper_set),
        results={k: r for k, (r, _) in zip(keys, outcomes, strict=True)},
        errors={k: m for k, (_, m) in zip(keys, outcomes, strict=True) if m},
        settings=settings,
        seconds=time.perf_counter() - start,
    )


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
    fig.suptitle(f"{cmp.settings.get('speed_kmh', 0.0):g} km/h (loco {loco.__version__})")
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
    fig.suptitle(f"{damper} frequency valve state (0 open: low damping; 1 closed: high damping)")
    return save_figure(fig, path)


def _histories_frame(cmp: FsdComparison) -> pd.DataFrame:
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


def save_fsd_comparison(cmp: FsdComparison, out_dir: str | Path) -> StudyRecord:
    """Write figures, tables and settings into ``out_dir``; return the record.

    Files: ``fsd_time_histories.png``, ``fsd_psd.png``, ``fsd_valve.png`` (and
    ``fsd_valve_hydraulic.png`` for FSD-H), ``fsd_valve_open_fraction.csv``, ``fsd_summary.csv``
    (dominant frequency and PSD peak per run), ``fsd_psd.csv``, ``fsd_time_histories.csv`` and
    ``fsd_comparison.json`` (loco version and settings).
    """
    start = time.perf_counter()
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    figures = [
        plot_time_histories(cmp, out / "fsd_time_histories.png"),
        plot_psds(cmp, out / "fsd_psd.png"),
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
    tables = [
        save_table(summary, out / "fsd_summary.csv"),
        save_table(
            pd.concat(psd, ignore_index=True) if psd else pd.DataFrame(), out / "fsd_psd.csv"
        ),
        save_table(_histories_frame(cmp), out / "fsd_time_histories.csv"),
        save_table(valve_open_fractions(cmp), out / "fsd_valve_open_fraction.csv"),
        save_json(cmp.settings, out / "fsd_comparison.json"),
    ]
    lead_in = cmp.settings.get("lead_in_m", 0.0)
    notes = f"Recorded after {lead_in:g} m of lead-in (start transients settled). " + "; ".join(
        f"{s} {d}: {SCENARIO_QUANTITY[s]} dominant {sp.dominant_hz:.2f} Hz, "
        f"PSD peak {sp.peak:.3g} (m/s²)²/Hz"
        for (s, d), sp in spectra.items()
    )
    openings = valve_open_fractions(cmp)
    bogies = openings[openings["valve"] == openings["bogie"]]
    notes += ". Valve open fraction (1 - mean scale factor) by bogie: " + "; ".join(
        f"{r.scenario} {r.damper} {r.bogie} {r.open_fraction:.2f}" for r in bogies.itertuples()
    )
    if cmp.errors:
        notes += ". Failed: " + "; ".join(f"{s} {d}: {m}" for (s, d), m in cmp.errors.items())
    return StudyRecord(
        name=out.name,
        title="YD1, YD2 and FSD yaw dampers on S_low and S_high (SPEC §6.6)",
        figures=figures,
        tables=tables,
        parameters={k: v for k, v in cmp.settings.items() if k != "dampers"},
        seconds=cmp.seconds + time.perf_counter() - start,
        notes=notes + ".",
    )
