"""Which surrogate the optimisation and the surrogate Sobol' indices run on, chosen by nested
cross-validation.

SPEC §6.3 fixes the network (10 Gaussian units, K-means centres, linear output with bias) and asks
for a held-out R² above 0.9; on the study's responses 10 units are too few. Six candidates are
scored on the same k outer folds (scikit-learn ``KFold`` shuffled with the seed). Every candidate
tunes its own hyperparameters on the training folds only (the inner loop: leave-one-out error for
the RBF networks, marginal likelihood for the Gaussian processes), so its outer score is a nested
cross-validation estimate. The candidates learn log(objective) with ``log_target`` (or, the
``_sqrt`` ones, its square root) and are scored by R² on the objective itself:

- ``rbf10``: the SPEC network (:class:`~loco.studies.rbf_network.RBFNetwork`, 10 units; its width
  factor chosen by leave-one-out error), always reported;
- ``rbf_cv``: a larger network of the same kind (:class:`LargerRBF`): K-means centres and a
  least-squares output layer, with the number of units (:data:`RBF_UNITS`) and the width factor
  chosen together by the exact leave-one-out error (PRESS) of the output layer;
- ``gp``: a Gaussian process with one length scale per parameter and a white-noise term
  (:class:`~loco.studies.surrogate_reference.GaussianProcessSurrogate`), squared-exponential;
- ``gp_matern``: the same with an ARD Matérn 5/2 kernel;
- ``gp_sqrt`` and ``gp_matern_sqrt``: those two fitted on the square root of the objective
  (:class:`SqrtTarget`): between the log, which stretches the small values, and no transform,
  which lets the hunting tail dominate the fit.

The candidate with the highest mean outer-fold R² is used (:func:`select_surrogate`), one choice
per objective; it is refitted on every sample. Picking the best of six scores is itself a fit, so
the maximum is optimistic; :func:`nested_selection_r2` estimates the whole procedure (choice made
on the inner folds of each outer training set, scored on the outer test fold), and
:mod:`loco.studies.surrogate_holdout` scores the chosen model on fresh samples used neither in
training nor in selection. Whether it reaches :data:`R2_REQUIRED` is reported, never forced.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np
import numpy.typing as npt

from loco.studies.rbf_network import WIDTH_FACTORS, RBFNetwork
from loco.studies.surrogate_reference import GaussianProcessSurrogate

__all__ = [
    "CANDIDATES",
    "R2_REQUIRED",
    "RBF_UNITS",
    "SPEC_MODEL",
    "CandidateScore",
    "LargerRBF",
    "NestedScore",
    "Regressor",
    "Selection",
    "SqrtTarget",
    "make_model",
    "nested_selection_r2",
    "select_surrogate",
    "selection_settings",
]

FloatArray = npt.NDArray[np.float64]

#: The candidates, in the order they are reported.
CANDIDATES: tuple[str, ...] = ("rbf10", "rbf_cv", "gp", "gp_matern", "gp_sqrt", "gp_matern_sqrt")
#: The network SPEC §6.3 prescribes.
SPEC_MODEL = "rbf10"
#: Held-out R² SPEC §6.3 asks of the surrogate.
R2_REQUIRED = 0.9
#: Hidden-unit counts :class:`LargerRBF` chooses from (those up to half the training samples).
RBF_UNITS: tuple[int, ...] = (10, 15, 20, 30, 40, 60, 80)

DESCRIPTIONS: dict[str, str] = {
    "rbf10": "SPEC RBF network, 10 Gaussian units (K-means), width by leave-one-out",
    "rbf_cv": "RBF network, units and width by leave-one-out (K-means, least squares)",
    "gp": "Gaussian process, one length scale per parameter plus white noise",
    "gp_matern": "Gaussian process, ARD Matérn 5/2 plus white noise",
    "gp_sqrt": "Gaussian process (as gp) fitted on the square root of the objective",
    "gp_matern_sqrt": "Gaussian process (as gp_matern) fitted on the square root of the objective",
}


class Regressor(Protocol):
    """A surrogate: ``fit(x (n, k) in SI, target (n,))`` then ``predict(x) -> (n,)``."""

    def fit(self, x: FloatArray, y: FloatArray) -> Any: ...

    def predict(self, x: npt.ArrayLike) -> FloatArray: ...


class LargerRBF:
    """Gaussian RBF network whose number of units and width factor are chosen by the exact
    leave-one-out error of its output layer (PRESS of :class:`RBFNetwork`), over
    :data:`RBF_UNITS` up to half the samples and :data:`WIDTH_FACTORS`. ``bounds`` (k, 2) scale
    the inputs; ``seed`` seeds K-means. After :meth:`fit`: ``network_`` (the network kept),
    ``n_centres_``, ``width_factor_``."""

    def __init__(self, bounds: npt.ArrayLike, *, seed: int = 0, units: Sequence[int] = RBF_UNITS):
        self.bounds = np.asarray(bounds, dtype=np.float64)
        self.seed = seed
        self.units = tuple(units)

    def fit(self, x: FloatArray, y: FloatArray) -> LargerRBF:
        scale = max(float(np.var(y)), np.finfo(float).tiny)
        best: tuple[float, RBFNetwork] | None = None
        # Up to half the samples; with fewer than 2 x the smallest count (tiny studies), that
        # smallest count alone, as long as there are as many samples as units.
        allowed = [u for u in self.units if u <= len(x) // 2]
        allowed = allowed or [u for u in self.units[:1] if u <= len(x)]
        for m in allowed:
            net = RBFNetwork(m, bounds=self.bounds, seed=self.seed, width_factor=WIDTH_FACTORS)
            net.fit(x, y)
            score = net.press_ / scale
            if best is None or score < best[0]:
                best = (score, net)
        if best is None:
            raise ValueError(f"LargerRBF: {len(x)} samples, fewer than {self.units[0]} units")
        self.network_ = best[1]
        self.n_centres_ = self.network_.n_centres
        self.width_factor_ = self.network_.width_factor_
        return self

    def predict(self, x: npt.ArrayLike) -> FloatArray:
        return self.network_.predict(x)


class SqrtTarget:
    """``inner`` fitted on the square root of the objective, behind the interface of the other
    candidates: it takes and predicts the same target as they do (log(objective) when
    ``log_target``, else the objective), so the Sobol' and NSGA-II stages use it unchanged. A
    negative square-root prediction means an objective of 0 (both objectives are >= 0); it is
    clipped to the smallest positive float so that the log stays finite."""

    def __init__(self, inner: Regressor, *, log_target: bool = True) -> None:
        self.inner = inner
        self.log_target = log_target

    def fit(self, x: FloatArray, y: FloatArray) -> SqrtTarget:
        objective = np.exp(y) if self.log_target else np.asarray(y, dtype=np.float64)
        if np.any(objective < 0):
            raise ValueError("SqrtTarget: the objective must be >= 0")
        self.inner.fit(x, np.sqrt(objective))
        return self

    def predict(self, x: npt.ArrayLike) -> FloatArray:
        root = np.maximum(np.asarray(self.inner.predict(x), dtype=np.float64), 0.0)
        if not self.log_target:
            return np.asarray(root**2, dtype=np.float64)
        return np.asarray(2.0 * np.log(np.maximum(root, np.finfo(float).tiny)), dtype=np.float64)


def make_model(
    kind: str, bounds: npt.ArrayLike, *, seed: int = 0, log_target: bool = True
) -> Regressor:
    """A fresh, unfitted candidate ``kind`` (one of :data:`CANDIDATES`) learning log(objective)
    when ``log_target`` (else the objective)."""
    if kind == "rbf10":
        return RBFNetwork(10, bounds=bounds, seed=seed)
    if kind == "rbf_cv":
        return LargerRBF(bounds, seed=seed)
    if kind in ("gp", "gp_matern", "gp_sqrt", "gp_matern_sqrt"):
        kernel = "matern52" if kind.startswith("gp_matern") else "se"
        gp = GaussianProcessSurrogate(bounds, seed=seed, kernel=kernel)
        return SqrtTarget(gp, log_target=log_target) if kind.endswith("_sqrt") else gp
    raise ValueError(f"unknown surrogate {kind!r}; expected one of {CANDIDATES}")


def describe(model: Any) -> dict[str, Any]:
    """Hyperparameters a fitted candidate chose (for the report)."""
    if isinstance(model, RBFNetwork):
        return {"units": model.n_centres, "width_factor": model.width_factor_}
    if isinstance(model, LargerRBF):
        return {"units": model.n_centres_, "width_factor": model.width_factor_}
    if isinstance(model, GaussianProcessSurrogate):
        return {"length_scales": model.length_scales_, "noise_share": model.noise_share_}
    if isinstance(model, SqrtTarget):
        return {"target": "sqrt", **describe(model.inner)}
    return {}


@dataclass(frozen=True)
class CandidateScore:
    """Held-out R² of one candidate on each fold, its held-out predictions (objective units,
    one per sample), and the hyperparameters its fit on every sample chose."""

    kind: str
    r2_folds: FloatArray
    predictions: FloatArray
    hyperparameters: dict[str, Any]

    @property
    def r2_mean(self) -> float:
        return float(self.r2_folds.mean())

    @property
    def r2_min(self) -> float:
        return float(self.r2_folds.min())


@dataclass(frozen=True)
class Selection:
    """The candidates' scores for one objective and the one used (``chosen``, refitted on every
    sample as ``model``); ``spec_model`` is the SPEC network fitted on every sample, ``models``
    every candidate fitted on every sample (for the fresh held-out samples)."""

    scores: dict[str, CandidateScore]
    chosen: str
    model: Regressor
    spec_model: RBFNetwork
    models: dict[str, Regressor]
    nested: NestedScore | None = None

    @property
    def meets_requirement(self) -> bool:
        """Whether the chosen surrogate's held-out R² reaches :data:`R2_REQUIRED`."""
        return self.scores[self.chosen].r2_mean >= R2_REQUIRED

    def reason(self) -> str:
        """Why ``chosen`` was used, in a sentence."""
        best = self.scores[self.chosen]
        spec = self.scores.get(SPEC_MODEL)
        text = f"{self.chosen} has the highest mean held-out R² ({best.r2_mean:.3f})"
        if spec is not None and self.chosen != SPEC_MODEL:
            text += f"; the SPEC network reaches {spec.r2_mean:.3f}"
        if not self.meets_requirement:
            text += f"; no candidate reaches the required {R2_REQUIRED}"
        return text


def selection_settings(n_splits: int, candidates: Sequence[str] = CANDIDATES) -> dict[str, Any]:
    """What the choice depends on beyond the samples and seed (for settings and stage hashes)."""
    return {
        "candidates": {k: DESCRIPTIONS[k] for k in candidates},
        "rbf_units": list(RBF_UNITS),
        "width_factors": list(WIDTH_FACTORS),
        "selection": f"highest mean held-out R² over {n_splits} folds (hyperparameters tuned "
        "inside each training fold)",
        "r2_required": R2_REQUIRED,
    }


def select_surrogate(
    x: FloatArray,
    y: FloatArray,
    bounds: npt.ArrayLike,
    *,
    n_splits: int = 5,
    seed: int = 0,
    log_target: bool = True,
    candidates: Sequence[str] = CANDIDATES,
    nested: bool = False,
) -> Selection:
    """Score every candidate on the same ``n_splits`` folds for one objective ``y`` (n,) > 0
    when ``log_target`` (finite values only: drop failed samples first), choose the best and
    refit every candidate on every sample. With ``nested``, also :func:`nested_selection_r2`
    (``selection.nested``; ``n_splits`` times the work).

    BLAS and OpenMP run single-threaded here: these fits are small (a few hundred samples), and
    on a loaded machine their thread pools cost 20 times the work itself (measured: an ARD GP fit
    of 160 samples 11 s with the default pools against 0.4 s with one thread, load average 14 on
    2 cores)."""
    if not np.isfinite(y).all():
        raise ValueError("select_surrogate: objective values must be finite (drop failed runs)")
    # The fits live in surrogate_fits, which builds on this module's candidates.
    from loco.studies.surrogate_fits import Objective, select_objectives

    (selection,) = select_objectives(
        [Objective(x, y)], bounds, n_splits=n_splits, seed=seed, log_target=log_target,
        candidates=candidates, nested=nested,
    )  # fmt: skip
    return selection


def best_candidate(scores: dict[str, CandidateScore]) -> str:
    """The candidate with the highest mean held-out R² (the first listed on a tie)."""
    return max(scores, key=lambda k: scores[k].r2_mean)


@dataclass(frozen=True)
class NestedScore:
    """The selection procedure scored by nested cross-validation: on each outer fold, the
    candidate the inner folds of its training samples chose (``chosen``) and its R² on the outer
    test fold (``r2_folds``)."""

    chosen: tuple[str, ...]
    r2_folds: FloatArray

    @property
    def r2_mean(self) -> float:
        return float(self.r2_folds.mean())


def nested_selection_r2(
    x: FloatArray,
    y: FloatArray,
    bounds: npt.ArrayLike,
    *,
    n_splits: int = 5,
    seed: int = 0,
    log_target: bool = True,
    candidates: Sequence[str] = CANDIDATES,
) -> NestedScore:
    """Nested cross-validation of the whole choice: the outer folds of :func:`select_surrogate`;
    inside each outer training set, every candidate scored on ``n_splits`` inner folds and the
    best fitted on that training set and scored on the outer test fold, which took no part in
    the choice. Its mean is the estimate of the accuracy of "choose, then fit" that the maximum
    of the candidates' scores overstates."""
    from loco.studies.surrogate_fits import Objective, nested_only

    return nested_only(Objective(x, y), bounds, n_splits=n_splits, seed=seed,
                       log_target=log_target, candidates=candidates)  # fmt: skip
