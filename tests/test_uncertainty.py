"""Input ranges (the core's ranges file) and the Morris screening on the linearised vehicle."""

from pathlib import Path

import numpy as np
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
