"""The 17-coordinate lateral model of Vehicle 1: its suspension alone against hand-derived
frequencies, rigid-body modes, the fore-aft mirror, the bogie kinematic mode against Wickens'
rigid-bogie wavelength, and the critical speeds."""

from __future__ import annotations

import itertools
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from . import state_space as ss
from .closed_forms import rigid_bogie_wavelength
from .lateral_vehicle_model import layout, mirror, model, running_gear_dofs, suspension
from .single_wheelset import SuspendedWheelset
from .vehicle1_parameters import CONICITIES, Element, G, Vehicle1
from .vehicle1_results import Row, format_table, table


def clamped_frequencies(v: Vehicle1, dofs: list[int]) -> np.ndarray:
    """Undamped natural frequencies (Hz) of the suspension with every coordinate but ``dofs``
    held at zero."""
    m, _, k = suspension(v)
    sub = np.ix_(dofs, dofs)
    w2 = np.linalg.eigvals(np.linalg.solve(m[sub], k[sub])).real
    return np.sort(np.sqrt(w2)) / (2 * np.pi)


def test_car_body_on_the_secondary_has_the_hand_derived_frequencies() -> None:
    # Bogies and wheelsets held: the car body's yaw on 4 lateral springs at ±9.5 m, 4
    # longitudinal springs at ±1 m and 2 anti-bending stiffnesses; its lateral and roll coupled
    # through the springs' height z = 0.8275 − 1.80 m, roll from 4 vertical springs at ±1 m, 2
    # anti-roll bars and the weight's −W|z| (springs below the centre of gravity).
    v = Vehicle1()
    _, _, car = layout(v)
    ky, kx, kz = (
        v.secondary_lateral.stiffness,
        v.secondary_longitudinal.stiffness,
        v.secondary_vertical.stiffness,
    )
    z, b, big_l = v.secondary_height - v.carbody.height, v.secondary_semi_spacing, 9.5
    yaw = 4 * ky * big_l**2 + 4 * kx * b**2 + 2 * v.anti_bending_per_bogie
    k2 = np.array(
        [
            [4 * ky, -4 * ky * z],
            [
                -4 * ky * z,
                4 * ky * z**2 + 4 * kz * b**2 + 2 * v.anti_roll_per_bogie + v.carbody.mass * G * z,
            ],
        ]
    )
    m2 = np.diag([v.carbody.mass, v.carbody.roll_inertia])
    sway = np.sort(np.sqrt(np.linalg.eigvals(np.linalg.solve(m2, k2)).real)) / (2 * np.pi)
    expected = np.sort([*sway, np.sqrt(yaw / v.carbody.yaw_inertia) / (2 * np.pi)])
    got = clamped_frequencies(v, [car.y, car.psi, car.roll])
    np.testing.assert_allclose(got, expected, rtol=1e-10)
    # The lower sway mode of a coach is slow, about 0.5-1 Hz.
    assert 0.3 < got[0] < 1.0


def test_at_vanishing_speed_the_bodies_move_as_on_the_suspension_alone() -> None:
    # As V → 0 the creep damping (∝ 1/V) locks the wheelsets on the time scale of the
    # suspension: the eigenvalues of the whole model tend to those of the bogies and the car
    # body on their suspension with the wheelsets held (damping included), the difference
    # falling with V. The 16 others are the wheelsets' creep modes, fast or slow.
    v = Vehicle1()
    m, c, k = suspension(v)
    held = list(range(8, 17))
    sub = np.ix_(held, held)
    alone = np.linalg.eigvals(ss.state_matrix(m[sub], c[sub], k[sub]))
    assert alone.size == 18
    gaps = []
    for speed in (1e-2, 1e-3):
        full = ss.eigen(model(v, 0.2), speed)[0]
        gap = max(np.min(np.abs(full - s)) / abs(s) for s in alone)
        gaps.append(gap)
    # Measured: 1.1e-4 at 0.01 m/s, 1.1e-5 at 0.001 m/s (first order in V).
    assert gaps[1] < 2e-5
    assert gaps[1] < gaps[0] / 5


def test_a_wheelset_of_the_assembled_model_is_the_suspended_wheelset() -> None:
    # Every coordinate but one wheelset's held: the assembled model (elements and creep terms)
    # must be the directly written two-coordinate wheelset on Vehicle 1's two axle boxes, with
    # the same creep coefficients, at every speed and in both running directions.
    v = Vehicle1()
    cr = v.creep()
    w = SuspendedWheelset.on_axle_boxes(
        v.primary_lateral.stiffness,
        v.primary_longitudinal.stiffness,
        v.primary_semi_spacing,
        f11=cr.f11,
        f22=cr.f22,
        conicity=0.2,
    )
    wheelset = layout(v)[0][1]
    sub = np.ix_([wheelset.y, wheelset.psi], [wheelset.y, wheelset.psi])
    for speed in (3.0, 60.0, -60.0):
        m, c, k = model(v, 0.2)(speed)
        mw, cw, kw = w.matrices(speed)
        np.testing.assert_allclose(m[sub], mw, rtol=1e-14)
        np.testing.assert_allclose(k[sub], kw, rtol=1e-12)
        # The axle boxes' dampers are the assembled model's addition.
        damping = np.diag(
            [2 * v.primary_lateral.damping, 2 * v.primary_longitudinal.damping * 1.0**2]
        )
        np.testing.assert_allclose(c[sub], cw + damping, rtol=1e-12)


def test_bogie_yaw_on_its_primary_and_secondary() -> None:
    # Everything else held: 4 lateral axle boxes at ±1.28 m, 4 longitudinal at ±1 m, the
    # secondary's 2 longitudinal springs at ±1 m and one anti-bending stiffness.
    v = Vehicle1()
    bogie = layout(v)[1][0]
    k = (
        4 * v.primary_lateral.stiffness * v.wheelbase_semi**2
        + 4 * v.primary_longitudinal.stiffness * v.primary_semi_spacing**2
        + 2 * v.secondary_longitudinal.stiffness * v.secondary_semi_spacing**2
        + v.anti_bending_per_bogie
    )
    (got,) = clamped_frequencies(v, [bogie.psi])
    assert got == pytest.approx(np.sqrt(k / v.bogie.yaw_inertia) / (2 * np.pi), rel=1e-12)


def test_the_suspension_has_exactly_the_two_rigid_modes_of_the_vehicle() -> None:
    # Without gravity, the suspension's stiffness is positive semi-definite with two zero
    # modes: every body sliding sideways together, and the whole vehicle yawing (each body at
    # x moving x ψ and yawing ψ). A wrong lever arm anywhere would make these strain it.
    v = replace(Vehicle1(), gravity=False)
    _, _, k = suspension(v)
    wheelsets, bogies, car = layout(v)
    slide, turn = np.zeros(17), np.zeros(17)
    for b in [*wheelsets, *bogies, car]:
        slide[b.y] = 1.0
        turn[b.y], turn[b.psi] = b.x, 1.0
    np.testing.assert_allclose(k, k.T, atol=0)
    scale = np.abs(k).max()
    assert np.abs(k @ slide).max() < 1e-12 * scale
    assert np.abs(k @ turn).max() < 1e-12 * scale
    eig = np.linalg.eigvalsh(k)
    assert np.sum(eig < 1e-9 * scale) == 2
    assert eig[2] > 1e3


@pytest.mark.parametrize("spin", [False, True])
def test_running_backwards_is_the_fore_aft_mirror(spin: bool) -> None:
    # Under x → −x (front and rear bodies swap, yaw changes sign) the model at V is the model
    # at −V; so the eigenvalues at ±V coincide.
    v = replace(Vehicle1(), spin=spin)
    t = mirror(v)
    for lam, speed in [(0.1, 30.0), (0.3, 70.0)]:
        forward, backward = model(v, lam)(speed), model(v, lam)(-speed)
        for a, b in zip(forward, backward, strict=True):
            np.testing.assert_allclose(t @ a @ t.T, b, rtol=1e-12, atol=1e-9 * np.abs(a).max())


def test_the_bogie_kinematic_mode_has_wickens_rigid_bogie_wavelength() -> None:
    # Primary 1e3 times stiffer (the bogie rigid), no secondary (the car body detached), no
    # gravity, f11 = f22 (Wickens' form): at 1 m/s the running gear's slowest oscillation has
    # the rigid bogie's kinematic wavelength 2π √(r0 l0/λ (1 + a²/l0²)). What is left: the
    # primary's compliance against the creep stiffness (~1e-4) and inertia (~1e-8 at 1 m/s).
    base = Vehicle1()
    cr = base.creep()
    stiff = 1e3
    v = replace(
        base,
        primary_lateral=Element(base.primary_lateral.stiffness * stiff),
        primary_longitudinal=Element(base.primary_longitudinal.stiffness * stiff),
        secondary_lateral=Element(0.0),
        secondary_longitudinal=Element(0.0),
        secondary_vertical=Element(0.0),
        anti_roll_per_bogie=0.0,
        anti_bending_per_bogie=0.0,
        gravity=False,
    ).with_contact(cr.f11, cr.f11)
    for lam in CONICITIES:
        mode = ss.kinematic_mode(model(v, lam), 1.0)
        expected = rigid_bogie_wavelength(
            v.rolling_radius, v.contact_semi_distance, lam, v.wheelbase_semi
        )
        assert ss.wavelength(mode, 1.0) == pytest.approx(expected, rel=1e-5)
    # With the contact's own f22/f11 (0.92) the general form holds just as well.
    v = replace(v, creep_override=None)
    for lam in CONICITIES:
        mode = ss.kinematic_mode(model(v, lam), 1.0)
        expected = rigid_bogie_wavelength(
            v.rolling_radius, v.contact_semi_distance, lam, v.wheelbase_semi, cr.f22 / cr.f11
        )
        assert ss.wavelength(mode, 1.0) == pytest.approx(expected, rel=1e-5)


@pytest.fixture(scope="module")
def rows() -> list[Row]:
    """Vehicle 1's results table, computed once."""
    return table()


def test_the_readme_records_the_current_results(rows: list[Row]) -> None:
    # The README's results table, as printed, is what the models give now.
    text = (Path(__file__).parent / "README.md").read_text(encoding="utf-8")
    for r in rows:
        line = (
            f"| {r.conicity:.2f} | {r.critical_speed:.2f} ({r.critical_speed * 3.6:.1f}) | "
            f"{r.hunting_frequency:.3f} | {r.kinematic_wavelength:.3f} "
            f"({r.kinematic_frequency:.4f}) | {r.rigid_bogie_wavelength:.3f} |"
        )
        assert line in text, line
        curving = ", ".join(
            f"{y * 1e3:.2f}/{p * 1e3:.3f}".replace("-", "−")
            for y, p in zip(r.offsets, r.attack_angles, strict=True)
        )
        assert f"| {r.conicity:.2f} | {curving} |" in text, curving


def test_vehicle1_hunts_in_its_bogies_above_a_critical_speed_falling_with_conicity(
    rows: list[Row],
) -> None:
    print("\n" + format_table(rows))
    speeds = [r.critical_speed for r in rows]
    assert all(np.isfinite(speeds))
    assert all(a > b for a, b in itertools.pairwise(speeds))
    v = Vehicle1()
    for r in rows:
        matrices = model(v, r.conicity)
        assert ss.largest_real_part(matrices, 0.999 * r.critical_speed) < 0.0
        assert ss.largest_real_part(matrices, 1.001 * r.critical_speed) > 0.0
        values, vectors = ss.eigen(matrices, r.critical_speed)
        shares = ss.energy_shares(matrices(r.critical_speed)[0], vectors[:, np.argmax(values.real)])
        # The unstable mode is the running gear's (bogie hunting): most of its kinetic energy
        # is in the wheelsets' and bogies' lateral and yaw motion (measured 0.78 at λ = 0.05,
        # where the car body takes 0.21, to 0.95 at λ = 0.3).
        assert shares[running_gear_dofs(v)].sum() > 0.5
        # The finite primary makes the bogie's kinematic wavelength shorter than the rigid
        # bogie's, more so as the creep stiffness (∝ λ) grows against the primary's.
        assert r.kinematic_wavelength < r.rigid_bogie_wavelength
