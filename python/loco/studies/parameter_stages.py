"""Sobol' sensitivity and NSGA-II optimisation of the parameter study (SPEC §6.2, §6.4), on the
simulator and on the surrogates trained from the Latin hypercube Monte Carlo of
:mod:`loco.studies.parameter_study`.

- :func:`run_sensitivity`: Sobol' first- and total-order indices of W_y (S_low) and A_yb
  (S_high), computed directly on the simulator from a Saltelli design and on the surrogates, side
  by side, and their convergence with the number of Saltelli base samples.
- :func:`run_optimisation`: NSGA-II on the surrogates (Pareto front, distribution of each
  parameter along it), then a spread of Pareto points re-simulated with the real model and the
  surrogate's error there.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

import numpy as np
import numpy.typing as npt
import pandas as pd

import loco
from loco.studies import captions as figure_captions
from loco.studies.optimisation import ParetoResult, nsga2, pick_spread, plot_pareto, verify_points
from loco.studies.parameter_study import (
    LOG_TARGET,
    OBJECTIVES,
    StudySetup,
    axis_label,
    fit_surrogates,
    labels,
    surrogate_objectives,
)
from loco.studies.parameters import names
from loco.studies.plotting import pyplot, save_figure
from loco.studies.report import StudyRecord, save_json, save_table
from loco.studies.sensitivity import (
    indices_note,
    plot_convergence,
    plot_indices,
    sobol_convergence,
    sobol_direct,
)
from loco.studies.stages import Demand, Runtime, Stage
from loco.studies.surrogate import Predictor
from loco.studies.surrogate_validation import Training, surrogate_label

__all__ = ["OptimisationStage", "SensitivityStage", "run_optimisation", "run_sensitivity"]

FloatArray = npt.NDArray[np.float64]


def run_sensitivity(
    setup: StudySetup,
    x_lhs: FloatArray,
    y_lhs: FloatArray,
    out_dir: Path,
    *,
    convergence_bases: Sequence[int],
    surrogate_base: int = 4096,
    seed: int = 0,
    log_target: bool = LOG_TARGET,
    models: Sequence[Predictor] | None = None,
    surrogate_name: str = "SPEC RBF network",
    runtime: Runtime | None = None,
) -> StudyRecord:
    """Sobol' indices of both objectives, direct (simulator) and on the surrogates.

    Parameters
    ----------
    setup : StudySetup
        Where the simulator runs.
    x_lhs, y_lhs : arrays (n, 6), (n, 2)
        Latin hypercube samples (SI) and objectives (NaN for failed runs) the surrogates learn.
    out_dir : Path
        Output directory.
    convergence_bases : sequence of int
        Saltelli base sample counts N (powers of 2); the largest is simulated, N·(6 + 2) runs per
        scenario, and the smaller are its prefixes (convergence plot).
    surrogate_base : int
        Saltelli base samples on the surrogates (cheap).
    seed : int
        Seed of the Saltelli designs, the bootstrap intervals and the networks' K-means.
    log_target : bool
        The surrogates learn log(objective) (:data:`loco.studies.parameter_study.LOG_TARGET`).
    models : sequence of Predictor, optional
        The surrogates fitted on ``(x_lhs, y_lhs)`` with ``log_target``, one per objective: the
        ones :func:`~loco.studies.surrogate_validation.select_surrogates` chose
        (``selection.model``)
        or the SPEC networks of :func:`~loco.studies.parameter_study.fit_surrogates` (the
        default, fitted here).
    surrogate_name : str
        Which surrogates ``models`` are, for the figures and settings (e.g. ``W_y: gp, A_yb:
        gp``).
    runtime : Runtime, optional
        Threads and progress bars of the simulations (default all cores, bars shown).

    Writes ``sobol_<label>.png`` (S1 and ST, direct and surrogate side by side),
    ``sobol_convergence.png``, ``sobol_summary.csv`` (one row per parameter), ``sobol_indices.csv``
    (with confidence half-widths), ``sobol_convergence.csv``,
    ``saltelli_samples.csv`` (the simulated design and its outputs) and ``sensitivity.json``.
    """
    runtime = runtime or Runtime()
    convergence = sobol_convergence(
        setup.evaluator(runtime),
        labels(),
        n_bases=convergence_bases,
        seed=seed,
        progress=runtime.progress,
        keep_design=True,
    )
    n_direct = max(convergence_bases)
    direct = convergence.indices
    if models is None:
        models = fit_surrogates(x_lhs, y_lhs, log_target=log_target, seed=seed)
    surrogate = sobol_direct(
        surrogate_objectives(models, log_target=log_target),
        labels(),
        n_base=surrogate_base,
        seed=seed,
    )
    direct_label = f"direct, Saltelli N={n_direct} ({n_direct * (len(names()) + 2)} runs)"
    surrogate_label = f"surrogate ({surrogate_name}) of {len(x_lhs)} LHS runs"
    figures = []
    for d, s in zip(direct, surrogate, strict=True):
        path = out_dir / f"sobol_{d.metric}.png"
        plot_indices(
            [(direct_label, d), (surrogate_label, s)], path, title=f"Sobol' indices of {d.metric}"
        )
        figures.append(path)
    plot_convergence(
        convergence.frame,
        out_dir / "sobol_convergence.png",
        title="Direct Sobol' indices against Saltelli base samples",
    )
    figures.append(out_dir / "sobol_convergence.png")
    indices = pd.concat(
        [ind.to_frame().assign(method="direct") for ind in direct]
        + [ind.to_frame().assign(method="surrogate") for ind in surrogate],
        ignore_index=True,
    )
    summary = indices.pivot_table(
        index="parameter", columns=["metric", "index", "method"], values="value", sort=False
    )
    summary.columns = [" ".join(c) for c in summary.columns]
    design = pd.DataFrame(convergence.x, columns=names())
    for j, label in enumerate(labels()):
        design[label] = convergence.y[:, j]
    dropped = {d.metric: d.n_dropped for d in direct}
    settings = {
        "loco_version": loco.__version__,
        "saltelli_base": n_direct,
        "convergence_bases": sorted(set(convergence_bases)),
        "surrogate_base": surrogate_base,
        "lhs_samples": len(x_lhs),
        "seed": seed,
        "log_target": log_target,
        "surrogate": surrogate_name,
        **setup.settings(),
    }
    notes = (
        "Total-order (ST) and first-order (S1) indices with their 95 % bootstrap half-widths. "
        + indices_note(direct, "Direct")
        + " "
        + indices_note(surrogate, f"On the surrogate ({surrogate_name})")
        + f" Saltelli base samples dropped for failed runs: {dropped}."
    )
    return StudyRecord(
        name=out_dir.name,
        title="Global sensitivity: Sobol' indices, direct and on the surrogate (SPEC §6.2)",
        figures=figures,
        tables=[
            save_table(summary.reset_index(), out_dir / "sobol_summary.csv"),
            save_table(indices, out_dir / "sobol_indices.csv"),
            save_table(convergence.frame, out_dir / "sobol_convergence.csv"),
            save_table(design, out_dir / "saltelli_samples.csv"),
            save_json(settings, out_dir / "sensitivity.json"),
        ],
        parameters=settings,
        notes=notes,
        captions=figure_captions.sobol_captions(d.metric for d in direct),
    )


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
class _OnSurrogates(Stage):
    """A stage on the surrogates of ``training`` that also simulates on ``setup``; ``seed``
    seeds its designs and the networks."""

    setup: StudySetup
    training: Training
    seed: int

    def _study(
        self, study: Callable[..., StudyRecord], out_dir: Path, runtime: Runtime, **sizes: Any
    ) -> StudyRecord:
        x, y, chosen = self.training.fitted()
        return study(
            self.setup,
            x,
            y,
            out_dir,
            seed=self.seed,
            log_target=self.training.log_target,
            models=[c.model for c in chosen],
            surrogate_name=surrogate_label(chosen),
            runtime=runtime,
            **sizes,
        )


@dataclass(frozen=True)
class SensitivityStage(_OnSurrogates):
    """The stage ``sensitivity`` of ``loco reproduce``: :func:`run_sensitivity` on ``setup``
    with the surrogates of ``training``."""

    name: ClassVar[str] = "sensitivity"
    convergence_bases: tuple[int, ...]
    surrogate_base: int

    def demand(self) -> Demand:
        """Both objectives on the largest Saltelli design, N·(6 + 2) points."""
        return self.setup.demand(max(self.convergence_bases) * (len(names()) + 2))

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """:func:`run_sensitivity` into ``out_dir``."""
        return self._study(
            run_sensitivity,
            out_dir,
            runtime,
            convergence_bases=self.convergence_bases,
            surrogate_base=self.surrogate_base,
        )


@dataclass(frozen=True)
class OptimisationStage(_OnSurrogates):
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
