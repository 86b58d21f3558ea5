"""Gaussian-process variants for the parameter study's surrogate, on the samples a
``loco reproduce`` run trained it on, by the held-out protocol of the surrogate stage.

The stage's GP (:class:`loco.studies.surrogate_reference.GaussianProcessSurrogate`: constant times
an ARD squared-exponential kernel plus white noise, inputs scaled to the box, log target) is
compared with variants of its kernel (ARD Matérn 5/2 and 3/2), its inputs (log scale), its target
transform (log, square root, none) and its optimiser (restarts), each on the same 5 folds
(scikit-learn ``KFold`` shuffled with seed 0, the folds of
:func:`loco.studies.surrogate_selection.select_surrogate`), R² scored on the objective itself.
Only the folds' training samples are fitted; the held-out ones are predicted.

Usage: ``python experiments/surrogate_candidates.py results/reproduce [variant ...]`` (the directory
holds ``monte_carlo/monte_carlo.csv`` and ``surrogate_samples/surrogate_samples.csv``; a variant
is a ``+``-joined name such as ``matern52+sqrt+restarts``, see :func:`variant`). Prints one line
per objective and variant: mean and worst-fold R², and each fold.
"""

from __future__ import annotations

import sys
import time
import warnings
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd
from sklearn.gaussian_process import GaussianProcessRegressor
from sklearn.gaussian_process.kernels import RBF, ConstantKernel, Matern, WhiteKernel
from sklearn.model_selection import KFold
from threadpoolctl import threadpool_limits

from loco.studies.parameter_study import OBJECTIVES
from loco.studies.parameters import bounds_si, names
from loco.studies.rbf_network import r2_score

#: The variants run when none is named: the stage's GP first.
DEFAULT_VARIANTS = (
    "se",
    "matern52",
    "se+log_inputs",
    "matern52+log_inputs",
    "se+raw",
    "matern52+raw",
    "se+sqrt",
    "matern52+sqrt",
    "se+restarts",
    "matern52+sqrt+restarts",
    "matern32+sqrt",
)

Transform = Callable[[np.ndarray], np.ndarray]
#: Target transforms (forward, back) of the fitted quantity.
TRANSFORMS: dict[str, tuple[Transform, Transform]] = {
    "log": (np.log, np.exp),
    "sqrt": (np.sqrt, np.square),
    "raw": (lambda v: v, lambda v: v),
}


def variant(name: str) -> Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray]:
    """``fit_predict(x_train, y_train, x_test)`` (SI inputs, objective values) of a variant:
    kernel ``se`` / ``matern52`` / ``matern32``, then any of ``log_inputs`` (inputs scaled on a
    log scale), ``raw`` or ``sqrt`` (target transform; log otherwise), ``restarts`` (5 restarts of
    the marginal-likelihood optimiser)."""
    parts = name.split("+")
    bounds = bounds_si()
    lo, hi = bounds[:, 0], bounds[:, 1]
    log_inputs = "log_inputs" in parts
    transform = next((t for t in ("raw", "sqrt") if t in parts), "log")
    forward, back = TRANSFORMS[transform]
    restarts = 5 if "restarts" in parts else 0

    def scale(x: np.ndarray) -> np.ndarray:
        if log_inputs:
            return (np.log(x) - np.log(lo)) / (np.log(hi) - np.log(lo))
        return (x - lo) / (hi - lo)

    def fit_predict(x: np.ndarray, y: np.ndarray, x_test: np.ndarray) -> np.ndarray:
        length = np.full(x.shape[1], 0.5)
        if parts[0] == "se":
            shape = RBF(length, (1e-2, 1e3))
        else:
            shape = Matern(length, (1e-2, 1e3), nu={"matern52": 2.5, "matern32": 1.5}[parts[0]])
        kernel = ConstantKernel(1.0) * shape + WhiteKernel(1e-2, (1e-8, 1e1))
        gp = GaussianProcessRegressor(
            kernel, normalize_y=True, random_state=0, n_restarts_optimizer=restarts
        )
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # length scales at their bound: expected
            gp.fit(scale(x), forward(y))
        return np.asarray(back(gp.predict(scale(x_test))), dtype=np.float64)

    return fit_predict


def main() -> None:
    run = Path(sys.argv[1])
    variants = sys.argv[2:] or list(DEFAULT_VARIANTS)
    frame = pd.concat(
        [
            pd.read_csv(run / "monte_carlo" / "monte_carlo.csv"),
            pd.read_csv(run / "surrogate_samples" / "surrogate_samples.csv"),
        ],
        ignore_index=True,
    )
    x_all = frame[names()].to_numpy(np.float64)
    with threadpool_limits(limits=1):
        for objective in OBJECTIVES:
            y_all = frame[objective.label].to_numpy(np.float64)
            ok = np.isfinite(y_all)
            x, y = x_all[ok], y_all[ok]
            splits = list(KFold(n_splits=5, shuffle=True, random_state=0).split(x))
            for name in variants:
                start = time.perf_counter()
                fit_predict = variant(name)
                r2 = np.array(
                    [
                        float(r2_score(y[test], fit_predict(x[train], y[train], x[test]))[0])
                        for train, test in splits
                    ]
                )
                print(
                    f"{objective.label:5s} {name:26s} mean {r2.mean():.3f} worst {r2.min():.3f} "
                    f"folds {np.round(r2, 3)} ({time.perf_counter() - start:.0f} s, n = {len(y)})",
                    flush=True,
                )


if __name__ == "__main__":
    main()
