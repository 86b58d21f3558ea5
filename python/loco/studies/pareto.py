"""Multi-objective optimisation of the study parameters with NSGA-II (pymoo), on surrogates.

SPEC §6.4: minimise W_y (S_low) and A_yb (S_high) over the six parameters with NSGA-II (Deb et
al. 2002), population 500, 100 generations, on the RBF surrogates; then re-simulate a spread of
Pareto points with the real model and report the surrogate's error there.

The objective is any :class:`~loco.studies.evaluators.Evaluator` returning one column per
objective (all minimised), so the same code runs on surrogates, on the simulator and on test
problems with a known front.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
import pandas as pd
from tqdm.auto import tqdm

from loco.studies.evaluators import Evaluator, evaluate_checked
from loco.studies.parameters import STUDY_PARAMETERS, StudyParameter, bounds_si, names
from loco.studies.parameters import to_study_units as _to_units
from loco.studies.plotting import pyplot, save_figure

__all__ = [
    "ParetoResult",
    "nsga2",
    "pick_spread",
    "plot_pareto",
    "verify_points",
]

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class ParetoResult:
    """The non-dominated set NSGA-II ended with, sorted by the first objective.

    ``x`` (p, k): Pareto set in SI; ``f`` (p, m): the objectives there. ``seconds``: run time.
    """

    parameters: tuple[StudyParameter, ...]
    objectives: tuple[str, ...]
    x: FloatArray
    f: FloatArray
    pop_size: int
    n_gen: int
    seed: int
    seconds: float

    @property
    def x_units(self) -> FloatArray:
        """Pareto set in the study's units (kN/mm, kN·s/m)."""
        return _to_units(self.x, self.parameters)

    def to_frame(self) -> pd.DataFrame:
        """One row per Pareto point: objectives, parameters in SI (``name``) and in the study's
        units (``name [unit]``)."""
        frame = pd.DataFrame(self.f, columns=list(self.objectives))
        for j, p in enumerate(self.parameters):
            frame[p.name] = self.x[:, j]
        for j, p in enumerate(self.parameters):
            frame[f"{p.name} [{p.unit}]"] = self.x_units[:, j]
        return frame


def nsga2(
    evaluate: Evaluator,
    objectives: Sequence[str],
    parameters: Sequence[StudyParameter] = STUDY_PARAMETERS,
    *,
    pop_size: int = 500,
    n_gen: int = 100,
    seed: int = 0,
    progress: bool = True,
) -> ParetoResult:
    """Minimise every column of ``evaluate`` over the parameters' box with NSGA-II.

    pymoo's defaults: binary tournament, SBX crossover, polynomial mutation, duplicates
    eliminated. The run is deterministic for a given ``seed`` (pymoo seeds its own generator
    from it). A point with a NaN objective (failed sample) is made infeasible through one
    inequality constraint (g = 1 failed, −1 ok): Deb's constraint domination ranks it behind every
    feasible point, and it never enters the returned set. A progress bar counts generations.
    """
    from pymoo.algorithms.moo.nsga2 import NSGA2
    from pymoo.core.callback import Callback
    from pymoo.core.problem import Problem
    from pymoo.optimize import minimize

    column_names = names(parameters)
    n_obj = len(objectives)
    bounds = bounds_si(parameters)

    class _Problem(Problem):
        def __init__(self) -> None:
            super().__init__(
                n_var=len(parameters),
                n_obj=n_obj,
                n_ieq_constr=1,
                xl=bounds[:, 0],
                xu=bounds[:, 1],
            )

        def _evaluate(self, x: FloatArray, out: dict[str, Any], *args: Any, **kw: Any) -> None:
            f = evaluate_checked(evaluate, x, column_names, n_obj)
            failed = np.asarray(~np.isfinite(f).all(axis=1), dtype=bool)
            out["F"] = np.where(failed[:, None], 0.0, f)
            out["G"] = np.where(failed, 1.0, -1.0)[:, None]

    bar = tqdm(total=n_gen, desc="NSGA-II generations", disable=not progress)

    class _Progress(Callback):
        def notify(self, algorithm: Any) -> None:
            bar.update(1)

    start = time.perf_counter()
    try:
        res = minimize(
            _Problem(),
            NSGA2(pop_size=pop_size),
            ("n_gen", n_gen),
            seed=seed,
            callback=_Progress(),
            verbose=False,
        )
    finally:
        bar.close()
    if res.X is None:
        raise RuntimeError("nsga2: every evaluated point failed (NaN objectives)")
    x = np.atleast_2d(np.asarray(res.X, dtype=np.float64))
    f = np.atleast_2d(np.asarray(res.F, dtype=np.float64))
    order = np.argsort(f[:, 0], kind="stable")
    return ParetoResult(
        parameters=tuple(parameters),
        objectives=tuple(objectives),
        x=x[order],
        f=f[order],
        pop_size=pop_size,
        n_gen=n_gen,
        seed=seed,
        seconds=time.perf_counter() - start,
    )


def pick_spread(result: ParetoResult, k: int) -> npt.NDArray[np.intp]:
    """Indices of ``k`` Pareto points evenly spaced along the front.

    The front (sorted by the first objective) is parametrised by its cumulative arc length in
    objectives scaled to [0, 1]; the point nearest each of ``k`` equally spaced arc lengths
    (ends included) is taken. Fewer than ``k`` indices come back when the front is shorter.
    """
    f = result.f
    span = np.ptp(f, axis=0)
    z = (f - f.min(axis=0)) / np.where(span > 0, span, 1.0)
    arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(z, axis=0), axis=1))])
    targets = np.linspace(0.0, arc[-1], k)
    picked = np.abs(arc[None, :] - targets[:, None]).argmin(axis=1)
    return np.unique(picked)


def verify_points(
    result: ParetoResult, indices: npt.ArrayLike, evaluate: Evaluator
) -> pd.DataFrame:
    """Re-evaluate chosen Pareto points (e.g. with the simulator) and compare with the
    optimiser's (surrogate) objectives.

    Returns one row per point: the parameters in the study's units, and per objective ``o``:
    ``o_surrogate``, ``o_simulated``, ``o_error`` (surrogate − simulated) and ``o_rel_error``
    (error / |simulated|). A failed simulation gives NaN.
    """
    idx = np.asarray(indices, dtype=np.intp)
    x = result.x[idx]
    simulated = evaluate_checked(evaluate, x, names(result.parameters), len(result.objectives))
    frame = pd.DataFrame({"pareto_index": idx})
    for j, p in enumerate(result.parameters):
        frame[f"{p.name} [{p.unit}]"] = result.x_units[idx, j]
    for j, o in enumerate(result.objectives):
        frame[f"{o}_surrogate"] = result.f[idx, j]
        frame[f"{o}_simulated"] = simulated[:, j]
        frame[f"{o}_error"] = result.f[idx, j] - simulated[:, j]
        frame[f"{o}_rel_error"] = frame[f"{o}_error"] / np.abs(simulated[:, j])
    return frame


def plot_pareto(result: ParetoResult, path: str | Path, *, title: str = "", bins: int = 20) -> None:
    """Save the front (first two objectives) and one histogram per parameter along it, over the
    parameter's full range in the study's units, as PNG."""
    k = len(result.parameters)
    ncols = 3
    nrows = int(np.ceil(k / ncols))
    fig = pyplot().figure(figsize=(4.2 + 2.6 * ncols, max(3.2, 2.2 * nrows)), layout="constrained")
    grid = fig.add_gridspec(nrows, ncols + 2)
    front = fig.add_subplot(grid[:, :2])
    front.scatter(result.f[:, 0], result.f[:, 1], s=8, c=result.f[:, 0], cmap="viridis")
    front.set(xlabel=f"{result.objectives[0]} (minimise)", ylabel=f"{result.objectives[1]} "
              "(minimise)", title=f"Pareto front, {len(result.f)} points")  # fmt: skip
    xu = result.x_units
    for j, p in enumerate(result.parameters):
        ax = fig.add_subplot(grid[j // ncols, 2 + j % ncols])
        ax.hist(xu[:, j], bins=np.linspace(p.low, p.high, bins + 1).tolist(), color="tab:blue")
        ax.set_xlim(p.low, p.high)
        ax.set_xlabel(f"{p.name} ({p.unit})", fontsize=8)
        ax.tick_params(labelsize=7)
    if title:
        fig.suptitle(title)
    save_figure(fig, path)
