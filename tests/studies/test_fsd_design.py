"""The FSD design study: its plumbing on a tiny case, the constraint NSGA-II uses, and
the conicity sweep's wheels measured by the core's EN 15302 equivalent conicity."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

import loco
from loco import dampers, profiles
from loco.conicity import equivalent_conicity
from loco.studies import fsd_conicity, fsd_search

#: 300 m without lead-in: the shortest record the metrics take at 200 km/h.
SETUP = fsd_search.DesignSetup(distance=300.0, lead_in=0.0, threads=2)
SPEC_FSD = [200e3, 800e3, 2.0, 0.05, dampers.REFERENCE_STROKE_AMPLITUDE]
#: YD1-like damping in both valve states: the linear critical speed on S_high is YD1's 123 km/h,
#: below 1.1 x 200 km/h.
SOFT = [150e3, 200e3, 2.0, 0.05, 1e-3]


@pytest.fixture(scope="module")
def evaluated() -> pd.DataFrame:
    return fsd_search.evaluate_designs(np.array([SPEC_FSD, SOFT]), SETUP)


def test_designs_are_simulated_as_the_hydraulic_fsd(evaluated: pd.DataFrame) -> None:
    assert list(evaluated.columns) == [*fsd_search.VARIABLES, *fsd_search.RESULT_COLUMNS]
    # The spec's design vector is the preset FSD-H: the same runs give the same numbers.
    law = fsd_search.design_damper(SPEC_FSD)
    assert dampers.describe(law) == dampers.describe(dampers.FSD_HYDRAULIC)
    s = loco.Scenario(name="S_low", speed=200 / 3.6, distance=300.0, yaw_damper=law)
    wy = loco.simulate(loco.Locomotive.default(), s).metrics["wy_max"]
    assert evaluated.loc[0, "W_y"] == wy
    high = loco.Scenario(name="S_high", speed=200 / 3.6, distance=100.0, yaw_damper=law)
    v = loco.critical_speed(loco.Locomotive.default(), high, high=fsd_search.SEARCH_HIGH)
    assert evaluated.loc[0, "v_crit_kmh"] == pytest.approx(float(v) * 3.6)


def test_a_design_below_the_critical_speed_margin_is_infeasible(evaluated: pd.DataFrame) -> None:
    limit = fsd_search.SPEED_MARGIN * SETUP.speed_kmh
    g = fsd_search.constraint(evaluated, SETUP)
    # The spec's FSD (closed valve: 285 km/h on S_high) holds; the soft design (YD1's 123 km/h)
    # violates it by the margin it misses, and the flag the front is filtered by says so.
    assert evaluated.loc[0, "v_crit_kmh"] > limit and g[0] < 0 and evaluated.loc[0, "feasible"]
    assert evaluated.loc[1, "v_crit_kmh"] < limit and not evaluated.loc[1, "feasible"]
    assert g[1] == pytest.approx(limit - evaluated.loc[1, "v_crit_kmh"])
    # A failed run or an underivable valve (NaN) counts as infeasible too.
    broken = evaluated.copy()
    broken.loc[0, "A_yb"] = np.nan
    assert fsd_search.constraint(broken, SETUP)[0] > 0


def test_non_dominated_and_picks() -> None:
    frame = pd.DataFrame({"W_y": [1.0, 2.0, 1.5, 1.2, 3.0], "A_yb": [3.0, 1.0, 1.5, 3.5, 0.9]})
    front = fsd_search.non_dominated(frame)
    assert front[["W_y", "A_yb"]].values.tolist() == [[1.0, 3.0], [1.5, 1.5], [2.0, 1.0],
                                                      [3.0, 0.9]]  # fmt: skip
    picks = fsd_search.pick_designs(front)
    assert picks["opt. FSD (low W_y)"] == 0 and picks["opt. FSD (low A_yb)"] == 3
    assert picks["opt. FSD (knee)"] == 1


def test_underivable_valve_is_an_infeasible_design() -> None:
    # c1 above c2: the core refuses the FSD naming the field (the bounds keep NSGA-II's designs
    # clear of it, a hand-given design is not).
    bad = [900e3, 600e3, 2.0, 0.05, 1e-3]
    with pytest.raises(loco.ParameterError, match="damping"):
        fsd_search.design_damper(bad)
    frame = fsd_search.evaluate_designs(np.array([bad]), SETUP)
    assert frame.loc[0, "error"] and not frame.loc[0, "feasible"]
    assert np.isnan(frame.loc[0, "W_y"])


@pytest.mark.slow
def test_nsga2_plumbing_on_a_tiny_case(monkeypatch: pytest.MonkeyPatch) -> None:
    """The whole loop with pymoo (2 generations of 4): every evaluated design is logged with its
    generation, and the front holds only feasible, non-dominated designs."""
    result = fsd_search.run_design_study(SETUP, pop_size=4, n_gen=2, seed=3)
    pop = result.population
    assert len(pop) == 8 and sorted(set(pop["generation"])) == [0, 1]
    bounds = np.array(list(fsd_search.VARIABLES.values()))
    x = pop[list(fsd_search.VARIABLES)].to_numpy()
    assert np.all((x >= bounds[:, 0]) & (x <= bounds[:, 1]))
    assert result.front["feasible"].all()
    assert len(result.front) == len(fsd_search.non_dominated(pop[pop["feasible"]]))
    assert set(result.picks.values()) <= set(range(len(result.front)))


def test_sweep_cases_run_in_parallel_keep_their_numbers() -> None:
    """The sweep runs its cases side by side: the numbers are those of each case run on its own
    (track 0: a single run of the seed), the same for one thread or two."""
    laws = {"YD1": dampers.YD1, "FSD-H": dampers.FSD_HYDRAULIC}
    args = {"speed_kmh": 200.0, "distance": 300.0, "lead_in": 0.0, "seed": 5, "n_tracks": 2}
    sweep = fsd_conicity.run_conicity_sweep(laws, [0.3], threads=2, **args)
    assert len(sweep) == 4 and (sweep["status"] == 0).all()
    serial = fsd_conicity.run_conicity_sweep(laws, [0.3], threads=1, **args)
    pd.testing.assert_frame_equal(sweep, serial)
    s = loco.Scenario(
        name="S_norm", speed=200 / 3.6, distance=300.0, lead_in=0.0, seed=5, yaw_damper="YD1"
    ).replace(name=None, wheel=fsd_conicity.conicity_wheel(0.3), rail="cn60")
    alone = loco.simulate(loco.Locomotive.default(), s)
    first = sweep[(sweep["damper"] == "YD1") & (sweep["track"] == 0)].iloc[0]
    assert first["ayb_peak_lp"] == alone.metrics["ayb_peak_lp"]
    assert first["wy_max"] == alone.metrics["wy_max"]


@pytest.mark.parametrize("target", [0.02, 0.05, 0.1, 0.25, 0.3, 0.45, fsd_conicity.MAX_CONICITY])
def test_sweep_wheels_have_the_requested_conicity(target: float) -> None:
    wheel = fsd_conicity.conicity_wheel(target)
    measured = equivalent_conicity(wheel, fsd_conicity.RAIL, fsd_conicity.AMPLITUDE)
    # Cones: Δr = 2λy exactly (EN 15302 integrates it); worn band: the bisection's tolerance.
    assert measured == pytest.approx(target, abs=fsd_conicity.CONICITY_TOLERANCE)


def test_cone_conicity_holds_at_every_amplitude() -> None:
    # Independent of the 3 mm the sweep is set at: a cone's conicity is its slope.
    cone = profiles.jm3(0.15, math.inf)
    for amplitude in (0.001, 0.003, 0.005):
        assert equivalent_conicity(cone, "cn60", amplitude) == pytest.approx(0.15, abs=1e-3)


def test_conicity_outside_the_families_is_refused() -> None:
    for bad in (0.01, 0.66, 0.7, float("nan")):  # 0.66: in the worn family's jump
        with pytest.raises(loco.ParameterError, match="conicity"):
            fsd_conicity.conicity_wheel(bad)
    with pytest.raises(loco.ParameterError, match="band_radius"):
        profiles.jm3(0.1, 0.05)
    with pytest.raises(loco.ParameterError, match="tread_slope"):
        profiles.jm3(0.5, math.inf)
