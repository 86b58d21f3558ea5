"""Eigenvalues about equilibrium agree with the time-domain behaviour of the same model; the
nonlinear critical speed of a ramp-down against the linear one."""

import math
import re

import numpy as np
import pytest

import loco
import loco.conicity
from verification_records import record


def test_hunting_mode_loses_damping_with_speed_and_weak_yaw_dampers() -> None:
    vehicle = loco.Locomotive.default()
    slow = loco.eigen(
        vehicle, loco.Scenario(name="S_high", speed=80 / 3.6, yaw_damper=loco.dampers.YD1)
    )
    fast = loco.eigen(
        vehicle, loco.Scenario(name="S_high", speed=300 / 3.6, yaw_damper=loco.dampers.YD1)
    )
    assert slow.least_damped().damping_ratio > 0.0
    hunting = fast.least_damped()
    # Worn wheels with YD1 hunt at 300 km/h; the time simulation shows the bogie frame's
    # dominant frequency near 4 Hz.
    assert hunting.damping_ratio < 0.0
    assert 2.0 < hunting.frequency < 7.0
    assert "least" not in hunting.describe()


def test_critical_speed_rises_with_the_stiffer_yaw_damper() -> None:
    vehicle = loco.Locomotive.default()
    yd1 = loco.critical_speed(
        vehicle, loco.Scenario(name="S_high", yaw_damper=loco.dampers.YD1), tolerance=2.0
    )
    yd2 = loco.critical_speed(
        vehicle, loco.Scenario(name="S_high", yaw_damper=loco.dampers.YD2), tolerance=2.0
    )
    assert 20.0 < yd1 < 300 / 3.6
    assert yd2 > yd1
    (
        record("stability_yd1_yd2", __file__)
        .value("yd1", yd1, "m/s", 3)
        .value("yd2", yd2, "m/s", 3)
        .value("bisection_tolerance", 2.0, "m/s", 1)
        .check()
    )


def test_linear_critical_speed_brackets_the_loss_of_damping_of_eigen() -> None:
    # The core's bisection (its own eigenvalue solver) agrees with numpy's eigenvalues: the
    # least damped mode is damped just below the result and undamped just above it.
    vehicle = loco.Locomotive.default()
    scenario = loco.Scenario(name="S_high", yaw_damper=loco.dampers.YD1)
    speed = loco.critical_speed(vehicle, scenario, tolerance=0.5)
    assert 20.0 < speed < 110.0
    for offset, stable in ((-0.5, True), (0.5, False)):
        at = loco.eigen(vehicle, scenario.replace(speed=speed + offset))
        assert (at.least_damped().damping_ratio > 0.0) == stable, offset
    assert speed.found and speed.outcome == "found"
    # Not found below the search limit: said so, not only an `inf`.
    above = loco.critical_speed(vehicle, scenario, high=25.0)
    assert math.isinf(above) and not above.found and above.outcome == "stable_at_high"
    assert above.limit == 25.0
    assert "no linear critical speed found up to the search limit 25.00 m/s" in above.reason
    below = loco.critical_speed(vehicle, scenario, low=100.0, high=110.0)
    assert below == 100.0 and not below.found and below.outcome == "unstable_at_low"
    assert "already unstable at the lowest searched speed 100.00 m/s" in below.reason


def test_a_tolerance_below_the_float_spacing_ends_at_the_float_resolution() -> None:
    # Once a hang: halving a bracket of adjacent floats gives one of its ends, which never
    # shrinks it below 1e-300. The search ends where the bracket cannot shrink any more.
    vehicle = loco.Locomotive.default()
    scenario = loco.Scenario(name="S_high", yaw_damper=loco.dampers.YD1)
    exact = loco.critical_speed(vehicle, scenario, tolerance=1e-300)
    coarse = loco.critical_speed(vehicle, scenario, tolerance=1e-6)
    assert exact.found and abs(exact - coarse) < 1e-6


def test_nonlinear_critical_speed_is_at_or_below_the_linear_one() -> None:
    # Worn wheels hunt subcritically: after a disturbance well above the linear critical speed
    # the limit cycle survives below it, so a ramp-down loses it at or below that speed.
    vehicle = loco.Locomotive.default()
    scenario = loco.Scenario(name="S_high", yaw_damper=loco.dampers.YD1)
    linear = loco.critical_speed(vehicle, scenario, tolerance=2.0)
    assert 20.0 < linear < 100.0
    start = scenario.replace(speed=1.3 * linear)
    nonlinear = loco.critical_speed(
        vehicle, start, low=0.4 * linear, method="nonlinear", deceleration=1.0
    )
    assert 0.4 * linear < nonlinear <= linear + 2.0
    if nonlinear < linear - 2.0:
        # Where the cycle dies the equilibrium is linearly stable.
        at = loco.eigen(vehicle, scenario.replace(speed=nonlinear))
        assert at.least_damped().damping_ratio > 0.0


def test_ramp_down_reports_its_record_and_checks_its_inputs() -> None:
    vehicle = loco.Locomotive.default()
    slow = loco.Scenario(name="S_high", yaw_damper=loco.dampers.YD2, speed=30.0)
    ramp = loco.stability.ramp_down(vehicle, slow, end_speed=25.0)
    # Stiff yaw dampers at 30 m/s: the disturbance dies during the hold, no ramp is needed.
    assert ramp.outcome == "stable_at_start"
    assert math.isinf(ramp.critical_speed)
    assert len(ramp.speed) == len(ramp.amplitude) > 0
    assert ramp.amplitude[0] > ramp.amplitude[-1]
    assert np.all(ramp.speed == 30.0)
    with pytest.raises(loco.ParameterError, match="deceleration"):
        loco.stability.ramp_down(vehicle, slow, deceleration=-1.0)
    with pytest.raises(loco.ParameterError, match="end_speed"):
        loco.stability.ramp_down(vehicle, slow, end_speed=40.0)
    with pytest.raises(loco.ParameterError, match="method"):
        loco.critical_speed(vehicle, slow, method="quadratic")


def test_linear_critical_speed_falls_as_the_conicity_rises() -> None:
    vehicle = loco.Locomotive.default()
    scenario = loco.Scenario(name="S_high", yaw_damper=loco.dampers.YD1)
    speeds = [
        loco.critical_speed(vehicle, scenario, conicity=c, tolerance=1.0, high=400 / 3.6)
        for c in (0.05, 0.2, 0.4)
    ]
    assert all(math.isfinite(v) for v in speeds), speeds
    # Each step beyond the bisection tolerance (1 m/s).
    assert speeds[0] - speeds[1] > 2.0 and speeds[1] - speeds[2] > 2.0, speeds
    # The pair stands for its conicity: EN 15302 on the generated profiles gives it back.
    wheel, rail = loco._loco.conical_profiles(0.2)
    assert loco.conicity.equivalent_conicity(wheel, rail) == pytest.approx(0.2, rel=0.02)
    with pytest.raises(loco.ParameterError, match="conicity"):
        loco.eigen(vehicle, scenario, conicity=-0.1)
    with pytest.raises(loco.ParameterError, match="conicity"):
        loco.critical_speed(vehicle, scenario, method="nonlinear", conicity=0.2)


def test_the_ramp_down_docstring_states_what_the_ramps_give() -> None:
    # The example of `ramp_down`'s documentation, rerun: three ramps of about a second each.
    doc = " ".join((loco.stability.ramp_down.__doc__ or "").split())
    found = re.search(
        r"S_high with YD1, linear critical speed ([\d.]+) m/s: ([\d.]+), ([\d.]+) and ([\d.]+) "
        r"m/s at ([\d.]+), ([\d.]+) and ([\d.]+) m/s² from ([\d.]+) times that",
        doc,
    )
    assert found, doc
    stated = found.groups()
    vehicle = loco.Locomotive.default()
    scenario = loco.Scenario(name="S_high", speed=200 / 3.6, yaw_damper="YD1")
    linear = float(loco.critical_speed(vehicle, scenario, method="linear"))
    assert f"{linear:.1f}" == stated[0]
    start = loco.Scenario(name="S_high", speed=float(stated[7]) * linear, yaw_damper="YD1")
    for speed, deceleration in zip(stated[1:4], stated[4:7], strict=True):
        ramp = loco.stability.ramp_down(vehicle, start, deceleration=float(deceleration))
        assert ramp.outcome == "died_out"
        assert f"{ramp.critical_speed:.1f}" == speed, deceleration
        # Below the linear critical speed, by the deceleration times a few seconds.
        assert 0.0 < linear - ramp.critical_speed < 4.0 * float(deceleration)
