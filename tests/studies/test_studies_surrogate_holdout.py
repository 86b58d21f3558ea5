"""The fresh held-out samples: disjoint from every training design, and scored by the R² of the
models the optimisation uses."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.stats import qmc
from sklearn.metrics import r2_score as sk_r2

from loco.studies.parameters import bounds_si
from loco.studies.surrogate_holdout import assert_disjoint, holdout_scores, r2_interval
from loco.studies.surrogate_samples import extension_design, holdout_design, training_design
from loco.studies.surrogate_selection import select_surrogate

BOUNDS = np.array([[0.0, 1.0]] * 6)


def smooth(z: np.ndarray) -> np.ndarray:
    return np.exp(np.sin(2 * np.pi * z[:, 0]) + z[:, 1] * z[:, 2])


@pytest.mark.parametrize("seed", [0, 1, 7919])
def test_holdout_design_is_fresh(seed: int) -> None:
    hold = holdout_design(50, seed)
    lo, hi = bounds_si()[:, 0], bounds_si()[:, 1]
    assert hold.shape == (50, 6) and ((hold >= lo) & (hold <= hi)).all()
    assert_disjoint(training_design(300, 200, seed), hold)
    # Nor any other study seed's training design nearby (the seeds are offset far apart).
    for other in (seed - 1, seed + 1):
        if other >= 0:
            assert_disjoint(training_design(300, 200, other), hold)
    assert_disjoint(extension_design(300, 200, seed), hold)
    assert holdout_design(0, seed).shape == (0, 6)


def test_shared_sample_refused() -> None:
    train = training_design(30, 20, 0)
    with pytest.raises(ValueError, match=r"held-out samples \[1\]"):
        assert_disjoint(train, np.vstack([holdout_design(3, 0)[:1], train[7], train[7] + 1]))


def test_holdout_scores_are_r2_of_the_fitted_models() -> None:
    x = qmc.LatinHypercube(d=6, seed=1).random(60)
    sel = select_surrogate(x, smooth(x), BOUNDS, n_splits=3, candidates=("rbf10", "gp"))
    z = qmc.LatinHypercube(d=6, seed=2).random(40)
    y = smooth(z)
    y[5] = np.nan  # a failed held-out run is left out
    scores = holdout_scores(sel, z, y)
    ok = np.isfinite(y)
    for kind in ("rbf10", "gp"):
        expected = sk_r2(y[ok], np.exp(sel.models[kind].predict(z[ok])))
        assert scores[kind] == pytest.approx(expected, rel=1e-12)
    assert scores["gp"] > scores["rbf10"]
    lo, hi = r2_interval(y[ok], np.exp(sel.model.predict(z[ok])))
    assert lo < scores[sel.chosen] < hi
