"""The RBF network of SPEC §6.3 on smooth functions of six variables."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import numpy.typing as npt
import pytest

from loco.studies.parameters import StudyParameter, bounds_si
from loco.studies.rbf_network import (
    RBFNetwork,
    cross_validate,
    fit_per_output,
    parity_plot,
    r2_score,
    surrogate_evaluator,
)
from loco.studies.sampling import latin_hypercube

BOX = [StudyParameter(f"x{i}", 0.0, 1.0, "-", "-", 1.0) for i in range(6)]


def smooth(x: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """A smooth, non-additive function of six inputs on [0, 1]^6."""
    return (
        np.exp(-np.sum((x - 0.3) ** 2, axis=1))
        + 0.5 * x[:, 0] * x[:, 1]
        + np.sin(2.0 * x[:, 2])
        + 0.3 * x[:, 3] ** 2
        + 0.2 * x[:, 4]
        - 0.1 * x[:, 5]
    )


def test_r2_score() -> None:
    y = np.array([1.0, 2.0, 3.0, 4.0])
    assert r2_score(y, y)[0] == 1.0
    assert r2_score(y, np.full(4, y.mean()))[0] == 0.0


def test_recovers_smooth_function_with_enough_centres() -> None:
    x = latin_hypercube(400, BOX, seed=1)
    x_test = latin_hypercube(1000, BOX, seed=2)
    model = RBFNetwork(40, bounds=bounds_si(BOX), seed=0).fit(x, smooth(x))
    assert model.centres_.shape == (40, 6)
    assert model.score(x_test, smooth(x_test))[0] > 0.99
    # Ten centres (the spec's network) on 200 samples: good but not exact for this function.
    x10 = latin_hypercube(200, BOX, seed=1)
    ten = RBFNetwork(10, bounds=bounds_si(BOX), seed=0).fit(x10, smooth(x10))
    r2_ten = ten.score(x_test, smooth(x_test))[0]
    assert 0.75 < r2_ten < model.score(x_test, smooth(x_test))[0]


def test_width_rules_and_selection() -> None:
    x = latin_hypercube(200, BOX, seed=3)
    x_test = latin_hypercube(500, BOX, seed=4)
    scores = {}
    for factor in (0.5, 1.0, 2.0, 4.0, 8.0):
        net = RBFNetwork(20, width_factor=factor, seed=0).fit(x, smooth(x))
        scores[factor] = net.score(x_test, smooth(x_test))[0]
    chosen = RBFNetwork(20, seed=0).fit(x, smooth(x))
    # Leave-one-out selection lands within 0.01 of the best candidate on unseen data.
    assert chosen.score(x_test, smooth(x_test))[0] > max(scores.values()) - 0.01
    assert chosen.width_factor_ in scores
    haykin = RBFNetwork(20, width_rule="haykin", width_factor=1.0, seed=0).fit(x, smooth(x))
    centres = haykin.centres_
    d_max = np.max(np.linalg.norm(centres[:, None] - centres[None], axis=2))
    np.testing.assert_allclose(haykin.widths_, d_max / np.sqrt(2 * 20))


def test_deterministic_multi_output_and_nan_rejected() -> None:
    x = latin_hypercube(100, BOX, seed=5)
    y = np.column_stack([smooth(x), x[:, 0] ** 2])
    a = RBFNetwork(10, seed=7).fit(x, y)
    b = RBFNetwork(10, seed=7).fit(x, y)
    np.testing.assert_array_equal(a.predict(x), b.predict(x))
    assert a.predict(x).shape == (100, 2)
    y[3, 0] = np.nan
    with pytest.raises(ValueError, match="finite"):
        RBFNetwork(10).fit(x, y)
    models = fit_per_output(x, y, n_centres=10)
    evaluate = surrogate_evaluator(models, [p.name for p in BOX])
    assert evaluate(x, [p.name for p in BOX]).shape == (100, 2)
    with pytest.raises(ValueError, match="trained on"):
        evaluate(x, ["a", "b", "c", "d", "e", "f"])


def test_cross_validation_and_parity_plot(tmp_path: Path) -> None:
    x = latin_hypercube(200, BOX, seed=6)
    y = smooth(x)
    cv = cross_validate(x, y, n_splits=5, seed=0, n_centres=10)
    assert cv.r2_folds.shape == (5, 1)
    assert cv.predictions.shape == (200, 1)
    assert 0.7 < cv.r2_mean[0] < 1.0
    # The out-of-fold predictions give about the same R² as the fold mean.
    assert abs(r2_score(y, cv.predictions)[0] - cv.r2_mean[0]) < 0.05
    path = parity_plot(y, cv.predictions[:, 0], tmp_path / "parity.png", label="f", unit="-")
    assert path.stat().st_size > 1000
