"""The radial-basis-function neural network of SPEC §6.3 and its validation.

Architecture (Moody & Darken 1989; Haykin, *Neural Networks*, 2nd ed. 1999, ch. 5):

- inputs scaled to [0, 1] per column by the design box (``bounds``) or, without one, by the
  training data's range;
- a hidden layer of ``n_centres`` Gaussian units φ_j(x) = exp(−‖x − c_j‖² / (2σ_j²)) whose
  centres c_j are the K-means centroids of the scaled training inputs (scikit-learn ``KMeans``,
  seeded, 10 restarts);
- a width rule for σ_j:

  ``"nearest"`` (default): the p-nearest-neighbour heuristic of Moody & Darken (1989):
  σ_j = a · RMS distance from c_j to its ``p_neighbours`` nearest other centres.
  ``"haykin"``: one width for all units, σ = a · d_max / √(2M) with d_max the largest distance
  between centres and M their number (Haykin 1999, §5.11), i.e. φ = exp(−M‖x − c‖² / d_max²)
  for a = 1.

  The multiplier a is ``width_factor``; given several candidates (the default
  :data:`WIDTH_FACTORS`) the fit keeps the one with the smallest leave-one-out error of the
  output layer (PRESS, computed exactly from the hat matrix, centres fixed), so the width
  adapts to how smooth the response is without a separate validation set;

- a linear output layer with bias, y = Σ_j w_j φ_j(x) + b, fitted by least squares
  (``numpy.linalg.lstsq``); with ``ridge`` > 0 the weights (not the bias) are penalised by
  ``ridge`` · ‖w‖² to tame an ill-conditioned Φ (the default 0 is plain least squares).

Several outputs share the hidden layer (one output column each). Only numpy and
scikit-learn's K-means and K-fold splitter are used: no kernel of scikit-learn.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Literal, Protocol

import numpy as np
import numpy.typing as npt
from sklearn.cluster import KMeans
from sklearn.model_selection import KFold

from loco.studies.evaluators import Evaluator
from loco.studies.plotting import pyplot, save_figure

__all__ = [
    "CrossValidation",
    "Predictor",
    "RBFNetwork",
    "cross_validate",
    "fit_per_output",
    "parity_plot",
    "r2_score",
    "surrogate_evaluator",
]

FloatArray = npt.NDArray[np.float64]
WidthRule = Literal["nearest", "haykin"]

#: Candidate multipliers of the width rule; :meth:`RBFNetwork.fit` keeps the one with the
#: smallest leave-one-out error. In 6 dimensions the plain Moody-Darken width (factor 1) leaves
#: the units too narrow to overlap, and a smooth response wants 2-8 times that.
WIDTH_FACTORS: tuple[float, ...] = (0.5, 1.0, 2.0, 4.0, 8.0)

#: Singular values below this fraction of the largest are dropped (minimum-norm solution).
_RCOND = 1e-10


def r2_score(y_true: npt.ArrayLike, y_pred: npt.ArrayLike) -> FloatArray:
    """Coefficient of determination 1 − SS_res/SS_tot of each output column, shape (m,)."""
    t = np.asarray(y_true, dtype=np.float64).reshape(len(np.asarray(y_true)), -1)
    p = np.asarray(y_pred, dtype=np.float64).reshape(t.shape)
    ss_res = np.sum((t - p) ** 2, axis=0)
    ss_tot = np.sum((t - t.mean(axis=0)) ** 2, axis=0)
    return np.asarray(1.0 - ss_res / ss_tot, dtype=np.float64)


def _pairwise(a: FloatArray, b: FloatArray) -> FloatArray:
    d2 = np.sum(a**2, axis=1)[:, None] + np.sum(b**2, axis=1)[None, :] - 2.0 * a @ b.T
    return np.asarray(np.maximum(d2, 0.0), dtype=np.float64)


class RBFNetwork:
    """Gaussian RBF network: K-means centres, a width rule, least-squares linear output.

    Parameters
    ----------
    n_centres : int
        Hidden neurons (SPEC §6.3: 10).
    width_rule : {"nearest", "haykin"}
        How σ_j is chosen (module docstring).
    p_neighbours : int
        Neighbours of the ``"nearest"`` rule (Moody & Darken suggest a few; default 2).
    width_factor : float or sequence of float
        Multiplier a of every σ_j (dimensionless); a sequence is a set of candidates chosen
        from by leave-one-out error (see :meth:`fit`).
    ridge : float
        Penalty on the output weights (0: plain least squares).
    bounds : array (k, 2), optional
        Input box [low, high] per column used to scale to [0, 1] (SI, e.g.
        :func:`loco.studies.parameters.bounds_si`); default: the training data's range.
    seed : int
        Seed of K-means.

    Attributes (after :meth:`fit`)
    ------------------------------
    centres_ : (M, k) centres in scaled inputs. widths_ : (M,) σ_j (scaled inputs).
    width_factor_ : the multiplier kept. press_ : its leave-one-out error (sum over outputs of
    PRESS / variance). weights_ : (M, m) output weights. bias_ : (m,) output bias.
    """

    def __init__(
        self,
        n_centres: int = 10,
        *,
        width_rule: WidthRule = "nearest",
        p_neighbours: int = 2,
        width_factor: float | Sequence[float] = WIDTH_FACTORS,
        ridge: float = 0.0,
        bounds: npt.ArrayLike | None = None,
        seed: int = 0,
    ) -> None:
        if n_centres < 2:
            raise ValueError(f"RBFNetwork: n_centres must be >= 2, got {n_centres}")
        if width_rule not in ("nearest", "haykin"):
            raise ValueError(f"RBFNetwork: unknown width_rule {width_rule!r}")
        if not 1 <= p_neighbours < n_centres:
            raise ValueError(f"RBFNetwork: need 1 <= p_neighbours < n_centres, got {p_neighbours}")
        factors = (width_factor,) if isinstance(width_factor, (int, float)) else width_factor
        self.width_factors = tuple(float(f) for f in factors)
        if not (self.width_factors and min(self.width_factors) > 0 and ridge >= 0):
            raise ValueError("RBFNetwork: width factors must be > 0 and ridge >= 0")
        self.n_centres = n_centres
        self.width_rule: WidthRule = width_rule
        self.p_neighbours = p_neighbours
        self.ridge = ridge
        self.bounds = None if bounds is None else np.asarray(bounds, dtype=np.float64)
        self.seed = seed

    # -- scaling and hidden layer ---------------------------------------------------------------
    def _scale(self, x: FloatArray) -> FloatArray:
        return (x - self.lower_) / (self.upper_ - self.lower_)

    def _widths(self, centres: FloatArray) -> FloatArray:
        d = np.sqrt(_pairwise(centres, centres))
        if self.width_rule == "haykin":
            sigma = np.full(len(centres), d.max() / np.sqrt(2.0 * len(centres)))
        else:
            np.fill_diagonal(d, np.inf)
            nearest = np.sort(d, axis=1)[:, : self.p_neighbours]
            sigma = np.sqrt(np.mean(nearest**2, axis=1))
        if not np.all(sigma > 0):
            raise ValueError("RBFNetwork: coincident centres (fewer distinct inputs than centres)")
        return np.asarray(sigma, dtype=np.float64)

    def hidden(self, x: npt.ArrayLike) -> FloatArray:
        """Hidden-layer outputs φ_j(x), shape (n, M), for inputs in their own units."""
        z = self._scale(np.atleast_2d(np.asarray(x, dtype=np.float64)))
        return np.exp(-_pairwise(z, self.centres_) / (2.0 * self.widths_**2))

    # -- fit and predict ------------------------------------------------------------------------
    def _solve(self, phi: FloatArray, y2: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Output weights and bias (M + 1, m), and the PRESS statistic of each output (m,)."""
        n, m_hidden = phi.shape
        design = np.hstack([phi, np.ones((n, 1))])
        target = y2
        if self.ridge > 0:
            penalty = np.hstack([np.sqrt(self.ridge) * np.eye(m_hidden), np.zeros((m_hidden, 1))])
            design = np.vstack([design, penalty])
            target = np.vstack([y2, np.zeros((m_hidden, y2.shape[1]))])
        u, s, vt = np.linalg.svd(design, full_matrices=False)
        keep = s > _RCOND * s[0]
        u, s, vt = u[:, keep], s[keep], vt[keep]
        coef = vt.T @ ((u.T @ target) / s[:, None])
        leverage = np.sum(u[:n] ** 2, axis=1)
        residual = y2 - design[:n] @ coef
        with np.errstate(divide="ignore", invalid="ignore"):
            loo = residual / (1.0 - leverage)[:, None]
        press = np.sum(loo**2, axis=0)
        return coef, np.where(np.isfinite(press), press, np.inf)

    def fit(self, x: npt.ArrayLike, y: npt.ArrayLike) -> RBFNetwork:
        """Fit on inputs ``x`` (n, k) and targets ``y`` (n,) or (n, m); no NaN allowed.

        Drop failed samples before (``~np.isnan(y).any(axis=1)``): a NaN target has no place in
        a least-squares fit. With several candidate ``width_factor`` values, the one with the
        smallest leave-one-out error of the output layer (PRESS, Allen 1974: e_i / (1 − h_ii)
        from the hat matrix; outputs weighted by 1/variance) is kept as ``width_factor_``.
        """
        xa = np.atleast_2d(np.asarray(x, dtype=np.float64))
        ya = np.asarray(y, dtype=np.float64)
        self._single_output = ya.ndim == 1
        y2 = ya.reshape(len(ya), -1)
        if len(xa) != len(y2):
            raise ValueError(f"RBFNetwork.fit: {len(xa)} inputs but {len(y2)} targets")
        if not (np.isfinite(xa).all() and np.isfinite(y2).all()):
            raise ValueError("RBFNetwork.fit: inputs and targets must be finite (drop NaN rows)")
        if len(xa) < self.n_centres:
            raise ValueError(f"RBFNetwork.fit: {len(xa)} samples < {self.n_centres} centres")
        if self.bounds is not None:
            self.lower_, self.upper_ = self.bounds[:, 0], self.bounds[:, 1]
        else:
            self.lower_, self.upper_ = xa.min(axis=0), xa.max(axis=0)
            self.upper_ = np.where(self.upper_ > self.lower_, self.upper_, self.lower_ + 1.0)
        z = self._scale(xa)
        kmeans = KMeans(n_clusters=self.n_centres, n_init=10, random_state=self.seed).fit(z)
        self.centres_ = np.asarray(kmeans.cluster_centers_, dtype=np.float64)
        base = self._widths(self.centres_)
        scale = np.maximum(y2.var(axis=0), np.finfo(float).tiny)
        best: tuple[float, float, FloatArray] | None = None
        for factor in self.width_factors:
            self.widths_ = base * factor
            coef, press = self._solve(self.hidden(xa), y2)
            score = float(np.sum(press / scale))
            if best is None or score < best[0]:
                best = (score, factor, coef)
        assert best is not None
        self.press_, self.width_factor_, coef = best
        self.widths_ = base * self.width_factor_
        self.weights_, self.bias_ = coef[:-1], coef[-1]
        return self

    def predict(self, x: npt.ArrayLike) -> FloatArray:
        """Predictions at ``x`` (n, k): shape (n,) for a 1-D fit target, else (n, m)."""
        out = self.hidden(x) @ self.weights_ + self.bias_
        return np.asarray(out[:, 0] if self._single_output else out, dtype=np.float64)

    def score(self, x: npt.ArrayLike, y: npt.ArrayLike) -> FloatArray:
        """R² of the predictions at ``x`` against ``y``, one value per output, shape (m,)."""
        return r2_score(y, self.predict(x))


@dataclass(frozen=True)
class CrossValidation:
    """k-fold cross-validation of an :class:`RBFNetwork`.

    ``r2_folds`` (n_splits, m): R² of each held-out fold; ``predictions`` (n, m): each sample
    predicted by the network that did not see it (for parity plots).
    """

    r2_folds: FloatArray
    predictions: FloatArray

    @property
    def r2_mean(self) -> FloatArray:
        """Mean held-out R² per output, shape (m,)."""
        return np.asarray(self.r2_folds.mean(axis=0), dtype=np.float64)


def cross_validate(
    x: npt.ArrayLike,
    y: npt.ArrayLike,
    *,
    n_splits: int = 5,
    seed: int = 0,
    n_centres: int = 10,
    **network: object,
) -> CrossValidation:
    """Held-out R² by k-fold cross-validation (scikit-learn ``KFold``, shuffled with ``seed``).

    Each fold trains ``RBFNetwork(n_centres, seed=seed, **network)`` on the other folds. Inputs
    (n, k); targets (n,) or (n, m), finite.
    """
    xa = np.asarray(x, dtype=np.float64)
    y2 = np.asarray(y, dtype=np.float64).reshape(len(xa), -1)
    folds = KFold(n_splits=n_splits, shuffle=True, random_state=seed)
    r2 = np.empty((n_splits, y2.shape[1]))
    predictions = np.empty_like(y2)
    for i, (train, test) in enumerate(folds.split(xa)):
        model = RBFNetwork(n_centres, seed=seed, **network)  # type: ignore[arg-type]
        model.fit(xa[train], y2[train])
        predictions[test] = model.predict(xa[test])
        r2[i] = r2_score(y2[test], predictions[test])
    return CrossValidation(r2_folds=r2, predictions=predictions)


def fit_per_output(
    x: npt.ArrayLike,
    y: npt.ArrayLike,
    *,
    n_centres: int = 10,
    bounds: npt.ArrayLike | None = None,
    seed: int = 0,
    **network: object,
) -> list[RBFNetwork]:
    """One :class:`RBFNetwork` per column of ``y`` (n, m), each fitted on the rows where that
    column is finite: a sample that failed in one scenario (NaN) still trains the others."""
    xa = np.asarray(x, dtype=np.float64)
    y2 = np.asarray(y, dtype=np.float64).reshape(len(xa), -1)
    models = []
    for j in range(y2.shape[1]):
        ok = np.isfinite(y2[:, j])
        net = RBFNetwork(n_centres, bounds=bounds, seed=seed, **network)  # type: ignore[arg-type]
        models.append(net.fit(xa[ok], y2[ok, j]))
    return models


class Predictor(Protocol):
    """A fitted surrogate of one output: ``predict(x (n, k) in SI) -> (n,)``."""

    def predict(self, x: npt.ArrayLike) -> FloatArray: ...


def surrogate_evaluator(models: Sequence[Predictor], input_names: Sequence[str]) -> Evaluator:
    """An :class:`~loco.studies.evaluators.Evaluator` from fitted surrogates (e.g.
    :class:`RBFNetwork`), outputs side by side.

    ``input_names`` are the columns the networks were trained on; the evaluator checks that it is
    called with the same names in the same order.
    """
    expected = list(input_names)

    def evaluate(params: FloatArray, names: Sequence[str]) -> FloatArray:
        if list(names) != expected:
            raise ValueError(f"surrogate trained on {expected}, called with {list(names)}")
        cols = [np.asarray(m.predict(params), dtype=np.float64).reshape(len(params), -1)
                for m in models]  # fmt: skip
        return np.hstack(cols)

    return evaluate


def parity_plot(
    y_true: npt.ArrayLike,
    y_pred: npt.ArrayLike,
    path: str | Path,
    *,
    label: str = "y",
    unit: str = "",
    title: str | None = None,
) -> Path:
    """Save a parity plot (prediction against reference, with the 1:1 line and R²) as PNG.

    ``label`` and ``unit`` name the quantity on the axes; returns the path written.
    """
    t = np.asarray(y_true, dtype=np.float64).ravel()
    p = np.asarray(y_pred, dtype=np.float64).ravel()
    r2 = float(r2_score(t, p)[0])
    lo, hi = float(min(t.min(), p.min())), float(max(t.max(), p.max()))
    pad = 0.05 * (hi - lo or 1.0)
    suffix = f" ({unit})" if unit else ""
    fig, ax = pyplot().subplots(figsize=(4.5, 4.5), layout="constrained")
    ax.plot([lo - pad, hi + pad], [lo - pad, hi + pad], color="0.5", lw=1, label="1:1")
    ax.scatter(t, p, s=12, alpha=0.7, label=f"samples, R² = {r2:.3f}")
    ax.set(xlim=(lo - pad, hi + pad), ylim=(lo - pad, hi + pad), aspect="equal")
    ax.set_xlabel(f"{label} simulated{suffix}")
    ax.set_ylabel(f"{label} surrogate{suffix}")
    ax.set_title(title or f"RBF surrogate of {label}")
    ax.legend(loc="upper left")
    return save_figure(fig, path)
