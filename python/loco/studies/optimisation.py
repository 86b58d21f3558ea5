"""The stage ``optimisation`` of ``loco reproduce`` (SPEC §6.4): NSGA-II on the surrogates
(Pareto front, distribution of each parameter along it), then a spread of Pareto points
re-simulated with the real model and the surrogate's error there. The search and the front's
figures are :mod:`loco.studies.pareto`'s.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np
import numpy.typing as npt
import pandas as pd

import loco
from loco.studies import captions as figure_captions
from loco.studies.parameter_study import (
    LOG_TARGET,
    OBJECTIVES,
    StudySetup,
    axis_label,
    fit_surrogates,
    labels,
    surrogate_objectives,
)
from loco.studies.pareto import ParetoResult, nsga2, pick_spread, plot_pareto, verify_points
from loco.studies.plotting import pyplot, save_figure
from loco.studies.rbf_network import Predictor
from loco.studies.report import StudyRecord, save_json, save_table
from loco.studies.stages import Demand, Runtime
from loco.studies.surrogate import OnSurrogates

__all__ = ["OptimisationStage", "run_optimisation"]

FloatArray = npt.NDArray[np.float64]


def _plot_verification(result: ParetoResult, check: pd.DataFrame, path: Path) -> Path:
    a, b = result.objectives
    fig, ax = pyplot().subplots(figsize=(6, 4.5), layout="constrained")
    ax.scatter(result.f[:, 0], result.f[:, 1], s=6, color="0.7", label="Pareto front (surrogate)")
    ax.scatter(
        check[f"{a}_surrogate"],
        check[f"{b}_surrogate"],
        s=30,
        facecolors="none",
        edgecolors="C0",
        label="picked points, surrogate",
    )
    ax.scatter(
        check[f"{a}_simulated"],
        check[f"{b}_simulated"],
        s=30,
        marker="x",
        color="C3",
        label="picked points, re-simulated",
    )
    for i in range(len(check)):
        ax.plot(
            [check[f"{a}_surrogate"].iloc[i], check[f"{a}_simulated"].iloc[i]],
            [check[f"{b}_surrogate"].iloc[i], check[f"{b}_simulated"].iloc[i]],
            color="0.4",
            lw=0.7,
        )
    ax.set(
        xlabel=axis_label(OBJECTIVES[0]),
        ylabel=axis_label(OBJECTIVES[1]),
        title="Surrogate Pareto points re-simulated with the model",
    )
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return save_figure(fig, path)


def run_optimisation(
    setup: StudySetup,
    x_lhs: FloatArray,
    y_lhs: FloatArray,
    out_dir: Path,
    *,
    pop_size: int = 500,
    n_gen: int = 100,
    n_verify: int = 10,
    seed: int = 0,
    log_target: bool = LOG_TARGET,
    models: Sequence[Predictor] | None = None,
    surrogate_name: str = "SPEC RBF network",
    runtime: Runtime | None = None,
) -> StudyRecord:
    """NSGA-II on the surrogates of W_y and A_yb, then ``n_verify`` Pareto points spread along
    the front re-simulated (``setup``, on ``runtime``) to measure the surrogate's error.
    ``models`` and ``surrogate_name`` are as in :func:`run_sensitivity` (default: the SPEC
    networks, fitted here).

    Writes ``pareto.png`` (front and parameter distributions), ``pareto_verification.png``,
    ``pareto_front.csv``, ``pareto_verification.csv`` and ``optimisation.json``.
    """
    runtime = runtime or Runtime()
    if models is None:
        models = fit_surrogates(x_lhs, y_lhs, log_target=log_target, seed=seed)
    result = nsga2(
        surrogate_objectives(models, log_target=log_target),
        labels(),
        pop_size=pop_size,
        n_gen=n_gen,
        seed=seed,
        progress=runtime.progress,
    )
    plot_pareto(
        result,
        out_dir / "pareto.png",
        title=f"NSGA-II on the surrogates ({surrogate_name}): population {pop_size}, "
        f"{n_gen} generations",
    )
    picked = pick_spread(result, n_verify)
    check = verify_points(result, picked, setup.evaluator(runtime))
    errors = {
        o: {
            "mean_abs_rel_error": float(np.nanmean(np.abs(check[f"{o}_rel_error"]))),
            "max_abs_rel_error": float(np.nanmax(np.abs(check[f"{o}_rel_error"]))),
            "n_failed": int(check[f"{o}_simulated"].isna().sum()),
        }
        for o in labels()
    }
    settings = {
        "loco_version": loco.__version__,
        "pop_size": pop_size,
        "n_gen": n_gen,
        "n_verify": n_verify,
        "seed": seed,
        "log_target": log_target,
        "lhs_samples": len(x_lhs),
        "surrogate": surrogate_name,
        "nsga2_seconds": result.seconds,
        **setup.settings(),
    }
    notes = (
        f"{len(result.f)} Pareto points; W_y from {result.f[:, 0].min():.3g} to "
        f"{result.f[:, 0].max():.3g}, A_yb from {result.f[:, 1].min():.3g} to "
        f"{result.f[:, 1].max():.3g} m/s² (surrogate: {surrogate_name}). Surrogate error at "
        f"{len(picked)} "
        "re-simulated points, mean |relative error|: "
        + ", ".join(
            f"{o} {e['mean_abs_rel_error']:.1%} (max {e['max_abs_rel_error']:.1%})"
            for o, e in errors.items()
        )
        + "."
    )
    return StudyRecord(
        name=out_dir.name,
        title="Multi-objective optimisation: NSGA-II on the surrogate (SPEC §6.4)",
        figures=[
            out_dir / "pareto.png",
            _plot_verification(result, check, out_dir / "pareto_verification.png"),
        ],
        tables=[
            save_table(check, out_dir / "pareto_verification.csv"),
            save_table(result.to_frame(), out_dir / "pareto_front.csv"),
            save_json({**settings, "surrogate_error": errors}, out_dir / "optimisation.json"),
        ],
        parameters=settings,
        notes=notes,
        captions=figure_captions.OPTIMISATION,
    )


@dataclass(frozen=True)
class OptimisationStage(OnSurrogates):
    """The stage ``optimisation`` of ``loco reproduce``: :func:`run_optimisation` on the
    surrogates of ``training``, ``n_verify`` Pareto points re-simulated on ``setup``."""

    name: ClassVar[str] = "optimisation"
    pop_size: int
    n_gen: int
    n_verify: int

    def demand(self) -> Demand:
        """At most: both objectives on ``n_verify`` Pareto points (fewer when the front has
        fewer)."""
        return self.setup.demand(self.n_verify)

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """:func:`run_optimisation` into ``out_dir``."""
        sizes = {"pop_size": self.pop_size, "n_gen": self.n_gen, "n_verify": self.n_verify}
        return self._study(run_optimisation, out_dir, runtime, **sizes)
