"""The carbody and bogie mode rules: the core's rules picking modes of the linearised vehicle."""

import numpy as np
import pytest

import loco
from loco import _loco
from loco.stability import Eigen, mode_rules

V200 = 200 / 3.6


def _eigen(scenario: str, damper: str, **kw: float) -> Eigen:
    return loco.eigen(
        loco.Locomotive.default(), loco.Scenario(name=scenario, speed=V200, yaw_damper=damper), **kw
    )


def test_carbody_mode_on_s_low_is_the_coupled_sway_damped_less_with_high_yaw_damping() -> None:
    yd1 = _eigen("S_low", "YD1").carbody_mode()
    yd2 = _eigen("S_low", "YD2").carbody_mode()
    # The linearised default vehicle at 200 km/h: 1.31 Hz at ζ 0.166 (YD1), 1.18 Hz at 0.031.
    assert yd1.frequency == pytest.approx(1.308, abs=0.01)
    assert yd1.damping_ratio == pytest.approx(0.166, abs=0.003)
    assert yd2.frequency == pytest.approx(1.183, abs=0.01)
    assert yd2.damping_ratio == pytest.approx(0.031, abs=0.003)
    for mode in (yd1, yd2):
        groups = mode.groups()
        assert groups["carbody"] >= 0.3 and groups["wheelsets"] >= 0.02
        # Not the carbody's lower sway on its springs (0.59 Hz, wheelsets at rest).
        assert mode.frequency > 1.0


def test_bogie_mode_on_s_high_is_the_hunting_mode() -> None:
    yd1 = _eigen("S_high", "YD1")
    yd2 = _eigen("S_high", "YD2")
    hunting = yd1.bogie_mode()
    assert hunting is yd1.least_damped()
    assert hunting.damping_ratio < 0.0 < yd2.bogie_mode().damping_ratio
    assert 4.0 < hunting.frequency < 5.0
    assert hunting.groups()["frames"] >= 0.1
    with pytest.raises(loco.ParameterError, match="carbody mode rule"):
        yd1.carbody_mode()


@pytest.mark.parametrize("damping", [100e3, 1000e3])
def test_rules_pick_a_mode_across_conicity_and_yaw_damping(damping: float) -> None:
    vehicle = loco.Locomotive.default().replace(C_sx=damping)
    scenario = loco.Scenario(name="S_low", speed=V200)
    low = loco.eigen(vehicle, scenario, conicity=0.02)
    high = loco.eigen(vehicle, scenario, conicity=0.7)
    carbody = low.carbody_mode()
    # The kinematic frequency falls with the conicity: the carbody mode below 1 Hz at 0.02.
    assert 0.4 < carbody.frequency < 1.0
    assert carbody.groups()["carbody"] >= 0.3
    bogie = high.bogie_mode()
    assert 3.0 < bogie.frequency < 6.0
    assert bogie.groups()["carbody"] <= 0.25
    # Low yaw damping: the bogies hunt on worn wheels, the carbody mode is stable on new ones.
    if damping == 100e3:
        assert bogie.damping_ratio < 0.0 < low.least_damped(2.0, 10.0).damping_ratio


def test_docstrings_state_the_core_rules() -> None:
    rules = mode_rules()
    for name, method in (("carbody", Eigen.carbody_mode), ("bogie", Eigen.bogie_mode)):
        r = rules[name]
        doc = " ".join((method.__doc__ or "").split())
        assert f"{r.band[0]:g}–{r.band[1]:g} Hz" in doc
        assert f"{100 * r.min_wheelset_share:g} % in the wheelsets" in doc
        assert f"{100 * r.min_lateral_share:g} % in lateral, roll and yaw" in doc
    assert "at least 30 % of their kinetic energy in the carbody" in Eigen.carbody_mode.__doc__
    assert "at least 10 % in the bogie" in (Eigen.bogie_mode.__doc__ or "")


def test_select_mode_refuses_unknown_rules_and_mismatched_shapes() -> None:
    one = np.ones(1)
    with pytest.raises(loco.LocoError, match="unknown mode rule `frames`"):
        _loco.select_mode("frames", ["carbody"], one, one, np.ones((1, 1)), np.ones((1, 1, 6)))
    with pytest.raises(loco.LocoError, match="do not agree"):
        _loco.select_mode("bogie", ["carbody"], one, one, np.ones((1, 2)), np.ones((1, 1, 6)))
    assert Eigen(speed=1.0, modes=[]).__class__ is Eigen
    with pytest.raises(loco.ParameterError, match="no modes"):
        Eigen(speed=1.0, modes=[]).bogie_mode()


def test_least_damped_is_the_cores_rule_the_first_of_the_lowest_damping_in_the_band() -> None:
    f = np.array([0.2, 1.0, 3.0, 3.0, 20.0, 25.0])
    z = np.array([-0.5, 0.10, 0.02, 0.02, 0.05, -0.2])
    # Outside 0.3–20 Hz the growing modes do not count; of two equals the first is taken.
    assert _loco.least_damped_mode(f, z, (0.3, 20.0)) == 2
    # The band's edges are inside it.
    assert _loco.least_damped_mode(f, z, (20.0, 25.0)) == 5
    assert _loco.least_damped_mode(f, z, (4.0, 19.0)) is None
    with pytest.raises(loco.LocoError, match="frequencies and"):
        _loco.least_damped_mode(f, z[:2], (0.3, 20.0))
    eigen = _eigen("S_high", "YD1")
    by_hand = min(
        (m for m in eigen.modes if 0.3 <= m.frequency <= 20.0), key=lambda m: m.damping_ratio
    )
    assert eigen.least_damped() is by_hand


def test_oscillatory_modes_are_one_of_each_pair_with_frequency_and_damping_ratio() -> None:
    values = np.array([-1.0 + 0.0j, -0.3 + 2 * np.pi * 1.5j, -0.3 - 2 * np.pi * 1.5j, 0.1 + 1e-7j])
    keep, frequencies, damping = _loco.oscillatory_modes(values.real.copy(), values.imag.copy())
    assert keep == [1]
    # The bits numpy gives for |Im λ|/2π and −Re λ/|λ|.
    assert frequencies == [float(abs(values[1].imag) / (2 * np.pi))]
    assert damping == [float(-values[1].real / abs(values[1]))]
