"""The suspended wheelset: Klingel's wavelength, the closed-form critical speed and its limit
for large creep coefficients, and running backwards."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from . import state_space as ss
from .closed_forms import klingel
from .single_wheelset import SuspendedWheelset


@pytest.mark.parametrize("speed", [1.0, 3.0, 10.0])
def test_the_free_wheelset_oscillates_at_klingels_wavelength(speed: float) -> None:
    w = SuspendedWheelset().free()
    # The kinematic mode is the least damped; the other pair is the creep-damped one.
    mode = max(ss.oscillatory_modes(w.matrices, speed), key=lambda s: s.real)
    ratio = ss.wavelength(mode, speed) / w.klingel_wavelength()
    assert w.klingel_wavelength() == klingel(0.46, 0.75, 0.1)
    # The inertia corrections (second order in ε = ω0 τ, τ the creep time constant): the
    # wavelength departs from Klingel's as predicted, to within 2 % of the departure plus the
    # third-order remainder, and up to 10 m/s by less than 0.1 % (at 30 m/s it is 0.5 %: the
    # closed form is the low-speed limit).
    predicted = w.klingel_correction(speed)
    assert abs(ratio - 1.0) < 1e-3
    assert ratio - 1.0 == pytest.approx(predicted, rel=0.02, abs=1e-12)
    # The free wheelset is unstable at every speed (its kinematic oscillation grows).
    assert mode.real > 0.0


def test_numeric_critical_speed_matches_routh_hurwitz() -> None:
    for ky, kpsi in [(1e6, 2e6), (0.0, 2e6), (1e5, 5e5)]:
        w = replace(SuspendedWheelset(), lateral_stiffness=ky, yaw_stiffness=kpsi)
        numeric = ss.critical_speed(w.matrices, 1.0, 300.0, 150)
        assert numeric == pytest.approx(w.critical_speed_closed_form(), rel=1e-8)
        # Just below it the wheelset is stable, just above it hunts.
        assert ss.largest_real_part(w.matrices, 0.999 * numeric) < 0.0
        assert ss.largest_real_part(w.matrices, 1.001 * numeric) > 0.0


def test_large_creep_coefficients_approach_the_textbook_limit() -> None:
    w = SuspendedWheelset()
    limit = w.critical_speed_large_creep()
    gaps = []
    for scale in (1.0, 10.0, 100.0):
        scaled = replace(w, f11=w.f11 * scale, f22=w.f22 * scale)
        assert scaled.critical_speed_large_creep() == pytest.approx(limit, rel=1e-12)
        gaps.append(abs(scaled.critical_speed_closed_form() / limit - 1.0))
    # The remainder falls like 1/f: a factor of about ten per decade.
    assert gaps[0] < 0.02
    assert gaps[1] < gaps[0] / 5 and gaps[2] < gaps[1] / 5
    # With f11 = f22 the limit is the textbook's (r0 l0/λ)(k_ψ + k_y l0²)/(I + m l0²).
    eq = replace(w, f22=w.f11)
    textbook = np.sqrt(
        eq.rolling_radius
        * eq.contact_semi_distance
        / eq.conicity
        * (eq.yaw_stiffness + eq.lateral_stiffness * eq.contact_semi_distance**2)
        / (eq.yaw_inertia + eq.mass * eq.contact_semi_distance**2)
    )
    assert eq.critical_speed_large_creep() == pytest.approx(textbook, rel=1e-12)


def test_a_stiffly_held_wheelset_is_stable_at_every_speed() -> None:
    # Vehicle 1's primary suspension (2 × 3.884e6 N/m, 2 × 3.1391e7 N/m at ±1 m) to a fixed
    # frame: the crossing condition has no real speed, and no eigenvalue crosses up to 300 m/s.
    w = SuspendedWheelset.on_axle_boxes(3.884e6, 3.1391e7, 1.0)
    assert (w.lateral_stiffness, w.yaw_stiffness) == (2 * 3.884e6, 2 * 3.1391e7)
    assert w.critical_speed_closed_form() == float("inf")
    assert ss.critical_speed(w.matrices, 1.0, 300.0, 60) == float("inf")


def test_running_backwards_is_the_mirror_image() -> None:
    w = SuspendedWheelset()
    t = np.diag([1.0, -1.0])
    for speed in (5.0, 40.0):
        forward, backward = w.matrices(speed), w.matrices(-speed)
        for a, b in zip(forward, backward, strict=True):
            np.testing.assert_allclose(t @ a @ t.T, b, rtol=1e-14)
