"""Which surrogate the optimisation and the surrogate Sobol' indices run on, chosen by
cross-validation.

SPEC §6.3 fixes the network (10 Gaussian units, K-means centres, linear output with bias) and asks
for a held-out R² above 0.9; on the study's responses 10 units may be too few. Three candidates
are scored on the same k folds (scikit-learn ``KFold`` shuffled with the seed), each learning the
same target (log of the objective with ``log_target``) and scored by R² on the objective itself:

- ``rbf10``: the SPEC network (:class:`~loco.studies.surrogate.RBFNetwork`, 10 units; its width
  factor chosen by leave-one-out error), always reported;
- ``rbf_cv``: a larger network of the same kind (:class:`LargerRBF`): K-means centres and a
  least-squares output layer, with the number of units (:data:`RBF_UNITS`) and the width factor
  chosen together by the exact leave-one-out error (PRESS) of the output layer on the training
  folds only, so the held-out score stays honest;
- ``gp``: a Gaussian process with one length scale per parameter and a white-noise term
  (:class:`~loco.studies.surrogate_reference.GaussianProcessSurrogate`).

The candidate with the highest mean held-out R² is used (:func:`select_surrogate`), one choice per
objective; it is refitted on every sample. Whether it reaches :data:`R2_REQUIRED` is reported,
never forced.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np
import numpy.typing as npt
from sklearn.model_selection import KFold
from threadpoolctl import threadpool_limits

from loco.studies.surrogate import WIDTH_FACTORS, RBFNetwork, r2_score
from loco.studies.surrogate_reference import GaussianProcessSurrogate

__all__ = [
    "CANDIDATES",
    "R2_REQUIRED",
    "RBF_UNITS",
    "SPEC_MODEL",
    "CandidateScore",
    "LargerRBF",
    "Regressor",
    "Selection",
    "make_model",
    "select_surrogate",
    "selection_settings",
]

FloatArray = npt.NDArray[np.float64]

#: The candidates, in the order they are reported.
CANDIDATES: tuple[str, ...] = ("rbf10", "rbf_cv", "gp")
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


def make_model(kind: str, bounds: npt.ArrayLike, *, seed: int = 0) -> Regressor:
    """A fresh, unfitted candidate ``kind`` (one of :data:`CANDIDATES`)."""
    if kind == "rbf10":
        return RBFNetwork(10, bounds=bounds, seed=seed)
    if kind == "rbf_cv":
        return LargerRBF(bounds, seed=seed)
    if kind == "gp":
        return GaussianProcessSurrogate(bounds, seed=seed)
    raise ValueError(f"unknown surrogate {kind!r}; expected one of {CANDIDATES}")


def describe(model: Any) -> dict[str, Any]:
    """Hyperparameters a fitted candidate chose (for the report)."""
    if isinstance(model, RBFNetwork):
        return {"units": model.n_centres, "width_factor": model.width_factor_}
    if isinstance(model, LargerRBF):
        return {"units": model.n_centres_, "width_factor": model.width_factor_}
    if isinstance(model, GaussianProcessSurrogate):
        return {"length_scales": model.length_scales_, "noise_share": model.noise_share_}
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
    sample as ``model``); ``spec_model`` is the SPEC network fitted on every sample."""

    scores: dict[str, CandidateScore]
    chosen: str
    model: Regressor
    spec_model: RBFNetwork

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
        "selection": f"highest mean held-out R² over {n_splits} folds",
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
) -> Selection:
    """Score every candidate on the same ``n_splits`` folds for one objective ``y`` (n,) > 0
    when ``log_target`` (finite values only: drop failed samples first), choose the best and
    refit it on every sample.

    BLAS and OpenMP run single-threaded here: these fits are small (a few hundred samples), and
    on a loaded machine their thread pools cost 20 times the work itself (measured: an ARD GP fit
    of 160 samples 11 s with the default pools against 0.4 s with one thread, load average 14 on
    2 cores)."""
    with threadpool_limits(limits=1):
        return _select(x, y, bounds, n_splits, seed, log_target, candidates)


def _select(
    x: FloatArray,
    y: FloatArray,
    bounds: npt.ArrayLike,
    n_splits: int,
    seed: int,
    log_target: bool,
    candidates: Sequence[str],
) -> Selection:
    if not np.isfinite(y).all():
        raise ValueError("select_surrogate: objective values must be finite (drop failed runs)")
    target = np.log(y) if log_target else y
    back: Callable[[FloatArray], FloatArray] = np.exp if log_target else (lambda v: v)
    splits = list(KFold(n_splits=n_splits, shuffle=True, random_state=seed).split(x))
    scores = {}
    fitted = {}
    for kind in candidates:
        predictions = np.empty(len(y))
        r2 = np.empty(n_splits)
        for i, (train, test) in enumerate(splits):
            model = make_model(kind, bounds, seed=seed)
            model.fit(x[train], target[train])
            predictions[test] = back(np.asarray(model.predict(x[test]), dtype=np.float64))
            r2[i] = float(r2_score(y[test], predictions[test])[0])
        full = make_model(kind, bounds, seed=seed)
        full.fit(x, target)
        fitted[kind] = full
        scores[kind] = CandidateScore(kind, r2, predictions, describe(full))
    chosen = max(candidates, key=lambda k: scores[k].r2_mean)
    spec = fitted.get(SPEC_MODEL)
    if not isinstance(spec, RBFNetwork):
        spec = RBFNetwork(10, bounds=bounds, seed=seed).fit(x, target)
    return Selection(scores=scores, chosen=chosen, model=fitted[chosen], spec_model=spec)
