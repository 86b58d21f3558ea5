"""The stage ``premise_map`` of ``loco reproduce``: the carbody and bogie modes of the linearised
vehicle over conicity, contact family and yaw damping at the study speed, and over speed with YD1
and YD2 (computed by :mod:`loco.studies.premise_modes`), and where the study's premise holds.

The eigen analyses run as tasks of :func:`loco.executors.task_pool` on the executor of the run
(worker processes, or the Dask cluster's workers). The stage takes a vehicle (default: the
default vehicle), so :func:`loco.studies.premise_study.premise_study` runs it on any vehicle file.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import pandas as pd

import loco
from loco.executors import task_pool
from loco.studies import captions as figure_captions
from loco.studies import premise_modes
from loco.studies.report import StudyRecord
from loco.studies.stages import Runtime, Stage, campaign_executor

__all__ = ["SWEEP_SPEEDS_KMH", "PremiseMapStage", "premise_cells_note"]

#: Speeds of the premise map's speed sweep, km/h.
SWEEP_SPEEDS_KMH: tuple[float, ...] = tuple(float(v) for v in range(100, 361, 20))


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
    conicities: tuple[float, ...] = premise_modes.CONICITIES
    dampings: tuple[float, ...] = premise_modes.DAMPINGS
    speed_kmh: float = 200.0
    sweep_speeds_kmh: tuple[float, ...] = SWEEP_SPEEDS_KMH
    vehicle: loco.Locomotive | None = None

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        with task_pool(campaign_executor()) as pool:
            result = premise_modes.premise_map(
                self.vehicle,
                conicities=self.conicities,
                dampings=self.dampings,
                speed=self.speed_kmh / 3.6,
                executor=pool,
                progress=runtime.progress,
            )
            sweep = premise_modes.speed_sweep(
                self.vehicle,
                speeds=[v / 3.6 for v in self.sweep_speeds_kmh],
                executor=pool,
                progress=runtime.progress,
            )
        cells = premise_modes.premise_cells(result)
        tables = [out / "premise_map.csv", out / "premise_speed.csv", out / "premise_cells.csv"]
        for frame, path in zip((result, sweep, cells), tables, strict=True):
            frame.to_csv(path, index=False, float_format="%.6g")
        figure = out / "premise_map.png"
        premise_modes.plot_premise_map(result, sweep, path=figure)
        return StudyRecord(
            name=self.name,
            title="Premise map: the carbody and bogie modes over conicity and yaw damping",
            figures=[figure],
            tables=tables,
            notes=premise_cells_note(cells),
            captions=figure_captions.PREMISE_MAP,
        )
