"""The stage ``screening`` of ``loco reproduce``: Morris screening of every ranged input on the
modes' damping and the linear critical speeds (:func:`loco.uncertainty.morris`): which estimates
the answer hangs on.

The eigen analyses run as tasks of :func:`loco.executors.task_pool` on the executor of the run
(worker processes, or the Dask cluster's workers); each finished trajectory is kept in
``<stage>/store/morris_rows.jsonl``, so a killed screening resumes where it stopped.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import pandas as pd

import loco
from loco import uncertainty
from loco.executors import task_pool
from loco.studies import captions as figure_captions
from loco.studies.plotting import pyplot
from loco.studies.report import StudyRecord
from loco.studies.stages import DataFile, Runtime, Stage, campaign_executor

__all__ = ["ScreeningStage", "top_inputs", "top_inputs_note"]


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
        with rows_file.open("a", encoding="utf-8") as sink, task_pool(campaign_executor()) as pool:

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
