"""A reference for the RBF surrogate's accuracy: how well the same samples can be fitted at all.

SPEC §6.3 fixes the surrogate (10 Gaussian units, K-means centres, linear output). When its
held-out R² is low, the question is whether the network is too small or the responses are too
rough for any smooth model of that many samples. A Gaussian process with one length scale per
parameter (automatic relevance determination) and a white-noise term, fitted on the same folds,
answers it: its R² is what a flexible smooth model reaches on these samples, and its noise level
is the share of the response that no smooth function of the six parameters explains.
"""

from __future__ import annotations

import warnings

import numpy as np
import numpy.typing as npt
from sklearn.exceptions import ConvergenceWarning
from sklearn.gaussian_process import GaussianProcessRegressor
from sklearn.gaussian_process.kernels import RBF, ConstantKernel, WhiteKernel
from sklearn.model_selection import KFold

from loco.studies.surrogate import r2_score

__all__ = ["gaussian_process_r2"]

FloatArray = npt.NDArray[np.float64]


def gaussian_process_r2(
    x: FloatArray,
    target: FloatArray,
    bounds: FloatArray,
    *,
    n_splits: int = 5,
    seed: int = 0,
    log_target: bool = False,
) -> tuple[float, float]:
    """Mean held-out R² of an ARD Gaussian process on the folds of ``KFold(n_splits, shuffle,
    seed)``, and the fitted noise share (white-noise variance over the target's variance, on all
    samples). ``x`` (n, k) in SI is scaled to [0, 1] by ``bounds`` (k, 2); ``target`` (n,) is the
    fitted quantity (log of the objective when ``log_target``); R² is scored on the objective.
    """
    z = (x - bounds[:, 0]) / (bounds[:, 1] - bounds[:, 0])
    objective = np.exp(target) if log_target else target

    def model() -> GaussianProcessRegressor:
        kernel = ConstantKernel(1.0) * RBF(np.full(x.shape[1], 0.5), (1e-2, 1e3)) + WhiteKernel(
            1e-2, (1e-8, 1e1)
        )
        return GaussianProcessRegressor(kernel, normalize_y=True, random_state=seed)

    scores = []
    with warnings.catch_warnings():
        # A length scale at its upper bound means that parameter does not matter: expected.
        warnings.simplefilter("ignore", ConvergenceWarning)
        for train, test in KFold(n_splits=n_splits, shuffle=True, random_state=seed).split(z):
            predicted = model().fit(z[train], target[train]).predict(z[test])
            if log_target:
                predicted = np.exp(predicted)
            scores.append(float(r2_score(objective[test], predicted)[0]))
        full = model().fit(z, target)
    noise = float(full.kernel_.k2.noise_level)
    # normalize_y scales the target to unit variance, so the noise level is already a share.
    return float(np.mean(scores)), noise
