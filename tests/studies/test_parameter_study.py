"""The parameter study's building blocks: the simulator evaluator of the objectives (the real
simulator, 300 m runs) and the log-target surrogates."""

from __future__ import annotations

import numpy as np
import pytest

import loco
from loco.studies.parameter_study import StudySetup, fit_surrogates, surrogate_objectives
from loco.studies.parameters import STUDY_PARAMETERS, bounds_si, names
from loco.studies.rbf_network import r2_score
from loco.studies.sampling import latin_hypercube
from loco.studies.stages import Runtime


def test_setup_evaluator_at_the_stiff_corner() -> None:
    """The study's simulator evaluator gives W_y on S_low and A_yb on S_high, the runs
    loco.simulate makes on the same track, also at the corner of the SPEC §6 box where the
    secondary lateral damper is stiffest (softest C_sy, stiffest series spring K_ncsy)."""
    x = np.array([[(p.low_si + p.high_si) / 2 for p in STUDY_PARAMETERS]])
    columns = names()
    x[0, columns.index("C_sy")] = STUDY_PARAMETERS[columns.index("C_sy")].low_si
    x[0, columns.index("K_ncsy")] = STUDY_PARAMETERS[columns.index("K_ncsy")].high_si
    setup = StudySetup(distance=300.0, track_seed=1)
    y = setup.evaluator(Runtime(progress=False))(x, columns)
    assert y.shape == (1, 2) and np.isfinite(y).all() and (y > 0).all()
    vehicle = loco.Locomotive.default().replace(dict(zip(columns, x[0], strict=True)))
    for j, (scenario, metric) in enumerate((("S_low", "wy_max"), ("S_high", "ayb_peak_lp"))):
        single = loco.simulate(vehicle, setup.scenario(scenario))
        assert y[0, j] == pytest.approx(single.metrics[metric], rel=1e-9)


def _positive_response(x: np.ndarray) -> np.ndarray:
    """Two positive responses of the unit-scaled inputs u: exp(2.5 (1 - u0) + 0.5 u2), with a
    long tail toward u0 = 0 like A_yb where hunting starts, and 2 + u1 + u3."""
    b = bounds_si()
    u = (x - b[:, 0]) / (b[:, 1] - b[:, 0])
    return np.column_stack([np.exp(2.5 * (1 - u[:, 0]) + 0.5 * u[:, 2]), 2.0 + u[:, 1] + u[:, 3]])


def test_log_target_surrogates() -> None:
    x, x_test = latin_hypercube(120, seed=1), latin_hypercube(400, seed=2)
    y, y_test = _positive_response(x), _positive_response(x_test)
    predicted = surrogate_objectives(fit_surrogates(x, y, seed=0))(x_test, names())
    assert predicted.shape == (400, 2) and (predicted > 0).all()
    r2_log = r2_score(y_test, predicted)
    assert (r2_log > 0.99).all()
    # On the linear scale the 10 Gaussians fit the exponential tail worse.
    linear = surrogate_objectives(fit_surrogates(x, y, log_target=False), log_target=False)
    assert r2_score(y_test, linear(x_test, names()))[0] < r2_log[0]
    # A failed sample (NaN) is left out of its own objective only; the log needs y > 0.
    y_nan = y.copy()
    y_nan[0, 1] = np.nan
    assert len(fit_surrogates(x, y_nan, seed=0)) == 2
    with pytest.raises(ValueError, match="> 0"):
        fit_surrogates(x, -y, seed=0)


def test_setup_scenarios() -> None:
    setup = StudySetup(speed_kmh=180.0, distance=400.0, track_seed=4)
    scenario = setup.scenario("S_low")
    assert scenario.speed == pytest.approx(50.0) and scenario.distance == 400.0
    assert scenario.seed == 4 and scenario.yaw_damper == "file"  # C_sx, K_ncsx act
    assert setup.settings()["objectives"] == {
        "W_y": "wy_max on S_low",
        "A_yb": "ayb_peak_lp on S_high",
    }
