"""Contact geometry from Python: symmetry, conical wheel on a knife edge, S1002/UIC60."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import loco
from loco import contact, profiles


def knife_rail(rho: float = 5e-4, alpha: float = 1.2) -> profiles.Profile:
    """A rail with a sharp apex (radius ``rho``) at y = 0 between flanks at ±alpha."""
    t = np.linspace(-alpha, alpha, 801)
    arc_y, arc_z = rho * np.sin(t), rho * (np.cos(t) - 1)
    flank = np.linspace(0.0, 0.02, 201)[1:]
    y = np.concatenate(
        [arc_y[0] - flank[::-1] * math.cos(alpha), arc_y, arc_y[-1] + flank * math.cos(alpha)]
    )
    z = np.concatenate(
        [arc_z[0] - flank[::-1] * math.sin(alpha), arc_z, arc_z[-1] - flank * math.sin(alpha)]
    )
    return profiles.Profile("knife", "rail", y, z)


def test_cone_on_knife_edges_matches_the_analytical_rolling_radius_difference() -> None:
    lam, r0, b = 0.05, 0.46, 0.75
    t = np.linspace(-0.04, 0.04, 801)
    cone = profiles.Profile("cone", "wheel", t, lam * t)
    rho, alpha, depth = 5e-4, 1.2, 0.014
    to_gauge = rho * math.sin(alpha) + (depth - rho * (1 - math.cos(alpha))) / math.tan(alpha)
    ys = np.array([-0.004, -0.001, 0.002, 0.005])
    setup = {
        "gauge": 2 * (b - to_gauge),
        "gauge_height": depth,
        "rail_inclination": 0.0,
        "back_to_back": 1.36,
        "nominal_radius": r0,
    }
    rail = knife_rail(rho, alpha)
    # EN 15302's Δr: the wheelset translated without roll, so Δr = 2λy.
    dr = contact.rolling_radius_difference(cone, rail, ys, **setup)  # type: ignore[arg-type]
    np.testing.assert_allclose(dr, 2 * lam * ys, rtol=2e-3)
    # The rigid wheelset rolls by φ = Δr/(2b), which moves each contact by r0·φ on the cone.
    r = contact.geometry(cone, rail, ys, **setup).touching("rolling_radius")  # type: ignore[arg-type]
    np.testing.assert_allclose(r[:, 0] - r[:, 1], 2 * lam * ys / (1 - lam * r0 / b), rtol=2e-3)


@pytest.fixture(scope="module")
def s1002_uic60(shared_data: Path) -> tuple[profiles.Profile, profiles.Profile]:
    return (
        profiles.load(shared_data / "profiles" / "MBench_S1002_v3.prw"),
        profiles.load(shared_data / "profiles" / "MBench_UIC60_v3.prr"),
    )


BENCHMARK_SETUP = {
    "gauge": 1.435,
    "gauge_height": 0.014,
    "rail_inclination": 0.0,
    "back_to_back": 1.360,
    "nominal_radius": 0.46,
}


def test_symmetric_wheelset_and_odd_rolling_radius_difference(
    s1002_uic60: tuple[profiles.Profile, profiles.Profile],
) -> None:
    wheel, rail = s1002_uic60
    ys = np.linspace(-0.009, 0.009, 37)
    g = contact.geometry(wheel, rail, ys, **BENCHMARK_SETUP)  # type: ignore[arg-type]
    centre = len(ys) // 2
    assert g.roll[centre] == pytest.approx(0.0, abs=1e-12)
    r = g.touching("rolling_radius")
    assert r[centre, 0] == pytest.approx(r[centre, 1], abs=1e-12)
    dr = r[:, 0] - r[:, 1]
    np.testing.assert_allclose(dr, -dr[::-1], atol=1e-9)
    assert g.gap.shape == (37, 2, 2)
    # In flange contact (y = 9 mm, left wheel) the contact angle is steep and the wheelset rises.
    assert g.touching("contact_angle")[-1, 0] > 0.8
    assert g.rise[-1] > 0.005
    # EN 15302's Δr (no roll): odd as well, within a few % of the rigid wheelset's on the tread
    # (|y| <= 4.5 mm), where the roll only shifts the contacts by r0·φ; but the roll turns the
    # flange toward the rail, so at 6.5 mm only the rigid wheelset is in flange contact.
    direct = contact.rolling_radius_difference(wheel, rail, ys, **BENCHMARK_SETUP)  # type: ignore[arg-type]
    np.testing.assert_allclose(direct, -direct[::-1], atol=1e-9)
    tread = np.abs(ys) <= 0.0045
    np.testing.assert_allclose(direct[tread], dr[tread], rtol=0.05, atol=1e-6)
    at_6_5mm = int(np.argmin(np.abs(ys - 0.0065)))
    assert dr[at_6_5mm] > 0.010 > 0.006 > direct[at_6_5mm]


def test_setup_errors_name_the_parameter(
    s1002_uic60: tuple[profiles.Profile, profiles.Profile],
) -> None:
    wheel, rail = s1002_uic60
    with pytest.raises(loco.ParameterError, match="gauge"):
        contact.geometry(wheel, rail, [0.0], gauge=-1.0)
    with pytest.raises(loco.ParameterError, match="back_to_back"):
        contact.geometry(wheel, rail, [0.0], back_to_back=float("nan"))
    with pytest.raises(loco.ParameterError, match="rail profile"):
        contact.geometry(rail, rail, [0.0])
    with pytest.raises(loco.ContactError):
        contact.geometry(wheel, rail, [0.2], **BENCHMARK_SETUP)  # type: ignore[arg-type]


def test_contact_module_exposes_conicity_and_creep() -> None:
    import loco.contact

    tan_gamma = loco.contact.equivalent_conicity("jm3-worn", "cn60", amplitude=0.003)
    assert 0.35 < tan_gamma < 1.05
    forces = loco.contact.fastsim(6e-3, 5e-3, 1e5, 0.0, 1e-3, 0.0)
    assert forces.fy < 0.0  # opposes the positive lateral creepage


def test_cone_on_knife_edge_rolls_as_wickens_says() -> None:
    """The rolled kinematics of the cone pair against Wickens' knife-edge result, computed here by
    hand: a cone of slope λ on a crown of radius R is, for the wheelset's roll, a cone on a knife
    edge at the crown's centre (the wheel surface offset by R along its normal is still a cone
    fixed to the wheelset), so the roll is φ = λy / (l − λ·r) with l the crowns' semi-spacing and
    r the radius down to the crown centre, and the rolled rolling-radius difference is
    Δr = 2λy·l / (l − λ·r): 21 % above the unrolled 2λy at λ = 0.2, 3.6 times it at 0.8. The
    whole ±15 mm table range is inside the (wide) cone up to λ = 1."""
    from loco import _loco

    crown = 0.01  # m, the knife edge's crown radius (contact/builtin/conical.rs)
    for lam, tol in [(0.05, 0.005), (0.2, 0.005), (0.5, 0.01), (0.8, 0.03)]:
        wheel, rail = _loco.conical_profiles(lam)
        g = loco.contact.geometry(wheel, rail, [0.0, 1e-3, -1e-3])
        angle = float(g.contact_angle[0][0][0])
        semi_spacing = float(g.lateral[0][0][0]) + crown * np.sin(angle)
        radius = float(g.rolling_radius[0][0][0]) + crown / np.cos(angle)
        roll_slope = (g.roll[1] - g.roll[2]) / 2e-3
        expected = lam / (semi_spacing - lam * radius)
        assert abs(roll_slope / expected - 1.0) < tol, (lam, roll_slope, expected)
        dr = g.rolling_radius[:, 0, 0] - g.rolling_radius[:, 1, 0]
        rolled_conicity = (dr[1] - dr[2]) / 4e-3
        wickens = lam * semi_spacing / (semi_spacing - lam * radius)
        assert abs(rolled_conicity / wickens - 1.0) < tol, (lam, rolled_conicity, wickens)
    for lam in (0.5, 0.8, 1.0):
        wheel, rail = _loco.conical_profiles(lam)
        g = loco.contact.geometry(wheel, rail, np.linspace(-0.015, 0.015, 31))
        assert np.isfinite(g.roll).all(), lam


def test_rail_inclination_is_the_scenarios_name_and_the_former_name_warns() -> None:
    wheel, rail = profiles.builtin("jm3-worn"), profiles.builtin("cn60")
    ys = np.array([-0.003, 0.0, 0.004])
    flat = contact.rolling_radius_difference(wheel, rail, ys, rail_inclination=0.0)
    with pytest.warns(DeprecationWarning, match="rail_inclination"):
        old = contact.rolling_radius_difference(wheel, rail, ys, inclination=0.0)
    np.testing.assert_array_equal(old, flat)
    # The default is the study's 1:40, which moves the contact: a different Δr.
    assert not np.array_equal(contact.rolling_radius_difference(wheel, rail, ys), flat)
    with pytest.raises(loco.ParameterError, match="inclination"):
        contact.geometry(wheel, rail, ys, rail_inclination=0.01, inclination=0.0)
