"""The vehicle API: parameters with sources, overrides, input checks, one simulated run."""

import math
import pickle
from pathlib import Path

import numpy as np
import pytest

import loco


def test_default_vehicle_parameters_have_sources_and_units() -> None:
    params = loco.Locomotive.default().parameters()
    assert params["carbody.mass"].value == 42e3
    assert params["secondary.yaw_damper_damping"].value == 800e3
    for p in params.values():
        assert p.source.strip() and p.unit.strip(), p.name
    assert len(loco.vehicle.dof_names()) == 90
    assert len(loco.vehicle.body_names()) == 25
    assert loco.Locomotive.default().total_mass() == pytest.approx(75_418.0)


def test_overrides_by_key_and_study_alias() -> None:
    base = loco.Locomotive.default()
    soft = base.replace(C_sx=2e5, K_py=5e6)
    assert soft["secondary.yaw_damper_damping"] == 2e5
    assert soft["K_py"] == 5e6
    assert base["C_sx"] == 800e3  # immutable
    other = base.replace({"carbody.cog_height": 1.8})
    assert other["carbody.cog_height"] == 1.8


@pytest.mark.parametrize(
    ("overrides", "name"),
    [
        ({"bogie_frame.mass": -1.0}, "bogie_frame.mass"),
        ({"K_px": math.nan}, "K_px"),
        ({"secondary.no_such_thing": 1.0}, "secondary.no_such_thing"),
    ],
)
def test_non_physical_parameters_are_refused_by_name(overrides: dict, name: str) -> None:
    with pytest.raises(loco.ParameterError, match=name):
        loco.Locomotive(overrides=overrides)


def test_bad_scenarios_raise_typed_errors() -> None:
    vehicle = loco.Locomotive.default()
    with pytest.raises(loco.ParameterError, match="speed"):
        loco.simulate(vehicle, loco.Scenario(name="S_high", speed=0.0, distance=50.0))
    with pytest.raises(loco.ParameterError, match="speed"):
        loco.simulate(vehicle, loco.Scenario(name="S_high", speed=200.0, distance=50.0))
    with pytest.raises(loco.ParameterError, match="scenario"):
        loco.simulate(vehicle, loco.Scenario(name="S_nope"))


def test_short_run_on_perfect_track_returns_channels() -> None:
    scenario = loco.Scenario(name="S_norm", speed=50.0, distance=40.0, track="perfect")
    result = loco.simulate(loco.Locomotive.default(), scenario)
    assert result.channels.shape == (len(result.channel_names), result.time.size)
    assert result.time[1] - result.time[0] == pytest.approx(1 / 500)
    assert np.max(np.abs(result.channel("wheelset1_y"))) < 1e-9
    # Under one 5 s Sperling segment the metrics are undefined, not invented.
    assert math.isnan(result.metrics["wy_max"])
    ds = result.to_xarray()
    assert "frame1_ay_wheelset1" in ds
    # Run statistics: 0.8 s at the default 2 ms step, four stages a step plus the static search.
    stats = result.statistics
    assert list(stats) == loco.simulation.RUN_STATISTICS
    assert stats["steps"] == 400
    assert stats["newton_iterations"] >= 1
    assert stats["rhs_evaluations"] > 4 * stats["steps"] + 90 * stats["newton_iterations"]
    assert stats["wall_time"] > 0.0
    assert repr(result).startswith("SimulationResult(0.800 s at 500 Hz, ")
    with pytest.raises(loco.ParameterError, match="no channel"):
        result.channel("nothing")


def test_an_output_rate_between_whole_steps_shortens_the_step() -> None:
    # 400 Hz at the default 2 ms is 1.25 steps per sample: two steps of 1.25 ms, not one of
    # 2.5 ms beyond the step the stability check passed.
    scenario = loco.Scenario(
        name="S_norm", speed=50.0, distance=40.0, track="perfect", output_rate=400.0
    )
    result = loco.simulate(loco.Locomotive.default(), scenario)
    assert result.time[1] - result.time[0] == pytest.approx(1 / 400)
    assert result.statistics["steps"] == 2 * (result.time.size - 1)


def test_full_run_gives_metrics_and_fsd_valve_state() -> None:
    scenario = loco.Scenario(
        name="S_high", speed=200 / 3.6, distance=300.0, seed=3, yaw_damper=loco.dampers.FSD
    )
    result = loco.simulate(loco.Locomotive.default(), scenario)
    assert 0.5 < result.metrics["wy_max"] < 5.0
    assert result.metrics["ayb_peak_lp"] > 0.0
    valve = result.channel("yaw_damper_bogie1_left_valve")
    assert np.all((valve >= 0.0) & (valve <= 1.0))


def test_vehicle_from_a_parameter_file(tmp_path: Path) -> None:
    text = loco.Locomotive.default().default_toml()
    old = 'mass = { value = 42000.0, unit = "kg", source = "SPEC §1'
    assert old in text
    path = tmp_path / "heavier.toml"
    path.write_text(text.replace("value = 42000.0", "value = 44000.0", 1), encoding="utf-8")
    vehicle = loco.Locomotive.from_toml(path)
    assert vehicle["carbody.mass"] == 44000.0
    assert vehicle.total_mass() == pytest.approx(loco.Locomotive.default().total_mass() + 2000.0)
    path.write_text(text.replace("value = 42000.0", "value = -1.0", 1), encoding="utf-8")
    with pytest.raises(loco.ParameterError, match=r"carbody\.mass"):
        loco.Locomotive.from_toml(path)
    path.write_text("[carbody]\nmass = { value = 1.0, unit = 'kg' }\n", encoding="utf-8")
    with pytest.raises(loco.ParameterError, match=r"heavier\.toml:2: .*`carbody\.mass`.*source"):
        loco.Locomotive.from_toml(path)
    path.write_text("[carbody\n", encoding="utf-8")
    with pytest.raises(loco.VehicleFormatError, match=r"heavier\.toml:1"):
        loco.Locomotive.from_toml(path)
    with pytest.raises(loco.LocoIOError):
        loco.Locomotive.from_toml(tmp_path / "missing.toml")


@pytest.mark.parametrize(
    ("value", "given"),
    [('"44000.0"', 'string "44000.0"'), ("true", "boolean true"), ("[44000.0]", "array")],
)
def test_a_file_value_of_the_wrong_type_names_the_key_and_line(
    tmp_path: Path, value: str, given: str
) -> None:
    text = loco.Locomotive.default().default_toml()
    old = 'mass = { value = 42000.0, unit = "kg"'
    line = text[: text.index(old)].count("\n") + 1
    path = tmp_path / "typed.toml"
    path.write_text(text.replace("value = 42000.0", f"value = {value}", 1), encoding="utf-8")
    with pytest.raises(loco.ParameterError) as raised:
        loco.Locomotive.from_toml(path)
    assert not isinstance(raised.value, loco.ProfileFormatError)
    message = str(raised.value)
    assert message.startswith(f"{path}:{line}: invalid parameter `carbody.mass`"), message
    assert f"`value` must be a number, got {given}" in message, message


def test_lead_in_is_run_but_not_recorded() -> None:
    # 100 m of lead-in at 50 m/s is 2 s = 1000 samples: the recorded 50 m are the last samples of
    # one 150 m run on the same track (the track covers lead-in + distance either way).
    vehicle = loco.Locomotive.default()
    common = {"name": "S_high", "speed": 50.0, "seed": 4, "yaw_damper": loco.dampers.FSD}
    whole = loco.simulate(vehicle, loco.Scenario(distance=150.0, **common))
    tail = loco.simulate(vehicle, loco.Scenario(distance=50.0, lead_in=100.0, **common))
    assert tail.time[0] == 0.0 and len(tail.time) == 501
    for name in ("frame1_ay_wheelset1", "yaw_damper_bogie1_left_valve", "wheel1_left_Q"):
        assert np.array_equal(tail.channel(name), whole.channel(name)[1000:]), name
    with pytest.raises(loco.ParameterError, match="lead_in"):
        loco.simulate(vehicle, loco.Scenario(distance=50.0, lead_in=-1.0, **common))


def test_the_native_handle_is_built_once_and_travels_by_its_file(tmp_path: Path) -> None:
    path = tmp_path / "loco.toml"
    path.write_text(loco.Locomotive.default().default_toml(), encoding="utf-8")
    base = loco.Locomotive.from_toml(path)
    soft = base.replace(C_sx=2e5).replace({"secondary.yaw_damper_damping": 3e5}, K_py=5e6)
    # Overrides merge as in one constructor call (later ones win) and keep the file.
    same = loco.Locomotive(
        base.toml_text, str(path), {"C_sx": 2e5, "K_py": 5e6, "secondary.yaw_damper_damping": 3e5}
    )
    assert soft == same and soft.parameters() == same.parameters()
    assert soft.native["secondary.yaw_damper_damping"] == soft["C_sx"] == 3e5
    assert soft.native.origin == str(path) and soft.native.toml_text == base.toml_text
    for obj in (soft, soft.native):
        back = pickle.loads(pickle.dumps(obj))
        assert repr(back) == repr(obj)
    back = pickle.loads(pickle.dumps(soft))
    assert back.native.parameters_table() == soft.native.parameters_table()
    assert np.array_equal(back.mass_matrix(), soft.mass_matrix())
    with pytest.raises(loco.ParameterError, match="C_sxx"):
        soft["C_sxx"]
    # The handle's run is the run of a vehicle built again from its file and overrides.
    scenario = loco.Scenario(name="S_norm", speed=50.0, distance=10.0, track="perfect")
    a = loco.simulate(soft, scenario)
    b = loco.simulate(back, scenario)
    assert np.array_equal(a.channels, b.channels)
