"""Input ranges (the core's ranges file) and the Morris screening on the linearised vehicle."""

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import loco
from loco import uncertainty


def test_ranges_cover_the_estimates_with_reasons_and_contain_the_values() -> None:
    table = uncertainty.ranges()
    assert list(table.columns) == list(uncertainty.RANGE_COLUMNS)
    assert (table["low"] < table["high"]).all()
    assert ((table["low"] <= table["nominal"]) & (table["nominal"] <= table["high"])).all()
    assert set(table["kind"]) == {"tolerance", "scaling", "estimate"}
    by_key = table.set_index("key")
    assert by_key.loc["carbody.mass", "kind"] == "tolerance"
    assert by_key.loc["carbody.roll_inertia", "kind"] == "scaling"
    assert by_key.loc["traction_motor.mass", "kind"] == "estimate"
    assert "scenario.rail_inclination" in by_key.index
    # Overrides move the nominal value and the relative ranges with it.
    soft = uncertainty.ranges(loco.Locomotive.default().replace(C_sx=2e5)).set_index("key")
    assert soft.loc["secondary.yaw_damper_damping", "low"] == pytest.approx(1.8e5)


def test_a_bad_ranges_file_is_refused_naming_key_file_and_line(tmp_path: Path) -> None:
    path = tmp_path / "r.toml"
    path.write_text(
        '[parameters.carbody]\nmass = { low = 5e4, high = 4e4, kind = "estimate", why = "w", '
        'source = "s" }\n',
        encoding="utf-8",
    )
    with pytest.raises(loco.ParameterError, match=r"r.toml:2: .*carbody.mass.*reversed"):
        uncertainty.ranges(file=path)
    with pytest.raises(loco.LocoIOError):
        uncertainty.ranges(file=tmp_path / "missing.toml")


def test_evaluate_at_the_nominal_values_gives_the_modes_of_eigen() -> None:
    table = uncertainty.screened_inputs(uncertainty.ranges(), ["S_low_carbody_zeta_YD2"])
    assert "carbody.floor_height" not in set(table["key"])
    assert "wheel.jm3-worn.band_radius" not in set(table["key"])
    (zeta,) = uncertainty.evaluate(
        loco.Locomotive.default(),
        list(table["key"]),
        list(table["nominal"]),
        ["S_low_carbody_zeta_YD2"],
    )
    scenario = loco.Scenario(name="S_low", speed=uncertainty.SPEED, yaw_damper="YD2")
    assert zeta == pytest.approx(
        loco.eigen(loco.Locomotive.default(), scenario).carbody_mode().damping_ratio, abs=1e-9
    )


def test_morris_ranks_the_carbody_mass_above_a_tiny_tolerance(tmp_path: Path) -> None:
    path = tmp_path / "r.toml"
    path.write_text(
        "[parameters.carbody]\n"
        'mass = { low = 3e4, high = 5.5e4, kind = "estimate", why = "w", source = "s" }\n'
        "[parameters.track]\n"
        'gravity = { low = 9.80, high = 9.811, kind = "tolerance", why = "w", source = "s" }\n',
        encoding="utf-8",
    )
    result = uncertainty.morris(
        outputs=["S_low_carbody_zeta_YD1"], trajectories=2, progress=False, ranges_file=path
    )
    mu = result.set_index("input")["mu_star"]
    assert mu["carbody.mass"] > 10 * mu["track.gravity"]
    assert np.isfinite(result["sigma"]).all()
    with pytest.raises(loco.ParameterError, match="unknown output"):
        uncertainty.morris(outputs=["W_y"], trajectories=2, progress=False)


def test_the_yaw_damper_tolerance_moves_the_presets() -> None:
    # YD1 and YD2 replace the file's damper; its ±10 % tolerance scales the preset instead.
    vehicle = loco.Locomotive.default()
    key = "secondary.yaw_damper_damping"
    outputs = ["S_low_carbody_zeta_YD1", "S_low_carbody_zeta_YD2"]
    low, nominal, high = (
        uncertainty.evaluate(vehicle, [key], [vehicle[key] * f], outputs) for f in (0.9, 1.0, 1.1)
    )
    assert nominal == uncertainty.evaluate(vehicle, [], [], outputs)
    # More damping of the carbody mode's yaw takes damping from it on low conicity.
    assert low[0] > nominal[0] > high[0] and low[1] > nominal[1] > high[1]


def test_a_critical_speed_from_a_guess_matches_the_bisection() -> None:
    vehicle = loco.Locomotive.default()
    scenario = loco.Scenario(name="S_high", speed=uncertainty.SPEED, yaw_damper="YD1")
    bisection = loco.critical_speed(vehicle, scenario)
    for guess in (30.0, float(bisection), 45.0):
        guessed = loco.critical_speed(vehicle, scenario, guess=guess)
        assert guessed.found and abs(guessed - bisection) <= 0.5
    with pytest.raises(loco.ParameterError, match="guess"):
        loco.critical_speed(vehicle, scenario, guess=200.0)


def test_an_infeasible_wheel_corner_is_nan_not_an_error() -> None:
    # Tread slope and band radius are ranged separately; at the steep, tight corner of the worn
    # wheel's ranges the band leaves no room for the JM3 tread: the outputs on that wheel are
    # NaN and the others are computed.
    keys = ["wheel.jm3-worn.band_radius", "wheel.jm3-worn.tread_slope"]
    table = uncertainty.ranges().set_index("key")
    values = [table.loc[keys[0], "low"], table.loc[keys[1], "high"]]
    with pytest.raises(loco.ParameterError, match="segment"):
        loco.profiles.jm3(tread_slope=values[1], band_radius=values[0])
    out = uncertainty.evaluate(
        loco.Locomotive.default(), keys, values, ["S_high_bogie_zeta_YD1", "S_low_carbody_zeta_YD1"]
    )
    assert np.isnan(out[0]) and np.isfinite(out[1])


def test_the_committed_screening_is_what_the_model_gives_now() -> None:
    # docs/screening (scripts/docs/morris_screening.py): the first points of the first trajectory
    # re-evaluated as the screening did them, and the committed table is the analysis of the
    # committed outputs.
    from script_modules import load_script

    script = load_script("morris_screening")
    outputs = list(uncertainty.OUTPUTS)
    results = Path(__file__).parents[2] / "docs" / "screening"
    stored = pd.read_csv(results / "morris_outputs.csv")[outputs].to_numpy()
    x = uncertainty.morris_samples(None, outputs, script.TRAJECTORIES, script.SEED, script.LEVELS)
    table = uncertainty.screened_inputs(uncertainty.ranges(), outputs)
    vehicle = loco.Locomotive.default()
    nominal = uncertainty.evaluate(vehicle, list(table["key"]), list(table["nominal"]), outputs)
    guesses = {n: v for n, v in zip(outputs, nominal, strict=True) if "critical_speed" in n}
    points = [[float(v) for v in row] for row in x[:3]]
    fresh = uncertainty._evaluate_trajectory(
        (vehicle, list(table["key"]), points, outputs, guesses)
    )
    np.testing.assert_allclose(np.array(fresh), stored[:3], rtol=1e-6, equal_nan=True)
    committed = pd.read_csv(results / "morris.csv")
    analysed = uncertainty.analyse(table, x, stored, outputs, script.SEED)
    pd.testing.assert_frame_equal(
        analysed[committed.columns], committed, check_exact=False, rtol=1e-5, check_dtype=False
    )
