"""The bogie mass m⁺ of the EN 14363 stability limit: computed from the bodies a bogie carries
(summed here from the parameters by hand), stated by a vehicle file or an override instead, and
the limit of a run's metrics follows it."""

from __future__ import annotations

import pytest

import loco
from loco.channels import Metric

KEY = "assessment.bogie_mass"


def _limit(vehicle: loco.Locomotive) -> float:
    scenario = loco.Scenario(name="S_norm", speed=200 / 3.6, distance=320.0, track="perfect")
    return loco.simulate(vehicle, scenario).metrics[Metric.AYB_EN_LIMIT]


def test_the_bogie_is_its_frame_wheelsets_axle_boxes_motors_and_hollow_shafts() -> None:
    v = loco.Locomotive.default()
    by_hand = (
        v["bogie_frame.mass"]
        + 2 * v["wheelset.mass"]
        + 4 * v["rotary_arm.mass"]
        + 2 * v["traction_motor.mass"]
        + 2 * v["hollow_shaft.mass"]
    )
    assert v.en14363_bogie_mass() == by_hand
    assert _limit(v) == pytest.approx((12.0 - by_hand / 1e3 / 5.0) / 2.0, rel=1e-12)
    with pytest.raises(loco.ParameterError, match="optional and not given by this vehicle"):
        v[KEY]


def test_a_vehicle_file_or_an_override_states_it() -> None:
    text = loco.Locomotive.default().default_toml() + (
        '\n[assessment]\nbogie_mass = { value = 12.0, unit = "t", source = "weighed" }\n'
    )
    stated = loco.Locomotive(toml_text=text, origin="stated.toml")
    assert stated.en14363_bogie_mass() == 12_000.0 and stated[KEY] == 12_000.0
    assert _limit(stated) == pytest.approx((12.0 - 12.0 / 5.0) / 2.0, rel=1e-12)
    override = loco.Locomotive.default().replace({KEY: 8000.0})
    assert override.en14363_bogie_mass() == 8000.0
    with pytest.raises(loco.ParameterRangeError, match=KEY):
        loco.Locomotive.default().replace({KEY: 100.0})
