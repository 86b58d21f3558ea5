"""The curving channels (``loco.wheel_channels()``, ``loco.wheelset_channels()``) against
independent checks: ΣY is the sum of the wheels' Y; ΔQ/Q0 from the weight; the whole vehicle's
ΣY in a steady curve is its mass times the track-plane acceleration (zero at balanced cant,
m·(V²/R·cos θ − g·sin θ) ≈ m·g·d/(2·b0) at cant deficiency d); T·γ is frictional work (never
negative, larger in the curve than on the straight); the flange flag follows the contact angle."""

from __future__ import annotations

import numpy as np
import pytest

import loco
from loco import _loco
from loco.studies import curving

WHEEL = _loco.wheel_channels()
WHEELSET = _loco.wheelset_channels()
VEHICLE = loco.Locomotive.default()
G = VEHICLE["track.gravity"]
TWO_B0 = 2.0 * VEHICLE["track.contact_point_half_distance"]
RADIUS, CANT = 1200.0, 120.0
#: Steady part of the record: the last metres, the whole vehicle on the circular curve.
STEADY = 20.0
CASE = curving.CurveCase(radius_m=RADIUS, cant_mm=CANT, transition_m=120.0, curve_m=400.0)
STRAIGHT = 20.0


def _run(deficiency_mm: float) -> tuple[loco.SimulationResult, float]:
    speed = curving.speed_for_deficiency(RADIUS, CANT, deficiency_mm, VEHICLE)
    scenario = loco.Scenario(
        name="S_norm",
        speed=speed,
        distance=STRAIGHT + CASE.transition_m + 80.0,
        track="perfect",
        curve=CASE.sections(STRAIGHT),
    )
    return loco.simulate(VEHICLE, scenario), speed


@pytest.fixture(scope="module")
def balanced() -> tuple[loco.SimulationResult, float]:
    return _run(0.0)


@pytest.fixture(scope="module")
def deficient() -> tuple[loco.SimulationResult, float]:
    return _run(100.0)


def _steady(result: loco.SimulationResult, speed: float) -> np.ndarray:
    return result.time >= result.time[-1] - STEADY / speed


def _vehicle_sum_y(result: loco.SimulationResult) -> np.ndarray:
    return np.sum([result.channel(c) for c in WHEELSET["sumY"]], axis=0)


def test_the_channel_tables_name_recorded_channels(deficient: tuple) -> None:
    result, _ = deficient
    names = set(result.channel_names)
    for table in (WHEEL, WHEELSET):
        for quantity, channels in table.items():
            assert len(channels) == (8 if table is WHEEL else 4), quantity
            assert set(channels) <= names, quantity
    assert 0.5 < _loco.flange_contact_angle() < 1.2


def test_sum_y_is_the_sum_of_the_wheel_forces(deficient: tuple) -> None:
    result, _ = deficient
    for w, name in enumerate(WHEELSET["sumY"]):
        left, right = (result.channel(WHEEL["Y"][2 * w + side]) for side in range(2))
        np.testing.assert_array_equal(result.channel(name), left + right)


def test_unloading_is_relative_to_the_mean_static_wheel_load(deficient: tuple) -> None:
    result, _ = deficient
    q0 = VEHICLE.total_mass() * G / 8.0
    for q, dqq in zip(WHEEL["Q"], WHEEL["dQQ"], strict=True):
        np.testing.assert_allclose(result.channel(dqq), (q0 - result.channel(q)) / q0, atol=1e-12)


def test_balanced_cant_puts_no_lateral_force_on_the_vehicle(balanced: tuple) -> None:
    """At zero cant deficiency gravity on the cant balances the centripetal force: the rails'
    net track-plane force on the vehicle is m times the track-plane acceleration, < 0.01 m/s²
    (the balanced-cant bound on the carbody acceleration)."""
    result, speed = balanced
    total = _vehicle_sum_y(result)[_steady(result, speed)]
    assert np.abs(total).max() < VEHICLE.total_mass() * 0.01


def test_cant_deficiency_force_is_mass_times_the_uncompensated_acceleration(
    deficient: tuple,
) -> None:
    """At 100 mm deficiency the rails push the vehicle toward the centre of the (left) curve by
    m·(V²/R·cos θ − g·sin θ), θ = atan(c/2b0); with V² = g·R·(c + d)/(2·b0) that is
    m·g·cos θ·d/(2·b0) = 49.4 kN (cos θ = 0.9968 at 120 mm); within 2 %."""
    result, speed = deficient
    theta = np.arctan(CANT * 1e-3 / TWO_B0)
    expected = VEHICLE.total_mass() * (speed**2 / RADIUS * np.cos(theta) - G * np.sin(theta))
    hand = VEHICLE.total_mass() * G * 0.1 / TWO_B0
    assert expected == pytest.approx(hand * np.cos(theta), rel=1e-12)
    total = float(np.median(_vehicle_sum_y(result)[_steady(result, speed)]))
    assert total == pytest.approx(expected, rel=0.02)


def test_wear_number_is_frictional_work(balanced: tuple, deficient: tuple) -> None:
    """T·γ = −(Fx ξ + Fy η + Mz φ) is the frictional work of the creep forces: never negative.
    On the straight the centred wheelsets only spin on the coned treads (φ = sin γ / r), the
    same on every wheel; in the curve the wheelsets creep to steer, the flanging wheel most:
    more than ten times the straight's."""
    for result, speed in (balanced, deficient):
        straight = result.time * speed < STRAIGHT  # the leading wheelset, so all, on the straight
        steady = _steady(result, speed)
        values = np.array([result.channel(c) for c in WHEEL["Tgamma"]])
        assert values.min() >= -1e-9 * np.abs(values).max()
        on_straight = values[:, straight]
        assert on_straight.max() - on_straight.min() < 0.01 * on_straight.max()
        assert values[:, steady].max() > 10.0 * on_straight.max()


def test_flange_flag_follows_the_contact_angle(deficient: tuple) -> None:
    result, _ = deficient
    limit = _loco.flange_contact_angle()
    for flag, angle in zip(WHEEL["flange"], WHEEL["contact_angle"], strict=True):
        # An unloaded wheel's contact angle channel is 0, so no flag either.
        expected = result.channel(angle) > limit
        np.testing.assert_array_equal(result.channel(flag) == 1.0, expected)
        assert set(np.unique(result.channel(flag))) <= {0.0, 1.0}
