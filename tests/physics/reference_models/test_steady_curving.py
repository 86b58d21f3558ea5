"""Steady curving of Vehicle 1 by the linear theory: the pure-rolling offset of wheelsets free
in yaw, the rigid bogie's offsets and angles of attack as the primary stiffens, Boocock's
bogie equations against the 17-coordinate model, and the mirror curve."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from .closed_forms import pure_rolling_offset, rigid_bogie_offset
from .lateral_vehicle_model import layout
from .steady_curving import BoocockBogie, boocock_bogie, vehicle_curving
from .vehicle1_parameters import CONICITIES, Element, Vehicle1


@pytest.mark.parametrize("conicity", CONICITIES)
def test_wheelsets_free_in_yaw_roll_at_the_pure_rolling_offset(conicity: float) -> None:
    # No primary longitudinal stiffness: nothing yaws the wheelsets but creep, so each finds
    # the offset where its rolling radius difference matches the curve, y = −r0 l0/(λR),
    # whatever the lateral springs and the car body do (balance speed).
    v = Vehicle1()
    v = replace(v, primary_longitudinal=Element(0.0, v.primary_longitudinal.damping))
    for radius in (1500.0, 3000.0, -3000.0):
        c = vehicle_curving(v, conicity, radius)
        np.testing.assert_allclose(
            c.offsets,
            pure_rolling_offset(v.rolling_radius, v.contact_semi_distance, conicity, radius),
            rtol=1e-9,
        )


@pytest.mark.parametrize("conicity", CONICITIES)
def test_a_stiff_primary_gives_the_rigid_bogies_offsets_and_angles(conicity: float) -> None:
    # Boocock's bogie with no secondary and the primary 1e3 and 1e4 times stiffer: both
    # wheelsets at −(r0/(λR))(l0 + (f22/f11) a²/l0), the leading at ψ = −a/R, the trailing
    # at +a/R; the remainder falls with the primary's stiffness (measured about 1/k).
    radius = 3000.0
    base = replace(BoocockBogie.of(Vehicle1()), secondary_lateral=0.0, secondary_yaw=0.0)
    expected_y = rigid_bogie_offset(
        base.rolling_radius,
        base.contact_semi_distance,
        conicity,
        base.semi_wheelbase,
        radius,
        base.f22 / base.f11,
    )
    angle = base.semi_wheelbase / radius
    errors = []
    for stiff in (1e3, 1e4):
        p = replace(
            base, primary_lateral=base.primary_lateral * stiff, primary_yaw=base.primary_yaw * stiff
        )
        y1, psi1, y2, psi2, _, _ = boocock_bogie(p, conicity, radius)
        errors.append(max(abs(y1 / expected_y - 1), abs(y2 / expected_y - 1)))
        assert psi1 == pytest.approx(-angle, rel=1e-3)
        assert psi2 == pytest.approx(angle, rel=1e-3)
    assert errors[1] < 1e-3
    assert errors[1] < errors[0] / 5


def test_boococks_bogie_equations_agree_with_the_assembled_model() -> None:
    # The 17-coordinate model with the car body held on the centreline, radial at its centre,
    # and the bogie frames' roll held: each bogie is Boocock's, its car body at −x_b²/(2R)
    # and −x_b/R from the bogie's local track; with cant deficiency (0.5 m/s² outward).
    v = Vehicle1()
    _wheelsets, bogies, car = layout(v)
    clamps = {car.y: 0.0, car.psi: 0.0, car.roll: 0.0, bogies[0].roll: 0.0, bogies[1].roll: 0.0}
    p = BoocockBogie.of(v)
    for conicity in CONICITIES:
        for radius in (1200.0, -3000.0):
            c = vehicle_curving(v, conicity, radius, 0.5, clamped=clamps)
            for j, bogie in enumerate(bogies):
                xb = bogie.x
                q = boocock_bogie(p, conicity, radius, 0.5, -(xb**2) / (2 * radius), -xb / radius)
                got = [
                    c.offsets[2 * j],
                    c.attack_angles[2 * j],
                    c.offsets[2 * j + 1],
                    c.attack_angles[2 * j + 1],
                    c.coordinates[bogie.y],
                    c.coordinates[bogie.psi],
                ]
                np.testing.assert_allclose(got, q, rtol=1e-9, atol=1e-12)


def test_a_right_curve_mirrors_a_left_one_and_the_creep_forces_carry_the_load() -> None:
    v = Vehicle1()
    wheelsets, bogies, car = layout(v)
    cr = v.creep()
    radius, accel = 3000.0, 0.6
    left = vehicle_curving(v, 0.1, radius, accel)
    right = vehicle_curving(v, 0.1, -radius, accel)
    np.testing.assert_allclose(right.coordinates, -left.coordinates, rtol=1e-12, atol=1e-15)
    balanced = vehicle_curving(v, 0.1, radius)
    # Outward is −y in a left curve: the car body and the bogies move further out.
    for b in (car, *bogies):
        assert left.coordinates[b.y] < balanced.coordinates[b.y]
    # The suspension's forces are internal: the wheelsets' lateral creep forces 2 f22 ψ_i sum
    # to the whole vehicle's outward load, and the creep yaw moments about the vehicle's
    # centre, x_i 2 f22 ψ_i − 2 f11 l0 (λ y_i/r0 + l0/R), to the load's (zero: the masses are
    # placed symmetrically fore and aft).
    l0, r0 = v.contact_semi_distance, v.rolling_radius
    for c, load in ((left, v.total_mass * accel), (balanced, 0.0)):
        lateral = 2 * cr.f22 * c.attack_angles
        moment = [w.x for w in wheelsets] @ lateral - np.sum(
            2 * cr.f11 * l0 * (0.1 * c.offsets / r0 + l0 / radius)
        )
        assert lateral.sum() == pytest.approx(load, rel=1e-9, abs=1e-6)
        assert abs(moment) < 1e-9 * 2 * cr.f11 * l0 * l0 / radius * 4
    # At balance the leading wheelset of each bogie is further out than the trailing one and
    # points outward (negative angle of attack), the trailing one inward.
    for j in (0, 1):
        assert balanced.offsets[2 * j] < balanced.offsets[2 * j + 1] < 0.0
        assert balanced.attack_angles[2 * j] < 0.0 < balanced.attack_angles[2 * j + 1]
