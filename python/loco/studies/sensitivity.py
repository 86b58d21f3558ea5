"""The stage ``sensitivity`` of ``loco reproduce`` (SPEC §6.2): Sobol' first- and total-order
indices of W_y (S_low) and A_yb (S_high), computed directly on the simulator from a Saltelli
design and on the surrogates trained from the Latin hypercube Monte Carlo
(:mod:`loco.studies.parameter_study`), side by side, and their convergence with the number of
Saltelli base samples. The indices, their intervals and figures are :mod:`loco.studies.sobol`'s.
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
    StudySetup,
    fit_surrogates,
    labels,
    surrogate_objectives,
)
from loco.studies.parameters import names
from loco.studies.rbf_network import Predictor
from loco.studies.report import StudyRecord, save_json, save_table
from loco.studies.sobol import (
    indices_note,
    plot_convergence,
    plot_indices,
    sobol_convergence,
    sobol_direct,
)
from loco.studies.stages import Demand, Runtime
from loco.studies.surrogate import OnSurrogates

__all__ = ["SensitivityStage", "run_sensitivity"]

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
        ones :func:`~loco.studies.surrogate.select_surrogates` chose
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


@dataclass(frozen=True)
class SensitivityStage(OnSurrogates):
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
