"""The scenario's settings: the core's defaults, one spelling per setting, the shared presets."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import loco
from loco import _loco


def test_defaults_are_the_cores() -> None:
    core = _loco.scenario_defaults()
    defaults = loco.Scenario.defaults()
    # The study's case (SPEC §6): 200 km/h over 500 m, the study rail, the file's yaw damper.
    assert defaults["speed"] == pytest.approx(200 / 3.6, rel=1e-15)
    assert (defaults["distance"], defaults["rail"], defaults["yaw_damper"]) == (
        500.0,
        "cn60",
        "file",
    )
    for name, value in defaults.items():
        assert core[name] == value, name
    s = loco.Scenario()
    for name, value in defaults.items():
        assert getattr(s, name) == value, name


def test_only_the_given_settings_are_kept() -> None:
    s = loco.Scenario(name="S_high", speed=50.0, track=None, band=[3.0, 100.0])
    assert s.given() == {"name": "S_high", "speed": 50.0, "band": (3.0, 100.0)}
    assert repr(s) == "Scenario(name='S_high', speed=50.0, band=(3.0, 100.0))"
    assert s.distance == loco.Scenario.defaults()["distance"]
    changed = s.replace(speed=60.0, band=None)
    assert changed.given() == {"name": "S_high", "speed": 60.0}
    assert changed == loco.Scenario("S_high", speed=60.0) and changed != s
    assert pickle.loads(pickle.dumps(s)) == s
    with pytest.raises(AttributeError):
        s.speed = 3.0  # type: ignore[misc]


@pytest.mark.parametrize(
    ("old", "new"),
    [
        ("perfect_track", 'track="perfect"'),
        ("creep_table", 'creep="table"'),
        ("track_kind", "track="),
        ("scenario", 'name="S_high"'),
    ],
)
def test_replaced_spellings_name_the_new_one(old: str, new: str) -> None:
    with pytest.raises(loco.ParameterError, match=old) as e:
        loco.Scenario(speed=50.0, **{old: "S_high"})  # type: ignore[arg-type]
    assert new in str(e.value)
    with pytest.raises(TypeError, match="spedd"):
        loco.Scenario(name="S_high", spedd=50.0)  # type: ignore[call-arg]


def test_settings_are_checked_by_the_core_naming_the_field() -> None:
    # The study file's rules: no synthesis setting with a perfect track (tests/test_batch_binary
    # checks the same study file is refused by loco-batch).
    with pytest.raises(loco.ParameterError, match="seed"):
        loco.Scenario(name="S_high", track="perfect", seed=3).native()
    with pytest.raises(loco.ParameterError, match="fsd_trigger"):
        loco.Scenario(name="S_high", yaw_damper="YD1", fsd_trigger="hydraulic").native()
    with pytest.raises(loco.ParameterError, match="yaw_damper"):
        loco.Scenario(name="S_high", yaw_damper="fsd").native()
    with pytest.raises(loco.ParameterError, match="`speed`"):
        loco.Scenario(name="S_high", speed="fast").native()  # type: ignore[arg-type]
    with pytest.raises(loco.ParameterError, match="gauge"):
        loco.Scenario(name="S_high", gauge=-1.0).native()
    # One spelling: the core's message names the field as Python and the study file write it.
    with pytest.raises(loco.ParameterError, match=r"`name`.*`name`.*`wheel`"):
        loco.Scenario(name="S_high", wheel="jm3-new").native()
    with pytest.raises(loco.ParameterError, match="`name`: unknown scenario 'S_mid'"):
        loco.Scenario(name="S_mid").native()


def test_presets_are_the_cores() -> None:
    assert loco.simulation.SCENARIOS == {n: (w, r) for n, w, r in _loco.scenario_presets()}
    assert list(loco.dampers.PRESETS) == ["YD1", "YD2", "FSD"]
    assert loco.dampers.label(loco.dampers.FSD_HYDRAULIC) == "FSD-H"


def _run(scenario: loco.Scenario) -> loco.SimulationResult:
    return loco.simulate(loco.Locomotive.default(), scenario)


def test_a_preset_damper_by_name_runs_as_the_damper_object() -> None:
    base = dict(
        name="S_low", speed=50.0, distance=15.0, track="perfect", initial_lateral_offset=3e-3
    )
    by_name = _run(loco.Scenario(**base, yaw_damper="FSD", fsd_trigger="hydraulic"))  # type: ignore[arg-type]
    by_object = _run(loco.Scenario(**base, yaw_damper=loco.dampers.FSD_HYDRAULIC))  # type: ignore[arg-type]
    assert np.array_equal(by_name.channels, by_object.channels)
    default = _run(loco.Scenario(**base))  # type: ignore[arg-type]
    assert not np.array_equal(by_name.channels, default.channels)


def test_track_setup_reaches_the_contact() -> None:
    # A wider gauge moves the rails apart: with the same wheels the flangeway clearance grows and
    # the wheels run on other tread points, so a disturbed run differs; the study's values
    # given explicitly are the defaults bit for bit.
    base = dict(
        name="S_high", speed=50.0, distance=10.0, track="perfect", initial_lateral_offset=3e-3
    )
    default = _run(loco.Scenario(**base))  # type: ignore[arg-type]
    d = loco.Scenario.defaults()
    explicit = _run(
        loco.Scenario(
            **base,  # type: ignore[arg-type]
            gauge=d["gauge"],
            gauge_height=d["gauge_height"],
            rail_inclination=d["rail_inclination"],
        )
    )
    assert np.array_equal(default.channels, explicit.channels)
    for setting in ({"gauge": 1.440}, {"gauge_height": 0.014}, {"rail_inclination": 1 / 20}):
        other = _run(loco.Scenario(**base, **setting))  # type: ignore[arg-type]
        assert not np.array_equal(default.channels, other.channels), setting


def _settings(scenario: loco.Scenario) -> tuple[dict[str, object], list[float]]:
    """What a worker sees of a scenario: its damper's parameters and its wheel's points."""
    assert isinstance(scenario.yaw_damper, _loco.Damper)
    assert isinstance(scenario.wheel, _loco.Profile)
    return scenario.yaw_damper.parameters(), list(scenario.wheel.y)


def test_a_scenario_with_native_dampers_and_profiles_goes_to_a_process_pool() -> None:
    # A new interpreter (spawn) that imported nothing but loco unpickles the damper and the
    # profile: a process pool or a Dask worker needs no import of its own for them.
    import concurrent.futures
    import multiprocessing

    wheel = loco.profiles.jm3(band_radius=float("inf"), tread_slope=0.03)
    scenario = loco.Scenario(yaw_damper=loco.dampers.FSD_HYDRAULIC, wheel=wheel)
    context = multiprocessing.get_context("spawn")
    with concurrent.futures.ProcessPoolExecutor(1, mp_context=context) as pool:
        parameters, y = pool.submit(_settings, scenario).result(timeout=120)
    assert parameters == loco.dampers.FSD_HYDRAULIC.parameters()
    assert y == list(wheel.y)
