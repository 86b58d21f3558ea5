"""The stages of ``loco reproduce`` that test the study's premise on uncertain inputs.

- :class:`PremiseMapStage` (``premise_map``): the carbody and bogie modes of the linearised
  vehicle over conicity, contact family and yaw damping, and over speed
  (:mod:`loco.studies.premise_map`).
- :class:`ScreeningStage` (``screening``): Morris screening of every ranged input on the modes'
  damping and the linear critical speeds (:func:`loco.uncertainty.morris`): which estimates the
  answer hangs on.
- :class:`PlausibleStage` (``plausible``): plausible locomotives with every damper on S_low and
  S_high, the share that has the premise and what the FSDs do there
  (:mod:`loco.studies.premise_probability`).

The eigen analyses of the first two run as tasks of :func:`loco.executors.task_pool` on the
executor of the run (worker processes, or the Dask cluster's workers); the screening keeps each
finished trajectory in ``<stage>/store/morris_rows.jsonl``, so a killed screening resumes
where it stopped. The plausible locomotives' simulations are ``loco.run_batch`` campaigns with the
run's executor and sample store. Each stage takes a vehicle (default: the default vehicle), so
:func:`loco.uncertainty.premise_study` runs them on any vehicle file.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

import numpy as np
import pandas as pd

import loco
from loco import campaign, uncertainty
from loco.executors import task_pool
from loco.studies import captions as figure_captions
from loco.studies import premise_map, premise_probability
from loco.studies.fsd_comparison import LEAD_IN
from loco.studies.plotting import pyplot, save_figure
from loco.studies.premise_sensitivity import advantage_sensitivity, premise_sensitivity
from loco.studies.report import StudyRecord, save_json
from loco.studies.stages import DataFile, Demand, Runtime, Stage

__all__ = ["PlausibleStage", "PremiseMapStage", "ScreeningStage"]

#: Speeds of the premise map's speed sweep, km/h.
SWEEP_SPEEDS_KMH: tuple[float, ...] = tuple(float(v) for v in range(100, 361, 20))


def _executor() -> Any:
    """The executor of the enclosing campaign block (None outside one)."""
    context = campaign.current()
    return None if context is None else context.executor


def premise_cells_note(cells: pd.DataFrame) -> str:
    """Where the premise and its reverse hold, per contact family, in words."""
    parts = []
    for family, g in cells.groupby("family", sort=False):
        held = g[g["premise"]]
        if family == "pair":
            where = ", ".join(held["pair"]) if len(held) else "none"
        elif len(held):
            low, high = held["conicity"].min(), held["conicity"].max()
            where = f"conicity {low:g}" + (f"–{high:g}" if high > low else "")
        else:
            where = "nowhere"
        parts.append(f"{family}: {where}")
    return "Premise (carbody mode stable with YD1, unstable with YD2) on " + "; ".join(parts) + "."


@dataclass(frozen=True)
class PremiseMapStage(Stage):
    """The premise map at ``speed_kmh`` (km/h) over ``conicities`` (–) and ``dampings``
    (N·s/m), and both modes over ``sweep_speeds_kmh`` (km/h) with YD1 and YD2, of ``vehicle``.
    Writes ``premise_map.csv``, ``premise_speed.csv``, ``premise_cells.csv`` and
    ``premise_map.png``."""

    name: ClassVar[str] = "premise_map"
    conicities: tuple[float, ...] = premise_map.CONICITIES
    dampings: tuple[float, ...] = premise_map.DAMPINGS
    speed_kmh: float = 200.0
    sweep_speeds_kmh: tuple[float, ...] = SWEEP_SPEEDS_KMH
    vehicle: loco.Locomotive | None = None

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        with task_pool(_executor()) as pool:
            result = premise_map.premise_map(
                self.vehicle,
                conicities=self.conicities,
                dampings=self.dampings,
                speed=self.speed_kmh / 3.6,
                executor=pool,
                progress=runtime.progress,
            )
            sweep = premise_map.speed_sweep(
                self.vehicle,
                speeds=[v / 3.6 for v in self.sweep_speeds_kmh],
                executor=pool,
                progress=runtime.progress,
            )
        cells = premise_map.premise_cells(result)
        tables = [out / "premise_map.csv", out / "premise_speed.csv", out / "premise_cells.csv"]
        for frame, path in zip((result, sweep, cells), tables, strict=True):
            frame.to_csv(path, index=False, float_format="%.6g")
        figure = out / "premise_map.png"
        premise_map.plot_premise_map(result, sweep, path=figure)
        return StudyRecord(
            name=self.name,
            title="Premise map: the carbody and bogie modes over conicity and yaw damping",
            figures=[figure],
            tables=tables,
            notes=premise_cells_note(cells),
            captions=figure_captions.PREMISE_MAP,
        )


@dataclass(frozen=True)
class ScreeningStage(Stage):
    """Morris screening (:func:`loco.uncertainty.morris`) of ``vehicle``'s ranged inputs on
    ``outputs`` (names of :data:`loco.uncertainty.OUTPUTS`), ``trajectories`` on a
    ``levels``-level grid from ``seed``. Writes ``morris.csv`` (μ*, μ, σ per input and
    output), ``morris_outputs.csv`` (every point's outputs) and ``morris.png``."""

    name: ClassVar[str] = "screening"
    trajectories: int = 20
    levels: int = 4
    seed: int = 0
    outputs: tuple[str, ...] = tuple(uncertainty.OUTPUTS)
    vehicle: loco.Locomotive | None = None
    ranges: DataFile | None = None

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        out = Path(out_dir)
        rows_file = out / "store" / "morris_rows.jsonl"
        rows_file.parent.mkdir(parents=True, exist_ok=True)
        known: dict[int, list[float]] = {}
        if rows_file.is_file():
            for line in rows_file.read_text(encoding="utf-8").splitlines():
                try:
                    row = json.loads(line)
                    known[int(row["i"])] = [float(v) for v in row["y"]]
                except (ValueError, KeyError, TypeError):
                    break  # a line cut by a kill: the rest is evaluated again
        rows = dict(known)
        with rows_file.open("a", encoding="utf-8") as sink, task_pool(_executor()) as pool:

            def keep(i: int, values: list[float]) -> None:
                rows[i] = values
                sink.write(json.dumps({"i": i, "y": values}) + "\n")
                sink.flush()

            result = uncertainty.morris(
                self.vehicle,
                self.outputs,
                trajectories=self.trajectories,
                seed=self.seed,
                executor=pool,
                progress=runtime.progress,
                levels=self.levels,
                on_row=keep,
                known=known,
                ranges_file=None if self.ranges is None else self.ranges.path,
            )
        table_path = out / "morris.csv"
        result.to_csv(table_path, index=False, float_format="%.6g")
        outputs_path = out / "morris_outputs.csv"
        frame = pd.DataFrame([rows[i] for i in sorted(rows)], columns=list(self.outputs))
        frame.to_csv(outputs_path, index=False, float_format="%.17g")
        figure = out / "morris.png"
        pyplot().close(uncertainty.plot_morris(result, path=figure))
        reused = f" ({len(known)} points from the store)" if known else ""
        return StudyRecord(
            name=self.name,
            title="Which estimates matter: Morris screening of the ranged inputs",
            figures=[figure],
            tables=[table_path, outputs_path],
            captions=figure_captions.SCREENING,
            notes=f"{len(frame)} points of {result['input'].nunique()} inputs{reused}. "
            + top_inputs_note(result),
        )


def top_inputs(result: pd.DataFrame, output: str, top: int = 3) -> list[tuple[str, float]]:
    """The ``top`` inputs of a screening table by μ* on ``output``, with their μ*."""
    rows = result[result["output"] == output].sort_values("mu_star", ascending=False).head(top)
    return [(str(r["input"]), float(r["mu_star"])) for _, r in rows.iterrows()]


def top_inputs_note(result: pd.DataFrame, top: int = 3) -> str:
    """One sentence per output: its ``top`` inputs by μ*."""
    parts = []
    for output in dict.fromkeys(result["output"]):
        names = ", ".join(f"`{k}` ({v:.3g})" for k, v in top_inputs(result, output, top))
        parts.append(f"{output}: {names}")
    return "Largest μ* per output: " + "; ".join(parts) + "."


@dataclass(frozen=True)
class PlausibleStage(Stage):
    """``n`` plausible locomotives of ``vehicle`` (from ``seed``) with every damper of
    :data:`loco.studies.premise_probability.DAMPERS` on their S_low pair and on S_high,
    ``distance`` m at ``speed_kmh`` km/h after the lead-in, on ``n_tracks`` tracks. Writes
    ``plausible.csv`` (inputs, pair, metrics, premise and valve shares per locomotive),
    ``plausible_fraction.csv``, ``plausible_fsd.csv``, ``plausible_importance.csv`` (which
    inputs decide the premise), ``plausible_advantage.csv`` (which decide the FSDs' advantage,
    :mod:`loco.studies.premise_sensitivity`), ``plausible.json`` and ``plausible.png``."""

    name: ClassVar[str] = "plausible"
    n: int = 200
    seed: int = 0
    n_tracks: int = 2
    speed_kmh: float = 200.0
    distance: float = 500.0
    vehicle: loco.Locomotive | None = None
    integrator: str = loco.Scenario.integrator
    ranges: DataFile | None = None

    def demand(self) -> Demand:
        runs = self.n * len(premise_probability.DAMPERS) * 2 * self.n_tracks
        return Demand.runs(runs, self.distance + LEAD_IN, self.speed_kmh / 3.6)

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        pp = premise_probability
        result = pp.run_plausible(
            self.n,
            self.seed,
            n_tracks=self.n_tracks,
            speed=self.speed_kmh / 3.6,
            distance=self.distance,
            vehicle=self.vehicle,
            threads=runtime.threads,
            progress=runtime.progress,
            integrator=self.integrator,
            ranges_file=None if self.ranges is None else self.ranges.path,
        )
        summary = pp.summarise(result)
        sens = premise_sensitivity(result, seed=self.seed)
        advantage = advantage_sensitivity(result, seed=self.seed)
        paths = {
            "plausible": out / "plausible.csv",
            "fraction": out / "plausible_fraction.csv",
            "fsd": out / "plausible_fsd.csv",
            "importance": out / "plausible_importance.csv",
            "advantage": out / "plausible_advantage.csv",
        }
        pp.to_frame(result).to_csv(paths["plausible"], index=False, float_format="%.6g")
        summary["fraction"].to_csv(paths["fraction"], index=False, float_format="%.4g")
        summary["fsd"].to_csv(paths["fsd"], index=False, float_format="%.4g")
        sens["importance"].to_csv(paths["importance"], index=False, float_format="%.4g")
        advantage.to_csv(paths["advantage"], index=False, float_format="%.4g")
        meta = {
            **result.settings,
            "failed_runs": result.failed,
            "classifier_accuracy": sens["accuracy"],
            "majority_share": sens["majority"],
        }
        meta_path = save_json(meta, out / "plausible.json")
        figure = plot_plausible(summary, result, out / "plausible.png")
        return StudyRecord(
            name=self.name,
            title="The verdict's probability: plausible locomotives",
            figures=[figure],
            tables=[*paths.values(), meta_path],
            captions=figure_captions.PLAUSIBLE,
            notes=probability_note(summary["fraction"], result.failed),
        )


def pooled(fraction: pd.DataFrame, rule: str = "premise") -> pd.Series:
    """The pooled row of a ``plausible_fraction`` table for ``rule``."""
    return fraction[(fraction["pair"] == "all pairs") & (fraction["rule"] == rule)].iloc[0]


def probability_note(fraction: pd.DataFrame, failed: int = 0) -> str:
    """The share with the premise, pooled, with its interval (and the failed runs)."""
    row = pooled(fraction)
    note = (
        f"The premise holds on {int(row['k'])} of {int(row['n'])} plausible locomotives "
        f"({row['fraction']:.0%}, 95 % Wilson interval {row['low']:.0%}–{row['high']:.0%})."
    )
    if failed:
        note += f" {failed} runs failed (their locomotives' metrics are means of the rest)."
    return note


def plot_plausible(
    summary: dict[str, pd.DataFrame], result: premise_probability.Plausible, path: Path
) -> Path:
    """Left: the share with the premise per S_low pair and pooled, with 95 % intervals. Right:
    inside the premise set, each FSD's judging metric over the better fixed damper's, per
    locomotive (below 1: the FSD is better)."""
    plt = pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    rows = summary["fraction"][summary["fraction"]["rule"] == "premise"]
    y = np.arange(len(rows))
    left.errorbar(
        rows["fraction"],
        y,
        xerr=[rows["fraction"] - rows["low"], rows["high"] - rows["fraction"]],
        fmt="o",
        capsize=4,
    )
    left.set_yticks(y, [f"{p} (n={n})" for p, n in zip(rows["pair"], rows["n"], strict=True)])
    left.invert_yaxis()
    left.set_xlim(0, 1)
    left.set_xlabel("share of plausible locomotives with the premise (95 % interval)")
    m = result.metrics[premise_probability.premise_holds(result.metrics)]
    data, labels = [], []
    for name in premise_probability.VALVED:
        for scenario, better in (("S_low", "YD1"), ("S_high", "YD2")):
            ratio = (m[f"{scenario} {name}"] / m[f"{scenario} {better}"]).dropna()
            if len(ratio):
                data.append(ratio.to_numpy())
                labels.append(f"{name}/{better}\n{scenario}")
    if data:
        right.boxplot(data)
        right.set_xticks(range(1, len(data) + 1), labels)
        right.set_yscale("log")
    right.axhline(1.0, color="0.5", lw=0.8)
    right.set_ylabel("FSD metric / better fixed damper's (–)")
    right.set_title(f"inside the premise set ({len(m)} locomotives)", fontsize=10)
    fig.tight_layout()
    return save_figure(fig, path)
