"""Sobol' global sensitivity indices (first and total order, with confidence intervals).

Computed by ``SALib.analyze.sobol`` (Saltelli 2002; Saltelli et al. 2010 estimators, bootstrap
confidence intervals) on Saltelli's design (:func:`loco.studies.sampling.saltelli`), evaluated by
any :class:`~loco.studies.evaluators.Evaluator`: the simulator (direct indices) or a surrogate
(:func:`sobol_on_surrogate`), through the same code.

Failed samples
--------------
The estimators pair, for each base sample j, the outputs of A_j, the D rows AB_j^(i) and B_j:
a block of D + 2 rows (2D + 2 with second order). A NaN anywhere in a block makes that base
sample unusable, so **every block containing a NaN is dropped whole** and the indices are
estimated from the remaining complete blocks (reported as ``n_dropped``). This is unbiased only
when failures are unrelated to the parameters; when many blocks fail, failures concentrate in a
corner of the box and the indices describe the rest of it, which the report must say.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Literal, overload

import numpy as np
import numpy.typing as npt
import pandas as pd
from SALib.analyze import sobol as _salib_sobol
from tqdm.auto import tqdm

from loco.studies.evaluators import Evaluator, evaluate_checked
from loco.studies.parameters import (
    STUDY_PARAMETERS,
    StudyParameter,
    bounds_si,
    names,
    salib_problem,
)
from loco.studies.plotting import pyplot, save_figure
from loco.studies.rbf_network import RBFNetwork, fit_per_output, surrogate_evaluator
from loco.studies.sampling import saltelli, saltelli_block_size

__all__ = [
    "SobolConvergence",
    "SobolIndices",
    "analyse_saltelli",
    "indices_note",
    "plot_convergence",
    "plot_indices",
    "sobol_convergence",
    "sobol_direct",
    "sobol_on_surrogate",
]

FloatArray = npt.NDArray[np.float64]

#: Mean half-width of the 95 % intervals of an output's indices above which the report says the
#: base sample is small for them (an index known to ±0.1 cannot order parameters whose indices
#: differ by less).
WIDE_INTERVAL = 0.1


@dataclass(frozen=True)
class SobolIndices:
    """First- and total-order Sobol' indices of one output.

    ``S1``, ``ST`` and their half-width confidence intervals ``S1_conf``, ``ST_conf`` (95 %,
    bootstrap) are (k,) arrays in the order of ``parameters``. ``n_base`` base samples were
    used of which ``n_dropped`` were dropped for NaN; ``n_evaluations`` model runs in all.
    """

    metric: str
    parameters: tuple[str, ...]
    S1: FloatArray
    S1_conf: FloatArray
    ST: FloatArray
    ST_conf: FloatArray
    n_base: int
    n_dropped: int
    n_evaluations: int

    def to_frame(self) -> pd.DataFrame:
        """Tidy table: one row per (parameter, index) with value and confidence half-width."""
        rows = []
        for order, value, conf in (("S1", self.S1, self.S1_conf), ("ST", self.ST, self.ST_conf)):
            for i, name in enumerate(self.parameters):
                rows.append((self.metric, name, order, value[i], conf[i]))
        frame = pd.DataFrame(rows, columns=["metric", "parameter", "index", "value", "conf"])
        frame["n_base"] = self.n_base - self.n_dropped
        frame["n_evaluations"] = self.n_evaluations
        return frame


def indices_note(indices: Sequence[SobolIndices], method: str) -> str:
    """The report's sentence on ``indices`` (one per output) estimated by ``method``: every
    parameter's ST and S1 with their 95 % half-widths and the base sample N used; then where the
    intervals are wide (mean half-width above :data:`WIDE_INTERVAL`) that N is small for them,
    and that a negative S1 is estimator noise (a first-order index is at least 0)."""

    def pm(value: float, conf: float) -> str:
        return f"{value:.2f} ± {conf:.2f}"

    parts, wide, negative = [], [], []
    for ind in indices:
        n = ind.n_base - ind.n_dropped
        rows = zip(ind.parameters, ind.S1, ind.S1_conf, ind.ST, ind.ST_conf, strict=True)
        values = [f"{p} ST {pm(st, stc)} (S1 {pm(s1, s1c)})" for p, s1, s1c, st, stc in rows]
        parts.append(f"{ind.metric} (N = {n}): " + ", ".join(values))
        half = float(np.nanmean(np.concatenate([ind.S1_conf, ind.ST_conf])))
        if half > WIDE_INTERVAL:
            wide.append(f"±{half:.2f} on {ind.metric} with N = {n}")
        negative += [
            (f"{p} on {ind.metric} {pm(s1, c)}", s1 + c >= 0)
            for p, s1, c in zip(ind.parameters, ind.S1, ind.S1_conf, strict=True)
            if round(float(s1), 2) < 0
        ]
    text = f"{method}: " + "; ".join(parts) + "."
    if wide:
        text += (
            " The base sample is small for these indices (mean half-width of the intervals "
            + ", ".join(wide)
            + "): they are known to about that much, and four times the base sample halves it."
        )
    if negative:
        reach = (
            "each of these intervals reaches 0"
            if all(ok for _, ok in negative)
            else "where an interval stays below 0 the noise is larger than the bootstrap says"
        )
        text += (
            " Negative S1 ("
            + ", ".join(t for t, _ in negative)
            + f") are estimator noise: a first-order index is at least 0, and {reach}."
        )
    return text


def _bootstrap_seed(seed: int) -> int:
    # SALib ignores a seed of 0 (``if seed:``) and would use the global generator.
    return int(np.random.SeedSequence([seed, 1]).generate_state(1)[0]) or 1


def analyse_saltelli(
    y: npt.ArrayLike,
    parameters: Sequence[StudyParameter] = STUDY_PARAMETERS,
    *,
    metric: str = "y",
    calc_second_order: bool = False,
    seed: int = 0,
    num_resamples: int = 200,
) -> SobolIndices:
    """Sobol' indices from the outputs ``y`` of a Saltelli design, dropping blocks with NaN.

    Parameters
    ----------
    y : array (n_base · block,)
        One output per row of :func:`loco.studies.sampling.saltelli`, in its row order.
    parameters : sequence of StudyParameter
        The box the design was drawn on.
    metric : str
        Name of the output (kept in the result).
    calc_second_order : bool
        Must match the design.
    seed : int
        Seed of the bootstrap confidence intervals.
    num_resamples : int
        Bootstrap resamples.
    """
    k = len(parameters)
    block = saltelli_block_size(k, calc_second_order)
    values = np.asarray(y, dtype=np.float64).ravel()
    if values.size % block:
        raise ValueError(f"analyse_saltelli: {values.size} outputs is not a multiple of {block}")
    blocks = values.reshape(-1, block)
    complete = np.isfinite(blocks).all(axis=1)
    n_base, n_ok = len(blocks), int(complete.sum())
    if n_ok < 2:
        raise ValueError(f"analyse_saltelli: {n_ok} complete base samples of {n_base} for {metric}")
    result = _salib_sobol.analyze(
        salib_problem(parameters),
        blocks[complete].ravel(),
        calc_second_order=calc_second_order,
        num_resamples=num_resamples,
        seed=_bootstrap_seed(seed),
    )
    return SobolIndices(
        metric=metric,
        parameters=tuple(names(parameters)),
        S1=np.asarray(result["S1"], dtype=np.float64),
        S1_conf=np.asarray(result["S1_conf"], dtype=np.float64),
        ST=np.asarray(result["ST"], dtype=np.float64),
        ST_conf=np.asarray(result["ST_conf"], dtype=np.float64),
        n_base=n_base,
        n_dropped=n_base - n_ok,
        n_evaluations=values.size,
    )


def sobol_direct(
    evaluate: Evaluator,
    metrics: Sequence[str],
    parameters: Sequence[StudyParameter] = STUDY_PARAMETERS,
    *,
    n_base: int = 256,
    seed: int = 0,
    calc_second_order: bool = False,
) -> list[SobolIndices]:
    """Sobol' indices of every output of ``evaluate`` on a Saltelli design of ``n_base``.

    ``evaluate`` must return one column per name in ``metrics``. The cost is
    ``n_base · (k + 2)`` evaluations (k = number of parameters; 2k + 2 with second order).
    """
    x = saltelli(n_base, parameters, seed, calc_second_order=calc_second_order)
    y = evaluate_checked(evaluate, x, names(parameters), len(metrics))
    return [
        analyse_saltelli(
            y[:, j], parameters, metric=m, calc_second_order=calc_second_order, seed=seed
        )
        for j, m in enumerate(metrics)
    ]


def sobol_on_surrogate(
    x_train: npt.ArrayLike,
    y_train: npt.ArrayLike,
    metrics: Sequence[str],
    parameters: Sequence[StudyParameter] = STUDY_PARAMETERS,
    *,
    n_base: int = 4096,
    seed: int = 0,
    n_centres: int = 10,
) -> tuple[list[SobolIndices], list[RBFNetwork]]:
    """Sobol' indices of RBF surrogates trained on ``(x_train, y_train)`` (e.g. a Latin hypercube).

    One network per output column, each trained on the rows where that output is finite (failed
    samples dropped), inputs scaled to the parameters' box. The surrogate is cheap, so the
    default design (4096 base samples) makes the sampling error small next to the surrogate's.
    Returns the indices and the fitted networks.
    """
    models = fit_per_output(
        x_train, y_train, n_centres=n_centres, bounds=bounds_si(parameters), seed=seed
    )
    evaluate = surrogate_evaluator(models, names(parameters))
    return sobol_direct(evaluate, metrics, parameters, n_base=n_base, seed=seed), models


@dataclass(frozen=True)
class SobolConvergence:
    """What :func:`sobol_convergence` computed with ``keep_design=True``.

    ``frame``: the tidy table of the indices at every N; ``x`` (n, k) the Saltelli design of the
    largest N (SI) and ``y`` (n, m) its outputs (NaN for failed samples); ``indices`` the
    :class:`SobolIndices` of each metric at the largest N (the rows of ``frame`` at that N).
    """

    frame: pd.DataFrame
    x: FloatArray
    y: FloatArray
    indices: list[SobolIndices]


@overload
def sobol_convergence(
    evaluate: Evaluator,
    metrics: Sequence[str],
    parameters: Sequence[StudyParameter] = ...,
    *,
    n_bases: Sequence[int] = ...,
    seed: int = ...,
    progress: bool = ...,
    keep_design: Literal[False] = ...,
) -> pd.DataFrame: ...


@overload
def sobol_convergence(
    evaluate: Evaluator,
    metrics: Sequence[str],
    parameters: Sequence[StudyParameter] = ...,
    *,
    n_bases: Sequence[int] = ...,
    seed: int = ...,
    progress: bool = ...,
    keep_design: Literal[True],
) -> SobolConvergence: ...


def sobol_convergence(
    evaluate: Evaluator,
    metrics: Sequence[str],
    parameters: Sequence[StudyParameter] = STUDY_PARAMETERS,
    *,
    n_bases: Sequence[int] = (16, 32, 64, 128, 256),
    seed: int = 0,
    progress: bool = True,
    keep_design: bool = False,
) -> pd.DataFrame | SobolConvergence:
    """Sobol' indices against the number of base samples, as a tidy DataFrame.

    One design of ``max(n_bases)`` is evaluated once; the indices at each smaller N are computed
    from its first N blocks, which are exactly the design of N (a Sobol' prefix), so the study
    costs ``max(n_bases) · (k + 2)`` evaluations. Columns: metric, parameter, index (S1/ST),
    value, conf, n_base (complete base samples used), n_evaluations.

    With ``keep_design`` the answer is a :class:`SobolConvergence`: the table, the evaluated
    design and outputs, and the indices at the largest N (the direct indices, not analysed
    again).
    """
    sizes = sorted(set(n_bases))
    x = saltelli(sizes[-1], parameters, seed)
    y = evaluate_checked(evaluate, x, names(parameters), len(metrics))
    block = saltelli_block_size(len(parameters))
    frames = []
    indices: list[SobolIndices] = []
    for n in tqdm(sizes, desc="Sobol convergence", disable=not progress):
        indices = [
            analyse_saltelli(y[: n * block, j], parameters, metric=m, seed=seed)
            for j, m in enumerate(metrics)
        ]
        frames += [ind.to_frame() for ind in indices]
    frame = pd.concat(frames, ignore_index=True)
    if keep_design:
        return SobolConvergence(frame=frame, x=x, y=y, indices=indices)
    return frame


def plot_convergence(frame: pd.DataFrame, path: str | Path, *, title: str = "") -> None:
    """Save the indices of :func:`sobol_convergence` against base samples (one panel per metric
    and order, error bars = confidence half-widths) as PNG."""
    metrics = list(dict.fromkeys(frame["metric"]))
    fig, axes = pyplot().subplots(
        len(metrics), 2, figsize=(9, 3.2 * len(metrics)), squeeze=False, layout="constrained"
    )
    for r, metric in enumerate(metrics):
        for c, order in enumerate(("S1", "ST")):
            ax = axes[r, c]
            sub = frame[(frame["metric"] == metric) & (frame["index"] == order)]
            for name, grp in sub.groupby("parameter", sort=False):
                ax.errorbar(grp["n_base"], grp["value"], yerr=grp["conf"], marker="o",
                            ms=3, capsize=2, label=str(name))  # fmt: skip
            ax.set_xscale("log", base=2)
            ax.set(xlabel="base samples N", ylabel=order, title=f"{metric}: {order}")
            ax.axhline(0.0, color="0.7", lw=0.8)
    axes[0, 1].legend(fontsize=7, ncol=2)
    if title:
        fig.suptitle(title)
    save_figure(fig, path)


def plot_indices(
    results: Sequence[tuple[str, SobolIndices]], path: str | Path, *, title: str = ""
) -> None:
    """Save bar charts of S1 and ST with confidence intervals, several estimates side by side
    (``(label, indices)`` pairs, e.g. direct and surrogate) for one metric, as PNG."""
    params = results[0][1].parameters
    width = 0.8 / len(results)
    pos = np.arange(len(params))
    fig, axes = pyplot().subplots(1, 2, figsize=(10, 3.6), layout="constrained")
    for ax, order in zip(axes, ("S1", "ST"), strict=True):
        for i, (label, ind) in enumerate(results):
            value = ind.S1 if order == "S1" else ind.ST
            conf = ind.S1_conf if order == "S1" else ind.ST_conf
            ax.bar(pos + (i - (len(results) - 1) / 2) * width, value, width, yerr=conf,
                   capsize=2, label=label)  # fmt: skip
        ax.set_xticks(pos, params)
        ax.set(ylabel=order, title=f"{results[0][1].metric}: {order}")
        ax.axhline(0.0, color="0.5", lw=0.8)
    axes[1].legend()
    if title:
        fig.suptitle(title)
    save_figure(fig, path)
