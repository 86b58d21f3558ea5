"""The selection's fits as independent tasks give, bit for bit, what one plain loop over
candidates and folds gives (the loop below is the selection as it was written before the fits
became tasks), in this process or spread over two."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.stats import qmc
from sklearn.model_selection import KFold
from threadpoolctl import threadpool_limits

from loco.studies.rbf_network import r2_score
from loco.studies.surrogate_fits import Objective, fit_tasks, select_objectives
from loco.studies.surrogate_selection import best_candidate, make_model, nested_selection_r2

BOUNDS = np.array([[0.0, 1.0]] * 6)
KINDS = ("rbf10", "rbf_cv", "gp_sqrt")
SPLITS = 3


def smooth(z: np.ndarray) -> np.ndarray:
    return np.exp(np.sin(2 * np.pi * z[:, 0]) + z[:, 1] * z[:, 2] - z[:, 3] ** 2)


def loop_scores(x: np.ndarray, y: np.ndarray) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """(R² per fold, held-out predictions) of each candidate, one fit after another."""
    out = {}
    splits = KFold(n_splits=SPLITS, shuffle=True, random_state=0).split(x)
    folds = list(splits)
    for kind in KINDS:
        predictions, r2 = np.empty(len(y)), np.empty(SPLITS)
        for i, (train, test) in enumerate(folds):
            model = make_model(kind, BOUNDS, seed=0).fit(x[train], np.log(y[train]))
            predictions[test] = np.exp(model.predict(x[test]))
            r2[i] = float(r2_score(y[test], predictions[test])[0])
        out[kind] = (r2, predictions)
    return out


@pytest.fixture(scope="module")
def data() -> tuple[np.ndarray, np.ndarray]:
    x = qmc.LatinHypercube(d=6, seed=5).random(48)
    return x, np.column_stack([smooth(x), smooth(x[:, ::-1])])


@pytest.mark.slow
@pytest.mark.parametrize("n_jobs", [1, 2])
def test_tasks_give_the_loop_result(data: tuple[np.ndarray, np.ndarray], n_jobs: int) -> None:
    x, y = data
    objectives = [Objective(x, y[:, 0]), Objective(x[1:], y[1:, 1])]
    got = select_objectives(
        objectives, BOUNDS, n_splits=SPLITS, candidates=KINDS, nested=True, n_jobs=n_jobs
    )
    z = qmc.LatinHypercube(d=6, seed=6).random(20)
    with threadpool_limits(limits=1):
        for o, sel in zip(objectives, got, strict=True):
            expected = loop_scores(o.x, o.y)
            for kind in KINDS:
                assert np.array_equal(sel.scores[kind].r2_folds, expected[kind][0])
                assert np.array_equal(sel.scores[kind].predictions, expected[kind][1])
                full = make_model(kind, BOUNDS, seed=0).fit(o.x, np.log(o.y))
                assert np.array_equal(sel.models[kind].predict(z), full.predict(z))
            assert sel.spec_model is sel.models["rbf10"]
            # The nested score: the choice of the inner folds, scored on the outer test fold.
            assert sel.nested is not None
            outer = KFold(n_splits=SPLITS, shuffle=True, random_state=0).split(o.x)
            for i, (train, test) in enumerate(outer):
                inner = loop_scores(o.x[train], o.y[train])
                means = {k: float(v[0].mean()) for k, v in inner.items()}
                best = max(means, key=lambda k: means[k])
                assert sel.nested.chosen[i] == best
                r2 = float(r2_score(o.y[test], sel.scores[best].predictions[test])[0])
                assert sel.nested.r2_folds[i] == r2
            alone = nested_selection_r2(o.x, o.y, BOUNDS, n_splits=SPLITS, candidates=KINDS)
            assert alone.chosen == sel.nested.chosen
            assert np.array_equal(alone.r2_folds, sel.nested.r2_folds)
            assert sel.chosen == best_candidate(sel.scores)


def test_largest_fits_first(data: tuple[np.ndarray, np.ndarray]) -> None:
    x, y = data
    tasks = fit_tasks([Objective(x, y[:, 0])], KINDS, SPLITS, 0, full=True, nested=True)
    assert len(tasks) == len(KINDS) * (SPLITS + 1 + SPLITS**2)
    assert [t.key for t in tasks[:3]] == [(0, "full", "gp_sqrt"), (0, "full", "rbf_cv"),
                                         (0, "cv", "gp_sqrt", 0)]  # fmt: skip
    assert len({t.key for t in tasks}) == len(tasks)
