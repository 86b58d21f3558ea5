"""Hertz's ellipse against Johnson's closed forms, Kalker's table lookup, and Vehicle 1's
creep coefficients."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.special import ellipe, ellipk

from .contact_coefficients import (
    A_LE_B,
    B_LE_A,
    TABLE_G,
    Steel,
    hertz_ellipse,
    kalker_coefficients,
)
from .vehicle1_parameters import Vehicle1


def test_equal_curvatures_give_johnsons_circle() -> None:
    # Johnson (1985) eq. 4.22: a³ = 3 N R / (4 E*), R = 1/(2A).
    load, curv = 5e4, 1.2
    circle = hertz_ellipse(load, curv, curv)
    radius = (3 * load / (2 * curv) / (4 * Steel().contact_modulus)) ** (1 / 3)
    assert circle.a == pytest.approx(radius, rel=1e-12)
    # A nearly round ellipse is continuous with the circle.
    nearly = hertz_ellipse(load, curv, curv * (1 + 1e-6))
    assert nearly.a == pytest.approx(radius, rel=1e-5)
    assert nearly.b == pytest.approx(radius, rel=1e-5)


@pytest.mark.parametrize(("curv_x", "curv_y"), [(1.087, 1.667), (3.0, 0.5), (0.2, 4.0)])
def test_the_ellipse_reproduces_both_curvature_sums(curv_x: float, curv_y: float) -> None:
    # Johnson (1985) eq. 4.39: with p0 = 3N/(2πab), e² = 1 − b²/a² (a the major semi-axis),
    # A = (p0/E*)(b/(e²a²))(K − E) and B = (p0/E*)(b/(e²a²))((a/b)² E − K). The solver uses
    # only their ratio and the A equation; the B equation checks the result.
    load, e_star = 6e4, Steel().contact_modulus
    ell = hertz_ellipse(load, curv_x, curv_y)
    major, minor = max(ell.a, ell.b), min(ell.a, ell.b)
    e2 = 1 - (minor / major) ** 2
    k, e = ellipk(e2), ellipe(e2)
    p0 = 3 * load / (2 * np.pi * major * minor)
    factor = p0 / e_star * minor / (e2 * major**2)
    small, large = factor * (k - e), factor * ((major / minor) ** 2 * e - k)
    assert small == pytest.approx(min(curv_x, curv_y), rel=1e-9)
    assert large == pytest.approx(max(curv_x, curv_y), rel=1e-9)
    # The longer axis lies along the smaller curvature sum.
    assert (ell.a > ell.b) == (curv_x < curv_y)


def test_kalker_lookup_returns_the_table_rows_and_meets_at_the_circle() -> None:
    for i, g in enumerate(TABLE_G):
        narrow = kalker_coefficients(g, 1.0)
        long = kalker_coefficients(1.0, g)
        for name in ("c11", "c22", "c23"):
            assert narrow[name] == pytest.approx(A_LE_B[name][i], rel=1e-12)
            assert long[name] == pytest.approx(B_LE_A[name][i], rel=1e-12)
    round_, nearly = kalker_coefficients(1.0, 1.0), kalker_coefficients(1.0, 1.0 - 1e-9)
    assert round_ == pytest.approx(nearly, rel=1e-8)
    with pytest.raises(ValueError, match="below Kalker's table"):
        kalker_coefficients(0.05, 1.0)


def test_vehicle1_contact_is_longer_than_wide_with_f11_above_f22() -> None:
    # Coned tread on the 300 mm rail crown: the rolling direction has the smaller curvature
    # sum (1/(2·0.46) against 1/(2·0.3) 1/m), so a > b, and for b/a < 1 Kalker's C11 > C22.
    v = Vehicle1()
    cr = v.creep()
    assert v.wheel_load == pytest.approx(54.5e3, rel=2e-3)
    assert cr.ellipse.a > cr.ellipse.b
    assert 0.7 < cr.ellipse.b / cr.ellipse.a < 0.8
    assert cr.f11 > cr.f22
    # Kalker: f = G c² C with c² = ab.
    c2 = cr.ellipse.a * cr.ellipse.b
    coeffs = kalker_coefficients(cr.ellipse.a, cr.ellipse.b)
    assert cr.f22 == pytest.approx(Steel().shear_modulus * c2 * coeffs["c22"], rel=1e-12)
