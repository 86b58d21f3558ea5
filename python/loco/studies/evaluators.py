"""What a study evaluates: a callable from parameter sets to metrics.

Every study of :mod:`loco.studies` takes an :class:`Evaluator`:
``evaluate(params, names) -> metrics`` where ``params`` is an (n, k) array in SI whose columns
are the parameters ``names`` and ``metrics`` is an (n, m) array, one column per metric the study
asked for, NaN where a sample failed. The simulator is one evaluator
(:func:`simulator_evaluator`); a fitted surrogate is another
(:func:`loco.studies.rbf_network.surrogate_evaluator`); an analytic test function is a third.
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence
from typing import Any, Protocol

import numpy as np
import numpy.typing as npt

from loco.batch import run_batch

__all__ = [
    "Evaluator",
    "evaluate_checked",
    "simulator_evaluator",
    "stack_evaluators",
]

FloatArray = npt.NDArray[np.float64]


class Evaluator(Protocol):
    """``(params (n, k) in SI, parameter names) -> metrics (n, m)``, NaN for failed samples."""

    def __call__(self, params: FloatArray, names: Sequence[str], /) -> FloatArray: ...


def evaluate_checked(
    evaluate: Evaluator, params: FloatArray, names: Sequence[str], n_metrics: int
) -> FloatArray:
    """Call ``evaluate`` and check its answer is an (n, ``n_metrics``) float array.

    A 1-D answer is accepted for ``n_metrics == 1``. Raises :class:`ValueError` otherwise.
    """
    x = np.ascontiguousarray(params, dtype=np.float64)
    y = np.asarray(evaluate(x, list(names)), dtype=np.float64)
    if y.ndim == 1 and n_metrics == 1:
        y = y[:, None]
    if y.shape != (x.shape[0], n_metrics):
        raise ValueError(
            f"evaluator returned shape {y.shape}, expected ({x.shape[0]}, {n_metrics})"
        )
    return y


def simulator_evaluator(
    scenario: Any,
    metrics: str | Sequence[str],
    *,
    vehicle: Any = None,
    threads: int | None = None,
    seed: int = 0,
    progress: bool = True,
    executor: Any = None,
    store: Any = None,
) -> Evaluator:
    """An evaluator that runs the locomotive model through ``loco.run_batch``.

    Parameters
    ----------
    scenario : object
        Passed unchanged to ``loco.run_batch(scenario=...)``: the track case (S_low, S_high, ...)
        at its speed and length.
    metrics : str or sequence of str
        Names of the metric columns to return, in this order (``result.metric_names``), e.g.
        ``"wy_max"`` (Sperling W_y) for S_low or ``"ayb_peak_lp"`` (A_yb, m/s²) for S_high; an
        unknown name raises :class:`loco.ParameterError` listing the available ones.
    vehicle, threads, seed, progress
        Passed unchanged to ``loco.run_batch``. With the same ``seed`` the batch is
        bit-identical for any thread count, so a study is reproducible.
    executor, store
        Passed unchanged to ``loco.run_batch``: where the samples run (local threads, a Dask
        cluster: :mod:`loco.executors`) and where finished samples are kept (:mod:`loco.store`).
        None takes those of an enclosing ``loco.campaign.using`` block (how ``loco reproduce``
        sets them for every study), else local threads and nothing kept. NSGA-II on this
        evaluator submits each generation's population through the executor.

    Returns
    -------
    Evaluator
        ``evaluate(params, names)`` returning the (n, len(metrics)) metrics; failed samples
        (``status != 0``) are NaN and counted in a :class:`RuntimeWarning` with the first
        failure messages.
    """
    wanted = [metrics] if isinstance(metrics, str) else list(metrics)

    def evaluate(params: FloatArray, names: Sequence[str]) -> FloatArray:
        result = run_batch(
            params,
            list(names),
            vehicle=vehicle,
            scenario=scenario,
            threads=threads,
            seed=seed,
            progress=progress,
            executor=executor,
            store=store,
        )
        out = np.column_stack([result.metric(m) for m in wanted]).astype(np.float64)
        failed = np.asarray(result.status) != 0
        out[failed] = np.nan
        if failed.any():
            messages = [str(m) for m in result.messages if m][:3]
            warnings.warn(
                f"{int(failed.sum())} of {len(failed)} simulations failed: {messages}",
                RuntimeWarning,
                stacklevel=2,
            )
        return out

    return evaluate


def stack_evaluators(*evaluators: tuple[Evaluator, int]) -> Evaluator:
    """Join evaluators column-wise: ``(evaluator, n_metrics)`` pairs, outputs side by side.

    For instance W_y on S_low and A_yb on S_high as the two objectives of the optimisation::

        both = stack_evaluators(
            (simulator_evaluator(s_low, loco.Metric.WY_MAX), 1),
            (simulator_evaluator(s_high, loco.Metric.AYB_PEAK_LP), 1),
        )
    """
    if not evaluators:
        raise ValueError("stack_evaluators needs at least one evaluator")

    def evaluate(params: FloatArray, names: Sequence[str]) -> FloatArray:
        return np.hstack([evaluate_checked(ev, params, names, m) for ev, m in evaluators])

    return evaluate
