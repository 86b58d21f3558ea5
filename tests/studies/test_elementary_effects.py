"""Morris elementary effects with missing outputs, against SALib where none is missing."""

import numpy as np
from SALib.analyze import morris as salib_analyze
from SALib.sample import morris as salib_sample

from loco.elementary_effects import elementary_effects

PROBLEM = {"num_vars": 3, "names": ["a", "b", "c"], "bounds": [[0.0, 2.0], [1.0, 5.0], [-1.0, 1.0]]}


def model(x: np.ndarray) -> np.ndarray:
    return 3.0 * x[:, 0] + x[:, 1] ** 2 + 0.1 * x[:, 0] * x[:, 2]


def test_complete_trajectories_give_salib_s_statistics() -> None:
    x = salib_sample.sample(PROBLEM, 12, num_levels=4, seed=3)
    y = model(x)
    ours = elementary_effects(x, y, [0, 1, -1], [2, 5, 1], PROBLEM["names"]).set_index("input")
    theirs = salib_analyze.analyze(PROBLEM, x, y, num_levels=4, seed=3, print_to_console=False)
    np.testing.assert_allclose(ours["mu_star"], theirs["mu_star"], rtol=1e-12)
    np.testing.assert_allclose(ours["mu"], theirs["mu"], rtol=1e-12)
    np.testing.assert_allclose(ours["sigma"], theirs["sigma"], rtol=1e-12)
    assert (ours["effects"] == 12).all()
    # The nearly linear input: 3 + 0.1·c per unit over a range of 2.
    assert abs(ours.loc["a", "mu_star"] - 6.0) < 0.2


def test_a_missing_output_loses_only_the_steps_that_touch_it() -> None:
    x = salib_sample.sample(PROBLEM, 12, num_levels=4, seed=3)
    y = model(x)
    y[5] = np.nan  # the second point of the second trajectory
    ours = elementary_effects(x, y, [0, 1, -1], [2, 5, 1], PROBLEM["names"])
    assert ours["effects"].sum() == 12 * 3 - 2
    assert np.isfinite(ours["mu_star"]).all()
