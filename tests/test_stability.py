"""Eigenvalues about equilibrium agree with the time-domain behaviour of the same model."""

import loco


def test_hunting_mode_loses_damping_with_speed_and_weak_yaw_dampers() -> None:
    vehicle = loco.Locomotive.default()
    slow = loco.eigen(
        vehicle, loco.Scenario(scenario="S_high", speed=80 / 3.6, yaw_damper=loco.dampers.YD1)
    )
    fast = loco.eigen(
        vehicle, loco.Scenario(scenario="S_high", speed=200 / 3.6, yaw_damper=loco.dampers.YD1)
    )
    assert slow.least_damped().damping_ratio > 0.0
    hunting = fast.least_damped()
    # Worn wheels with YD1 hunt at 200 km/h; the time simulation shows the bogie frame's
    # dominant frequency near 4 Hz.
    assert hunting.damping_ratio < 0.0
    assert 2.0 < hunting.frequency < 7.0
    assert "least" not in hunting.describe()


def test_critical_speed_rises_with_the_stiffer_yaw_damper() -> None:
    vehicle = loco.Locomotive.default()
    yd1 = loco.critical_speed(
        vehicle, loco.Scenario(scenario="S_high", yaw_damper=loco.dampers.YD1), tolerance=2.0
    )
    yd2 = loco.critical_speed(
        vehicle, loco.Scenario(scenario="S_high", yaw_damper=loco.dampers.YD2), tolerance=2.0
    )
    assert 20.0 < yd1 < 200 / 3.6
    assert yd2 > yd1
