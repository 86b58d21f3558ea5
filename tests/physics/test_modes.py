"""Mode descriptions by kinetic energy: the model's mass matrix, absolute body motions."""

import numpy as np
import pytest

import loco
from loco import _loco

BOGIE = ("frames", "wheelsets", "motors", "hollow_shafts", "rotary_arms")


def test_mass_matrix_carries_the_vehicle_mass() -> None:
    vehicle = loco.Locomotive.default()
    m = vehicle.mass_matrix()
    assert np.allclose(m, m.T)
    assert np.linalg.eigvalsh(m).min() > 0.0
    # A rigid lateral shift of the whole vehicle (every free body's y, no relative motion)
    # has the kinetic energy of the total mass.
    names = _loco.dof_names()
    q = np.array([1.0 if n.endswith(".y") else 0.0 for n in names])
    assert q @ m @ q == pytest.approx(vehicle.total_mass(), rel=1e-12)


def test_hunting_mode_of_worn_wheels_is_the_bogies_lateral_and_yaw() -> None:
    # S_high with YD1 near its linear critical speed (39.2 m/s): the least damped mode.
    scenario = loco.Scenario(name="S_high", speed=39.0, yaw_damper=loco.dampers.YD1)
    eigen = loco.eigen(loco.Locomotive.default(), scenario)
    mode = eigen.least_damped()
    assert repr(eigen).startswith(f"Eigen(speed=39 m/s, {len(eigen.modes)} modes, least damped")
    assert repr(mode).startswith(f"Mode({mode.frequency:.3f} Hz, ζ=")
    groups = mode.groups()
    assert sum(groups.values()) == pytest.approx(1.0)
    assert sum(groups[g] for g in BOGIE) > 0.9
    assert groups["carbody"] < 0.1
    motions = mode.motion_shares()
    assert motions["lateral"] + motions["yaw"] > 0.9
    frames = mode.group_motions("frames")
    assert frames["lateral"] + frames["yaw"] > 0.9 and frames["yaw"] > 0.1
    wheelsets = mode.group_motions("wheelsets")
    assert wheelsets["lateral"] + wheelsets["yaw"] > 0.8
    text = mode.describe()
    assert "frames" in text and "lateral" in text


def test_low_conicity_sway_is_carbody_lateral_and_roll() -> None:
    # S_low with the stiff YD2 yaw damper at 200 km/h (SPEC §6): the 1-1.5 Hz mode.
    scenario = loco.Scenario(name="S_low", speed=200 / 3.6, yaw_damper=loco.dampers.YD2)
    mode = loco.eigen(loco.Locomotive.default(), scenario).least_damped(1.0, 1.5)
    groups = mode.groups()
    assert max(groups, key=lambda g: groups[g]) == "carbody"
    assert groups["carbody"] > 0.5
    carbody = mode.motions["carbody"]
    assert carbody["lateral"] + carbody["roll"] > 0.6
    assert carbody["vertical"] + carbody["pitch"] < 0.05
    assert mode.describe().split(": ")[1].startswith("carbody")
