"""The stage ``monte_carlo`` of ``loco reproduce`` (SPEC §6.2): a Latin hypercube over the six
parameters, both objectives simulated; its table ``monte_carlo.csv`` and its figure.

The objectives and the table's layout are :mod:`loco.studies.parameter_study`'s.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np

import loco
from loco.studies import captions as figure_captions
from loco.studies.parameter_study import (
    OBJECTIVES,
    FloatArray,
    StudySetup,
    axis_label,
    labels,
    samples_frame,
)
from loco.studies.parameters import STUDY_PARAMETERS, names, to_study_units
from loco.studies.plotting import pyplot, save_figure
from loco.studies.report import StudyRecord, save_json, save_table
from loco.studies.sampling import latin_hypercube
from loco.studies.stages import Demand, Runtime, Stage

__all__ = ["MonteCarloStage", "run_monte_carlo"]


def _plot_scatter(x: FloatArray, y: FloatArray, path: Path) -> Path:
    units = to_study_units(x)
    k = len(STUDY_PARAMETERS)
    fig, axes = pyplot().subplots(
        len(OBJECTIVES),
        k,
        figsize=(2.3 * k, 2.4 * len(OBJECTIVES) + 0.6),
        sharey="row",
        squeeze=False,
        layout="constrained",
    )
    for i, objective in enumerate(OBJECTIVES):
        for j, p in enumerate(STUDY_PARAMETERS):
            ax = axes[i, j]
            ax.scatter(units[:, j], y[:, i], s=6, alpha=0.7, color=f"C{i}")
            ax.set_xlim(p.low, p.high)
            ax.set_xlabel(f"{p.name} ({p.unit})", fontsize=8)
            ax.tick_params(labelsize=7)
            ax.grid(True, alpha=0.3)
        axes[i, 0].set_ylabel(axis_label(objective), fontsize=8)
    fig.suptitle(f"Latin hypercube Monte Carlo, {len(x)} samples (loco {loco.__version__})")
    return save_figure(fig, path)


@dataclass(frozen=True)
class MonteCarloStage(Stage):
    """The stage ``monte_carlo`` of ``loco reproduce``: :func:`run_monte_carlo` of ``n_samples``
    on ``setup`` with the Latin hypercube's ``seed``."""

    name: ClassVar[str] = "monte_carlo"
    setup: StudySetup
    n_samples: int
    seed: int = 0

    def demand(self) -> Demand:
        """Both objectives on every sample."""
        return self.setup.demand(self.n_samples)

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """:func:`run_monte_carlo` into ``out_dir``."""
        return run_monte_carlo(self.setup, self.n_samples, self.seed, out_dir, runtime)


def run_monte_carlo(
    setup: StudySetup, n_samples: int, seed: int, out_dir: Path, runtime: Runtime | None = None
) -> StudyRecord:
    """Latin hypercube of ``n_samples`` over the six parameters (``seed``), both objectives
    simulated (on ``runtime``). Writes ``monte_carlo.csv`` (samples in SI and the study's units,
    objectives), ``monte_carlo_summary.csv``, ``monte_carlo.png`` (objectives against each
    parameter) and ``monte_carlo.json``."""
    x = latin_hypercube(n_samples, seed=seed)
    y = setup.evaluator(runtime)(x, names())
    frame = samples_frame(x, y)
    summary = frame[labels()].describe().T.reset_index(names="objective")
    summary["n_failed"] = [int(np.isnan(y[:, j]).sum()) for j in range(y.shape[1])]
    settings = {
        "loco_version": loco.__version__,
        "lhs_samples": n_samples,
        "lhs_seed": seed,
        **setup.settings(),
    }
    return StudyRecord(
        name=out_dir.name,
        title="Monte Carlo: Latin hypercube over the six parameters (SPEC §6.2)",
        figures=[_plot_scatter(x, y, out_dir / "monte_carlo.png")],
        tables=[
            save_table(frame, out_dir / "monte_carlo.csv"),
            save_table(summary, out_dir / "monte_carlo_summary.csv"),
            save_json(settings, out_dir / "monte_carlo.json"),
        ],
        parameters=settings,
        captions=figure_captions.MONTE_CARLO,
        notes=f"{n_samples} samples; failed runs per objective: "
        + ", ".join(f"{r.objective} {r.n_failed}" for r in summary.itertuples()),
    )
