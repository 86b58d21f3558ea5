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
from sklearn.gaussian_process.kernels import RBF, Matern
from sklearn.model_selection import KFold

from loco.studies.gp_kernel import scaled_kernel_with_noise
from loco.studies.rbf_network import r2_score

__all__ = ["GaussianProcessSurrogate", "gaussian_process_r2"]

FloatArray = npt.NDArray[np.float64]


class GaussianProcessSurrogate:
    """ARD Gaussian process on inputs scaled to [0, 1] by ``bounds`` (k, 2): a constant times a
    squared-exponential kernel with one length scale per parameter (1e-2 to 1e3 of the box) plus
    white noise, targets normalised (scikit-learn ``GaussianProcessRegressor``, hyperparameters by
    maximum marginal likelihood, ``seed``).

    After :meth:`fit`: ``length_scales_`` (k,) in box units (a length at the upper bound means the
    parameter does not matter), ``noise_share_`` (white-noise variance over the target variance:
    the share no smooth function of the parameters explains).

    ``kernel="matern52"`` replaces the squared exponential by an ARD Matérn kernel with ν = 5/2
    (twice differentiable rather than infinitely: it can follow the steeper rise of A_yb at the
    hunting onset without the squared exponential's shortest length scale spreading everywhere).
    """

    KERNELS: tuple[str, ...] = ("se", "matern52")

    def __init__(self, bounds: npt.ArrayLike, *, seed: int = 0, kernel: str = "se") -> None:
        if kernel not in self.KERNELS:
            raise ValueError(f"GaussianProcessSurrogate: kernel {kernel!r} not in {self.KERNELS}")
        self.bounds = np.asarray(bounds, dtype=np.float64)
        self.seed = seed
        self.kernel = kernel

    def _scale(self, x: npt.ArrayLike) -> FloatArray:
        z = np.atleast_2d(np.asarray(x, dtype=np.float64))
        return (z - self.bounds[:, 0]) / (self.bounds[:, 1] - self.bounds[:, 0])

    def fit(self, x: FloatArray, y: FloatArray) -> GaussianProcessSurrogate:
        length = np.full(x.shape[1], 0.5)
        shape = (
            RBF(length, (1e-2, 1e3)) if self.kernel == "se" else Matern(length, (1e-2, 1e3), nu=2.5)
        )
        kernel = scaled_kernel_with_noise(shape, constant=1.0, noise=1e-2, noise_bounds=(1e-8, 1e1))
        self.model_ = GaussianProcessRegressor(kernel, normalize_y=True, random_state=self.seed)
        with warnings.catch_warnings():
            # A length scale at its upper bound means that parameter does not matter: expected.
            warnings.simplefilter("ignore", ConvergenceWarning)
            self.model_.fit(self._scale(x), np.asarray(y, dtype=np.float64))
        kernel_ = self.model_.kernel_
        self.length_scales_ = np.atleast_1d(kernel_.k1.k2.length_scale).astype(float).tolist()
        # normalize_y scales the target to unit variance, so the noise level is already a share.
        self.noise_share_ = float(kernel_.k2.noise_level)
        return self

    def predict(self, x: npt.ArrayLike) -> FloatArray:
        return np.asarray(self.model_.predict(self._scale(x)), dtype=np.float64)


def gaussian_process_r2(
    x: FloatArray,
    target: FloatArray,
    bounds: FloatArray,
    *,
    n_splits: int = 5,
    seed: int = 0,
    log_target: bool = False,
) -> tuple[float, float]:
    """Mean held-out R² of :class:`GaussianProcessSurrogate` on the folds of ``KFold(n_splits,
    shuffle, seed)``, and the fitted noise share on all samples. ``x`` (n, k) in SI, scaled by
    ``bounds`` (k, 2); ``target`` (n,) is the fitted quantity (log of the objective when
    ``log_target``); R² is scored on the objective.
    """
    objective = np.exp(target) if log_target else target
    scores = []
    for train, test in KFold(n_splits=n_splits, shuffle=True, random_state=seed).split(x):
        predicted = GaussianProcessSurrogate(bounds, seed=seed).fit(x[train], target[train])
        p = predicted.predict(x[test])
        scores.append(float(r2_score(objective[test], np.exp(p) if log_target else p)[0]))
    full = GaussianProcessSurrogate(bounds, seed=seed).fit(x, target)
    return float(np.mean(scores)), full.noise_share_
