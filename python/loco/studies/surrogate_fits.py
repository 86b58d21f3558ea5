"""The fits of the surrogate selection as independent tasks, the largest first, on a process pool.

Choosing the surrogate of one objective (:mod:`loco.studies.surrogate_selection`) fits every
candidate on each of the k outer folds, on every sample, and, for the nested cross-validation, on
each of the k inner folds of every outer training set: 6 (k + 1 + k²) = 186 fits for six
candidates and five folds, nearly all of the time in the Gaussian processes' marginal-likelihood
optimisation. One objective per process left a core idle while the other objective's last fits
ran; here every fit is one task (objective × candidate × fold), handed out largest first
(longest-processing-time order), so both cores stay busy until the last small fits.

Every fit depends only on its samples, candidate and seed, and runs with BLAS and OpenMP on one
thread, so the result does not depend on the number of processes or on the order the tasks ran
in: the scores are assembled exactly as a serial loop computes them.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import dataclasses
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt
from joblib import Parallel, delayed
from sklearn.model_selection import KFold
from threadpoolctl import threadpool_limits

from loco.studies.rbf_network import RBFNetwork, r2_score
from loco.studies.surrogate_selection import (
    SPEC_MODEL,
    CandidateScore,
    NestedScore,
    Regressor,
    Selection,
    best_candidate,
    describe,
    make_model,
)

__all__ = ["Objective", "fit_tasks", "nested_only", "select_objectives"]

FloatArray = npt.NDArray[np.float64]
Index = npt.NDArray[np.intp]
Split = tuple[Index, Index]

#: Relative cost of one fit per (sample count)³, measured on the study's samples: the ARD
#: Matérn kernels take most optimiser steps, the RBF networks only K-means and a few SVDs.
_COST: dict[str, float] = {
    "gp_matern": 4.0,
    "gp_matern_sqrt": 4.0,
    "gp": 3.0,
    "gp_sqrt": 3.0,
    "rbf_cv": 1.0,
    "rbf10": 0.1,
}


@dataclass(frozen=True)
class Objective:
    """The finite samples of one objective: inputs ``x`` (n, k) in SI and values ``y`` (n,)."""

    x: FloatArray
    y: FloatArray


@dataclass(frozen=True)
class _Fit:
    """One fit: ``kind`` on ``x[train]`` (all of ``x`` when ``train`` is None); with ``test``
    it returns the back-transformed predictions at ``x[test]``, else the fitted model. ``key``
    says where the result goes: (objective, "full", kind), (objective, "cv", kind, fold) or
    (objective, "inner", outer fold, kind, inner fold)."""

    key: tuple[Any, ...]
    kind: str
    x: FloatArray
    y: FloatArray
    train: Index | None
    test: Index | None

    @property
    def cost(self) -> float:
        n = len(self.x) if self.train is None else len(self.train)
        return _COST.get(self.kind, 4.0) * float(n) ** 3


def folds(x: FloatArray, n_splits: int, seed: int) -> list[Split]:
    """The shuffled k folds of ``x`` every candidate is scored on."""
    return list(KFold(n_splits=n_splits, shuffle=True, random_state=seed).split(x))


def target(y: FloatArray, log_target: bool) -> FloatArray:
    """What the candidates learn: log(objective) with ``log_target``, else the objective."""
    return np.asarray(np.log(y) if log_target else y, dtype=np.float64)


def back(p: npt.ArrayLike, log_target: bool) -> FloatArray:
    """A prediction on the objective's scale."""
    v = np.asarray(p, dtype=np.float64)
    return np.asarray(np.exp(v) if log_target else v, dtype=np.float64)


def fit_tasks(
    objectives: Sequence[Objective],
    candidates: Sequence[str],
    n_splits: int,
    seed: int,
    *,
    full: bool,
    nested: bool,
) -> list[_Fit]:
    """Every fit the selection of ``objectives`` needs, largest first: each candidate on each
    outer fold; with ``full``, on every sample (the SPEC network too); with ``nested``, on each
    inner fold of each outer training set."""
    tasks = []
    for j, o in enumerate(objectives):
        outer = folds(o.x, n_splits, seed)
        for kind in candidates:
            for i, (train, test) in enumerate(outer):
                tasks.append(_Fit((j, "cv", kind, i), kind, o.x, o.y, train, test))
        if full:
            for kind in dict.fromkeys([*candidates, SPEC_MODEL]):
                tasks.append(_Fit((j, "full", kind), kind, o.x, o.y, None, None))
        if nested:
            for i, (train, _) in enumerate(outer):
                x, y = o.x[train], o.y[train]
                for kind in candidates:
                    for m, (tr, te) in enumerate(folds(x, n_splits, seed)):
                        tasks.append(_Fit((j, "inner", i, kind, m), kind, x, y, tr, te))
    return sorted(tasks, key=lambda t: -t.cost)


_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3


def _keep_freed_memory() -> None:
    """Let glibc's malloc reuse the freed n × n × p kernel gradients instead of returning them
    to the system: a Gaussian-process fit allocates a few of them per likelihood evaluation, and
    mapping them afresh (page faults and zeroing) cost about 10 % of the fit. Arithmetic is
    unchanged; outside glibc nothing is done."""
    name = ctypes.util.find_library("c")
    try:
        libc = ctypes.CDLL(name)
        libc.mallopt(_M_MMAP_THRESHOLD, 32 << 20)
        libc.mallopt(_M_TRIM_THRESHOLD, 512 << 20)
    except (OSError, AttributeError, TypeError):
        pass


def _run(task: _Fit, bounds: FloatArray, seed: int, log_target: bool, worker: bool) -> Any:
    if worker:
        _keep_freed_memory()
    with threadpool_limits(limits=1):
        x = task.x if task.train is None else task.x[task.train]
        y = task.y if task.train is None else task.y[task.train]
        model = make_model(task.kind, bounds, seed=seed, log_target=log_target)
        model.fit(x, target(y, log_target))
        if task.test is None:
            return model
        return back(model.predict(task.x[task.test]), log_target)


def _scores(
    y: FloatArray,
    splits: Sequence[Split],
    candidates: Sequence[str],
    predicted: dict[tuple[Any, ...], FloatArray],
    prefix: tuple[Any, ...],
) -> dict[str, CandidateScore]:
    """Held-out predictions and R² per fold of each candidate, as a serial loop computes them."""
    scores = {}
    for kind in candidates:
        predictions = np.empty(len(y))
        r2 = np.empty(len(splits))
        for i, (_, test) in enumerate(splits):
            predictions[test] = predicted[(*prefix, kind, i)]
            r2[i] = float(r2_score(y[test], predictions[test])[0])
        scores[kind] = CandidateScore(kind, r2, predictions, {})
    return scores


def _evaluate(
    objectives: Sequence[Objective],
    bounds: npt.ArrayLike,
    settings: _Settings,
    *,
    full: bool,
    nested: bool,
    n_jobs: int,
) -> list[tuple[dict[str, CandidateScore], dict[str, Regressor], NestedScore | None]]:
    n_splits, seed, candidates = settings.n_splits, settings.seed, settings.candidates
    b = np.asarray(bounds, dtype=np.float64)
    tasks = fit_tasks(objectives, candidates, n_splits, seed, full=full, nested=nested)
    if n_jobs <= 1:
        results = [_run(t, b, seed, settings.log_target, False) for t in tasks]
    else:
        run = delayed(_run)
        results = Parallel(n_jobs=n_jobs, backend="loky", batch_size=1)(
            run(t, b, seed, settings.log_target, True) for t in tasks
        )
    done = {t.key: r for t, r in zip(tasks, results, strict=True)}
    out = []
    for j, o in enumerate(objectives):
        outer = folds(o.x, n_splits, seed)
        scores = _scores(o.y, outer, candidates, done, (j, "cv"))
        fitted = {k: done[(j, "full", k)] for k in (*candidates, SPEC_MODEL)} if full else {}
        if full:
            scores = {k: dataclasses.replace(v, hyperparameters=describe(fitted[k]))
                      for k, v in scores.items()}  # fmt: skip
        inner = None
        if nested:
            chosen, r2 = [], np.empty(len(outer))
            for i, (train, test) in enumerate(outer):
                inner_splits = folds(o.x[train], n_splits, seed)
                best = best_candidate(
                    _scores(o.y[train], inner_splits, candidates, done, (j, "inner", i))
                )
                # The chosen candidate fitted on this outer training set is the outer fold's
                # model: its held-out predictions are those of the outer cross-validation.
                r2[i] = float(r2_score(o.y[test], scores[best].predictions[test])[0])
                chosen.append(best)
            inner = NestedScore(tuple(chosen), r2)
        out.append((scores, fitted, inner))
    return out


@dataclass(frozen=True)
class _Settings:
    n_splits: int
    seed: int
    log_target: bool
    candidates: tuple[str, ...]


def select_objectives(
    objectives: Sequence[Objective],
    bounds: npt.ArrayLike,
    *,
    n_splits: int = 5,
    seed: int = 0,
    log_target: bool = True,
    candidates: Sequence[str],
    nested: bool = False,
    n_jobs: int = 1,
) -> list[Selection]:
    """For each objective: every candidate scored on the same ``n_splits`` folds, the best
    chosen, every candidate (and the SPEC network) fitted on every sample, and with ``nested``
    the nested cross-validation of the choice. The fits run in ``n_jobs`` processes (joblib's
    loky; 1: here, one after the other)."""
    settings = _Settings(n_splits, seed, log_target, tuple(candidates))
    out = []
    for scores, fitted, inner in _evaluate(
        objectives, bounds, settings, full=True, nested=nested, n_jobs=n_jobs
    ):
        chosen = best_candidate(scores)
        spec = fitted[SPEC_MODEL]
        assert isinstance(spec, RBFNetwork)
        models = {k: fitted[k] for k in candidates}
        out.append(Selection(scores=scores, chosen=chosen, model=fitted[chosen], spec_model=spec,
                             models=models, nested=inner))  # fmt: skip
    return out


def nested_only(
    objective: Objective,
    bounds: npt.ArrayLike,
    *,
    n_splits: int,
    seed: int,
    log_target: bool,
    candidates: Sequence[str],
) -> NestedScore:
    """The nested cross-validation of the choice alone (no fit on every sample), here."""
    settings = _Settings(n_splits, seed, log_target, tuple(candidates))
    ((_, _, inner),) = _evaluate([objective], bounds, settings, full=False, nested=True, n_jobs=1)
    assert inner is not None
    return inner
