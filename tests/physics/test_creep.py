"""Hertz contact, creepages, Kalker's linear theory, FASTSIM and FaStrip (loco.creep).

References: analytic Hertz (sphere on plane), CONTACT's output for the `fastsim` example
(eve70a/CONTACT, in the shared reference data), Kalker's table (table nodes), and the linear
theory as the small-creepage limit of FASTSIM and FaStrip, CONTACT's FaStrip (case 7).
"""

from __future__ import annotations

import math
import os
import re
from pathlib import Path

import pytest

from loco import ParameterError
from loco.creep import (
    fastrip,
    fastsim,
    hertz,
    hertz_stiffness,
    kalker_coefficients,
    linear_creep_forces,
    wheelset_creepages,
)
from verification_records import record

G_REF = 82e9
NU_REF = 0.28


def shared_data() -> Path | None:
    """The shared reference data directory, or None when it is not available."""
    env = os.environ.get("LOCO_SHARED_DATA")
    if env:
        return Path(env) if Path(env).is_dir() else None
    for parent in Path(__file__).resolve().parents:
        candidate = parent / "shared" / "data"
        if candidate.is_dir():
            return candidate
    return None


def contact_reference() -> str:
    data = shared_data()
    path = None if data is None else data / "profiles" / "fastsim.ref_out"
    if path is None or not path.is_file():
        pytest.skip("shared reference data profiles/fastsim.ref_out not found")
    return path.read_text()


def contact_cases(text: str) -> list[dict[str, float]]:
    """Per case of CONTACT's output: bound, material model, grid, FY/(mu FN), MZ (N mm)."""
    cases = []
    for block in re.split(r"\n Case +\d+\n", text)[1:]:
        bound = int(re.search(r"BOUND +(\d)", block).group(1))  # type: ignore[union-attr]
        mater = int(re.search(r"MATER +(\d)", block).group(1))  # type: ignore[union-attr]
        mx = int(re.search(r"DISCRETISATION MX,MY, DX,DY: +(\d+)", block).group(1))  # type: ignore[union-attr]
        forces = re.search(r"FN +FX +FY +MZ.*\n +(\S+) +(\S+) +(\S+) +(\S+)", block)
        ratios = re.search(r"FN/G +FX/FSTAT/FN +FY/FSTAT/FN +APPROACH +PMAX *\n(.*)", block)
        curv = re.search(r"THE CURVATURES A1,B1 ARE: +(\S+) +(\S+)", block)
        assert forces and ratios and curv
        fy_ratio, approach, pmax = (float(v) for v in ratios.group(1).split()[2:5])
        cases.append(
            {
                "bound": bound,
                "mater": mater,
                "mx": mx,
                "fy_ratio": fy_ratio,
                "mz_nmm": float(forces.group(4)),
                "approach_mm": approach,
                "pmax_mpa": pmax,
                "a1_per_mm": float(curv.group(1)),
                "b1_per_mm": float(curv.group(2)),
            }
        )
    return cases


# --- Hertz ------------------------------------------------------------------------------------


def test_hertz_sphere_on_plane() -> None:
    r, n, e, nu = 0.46, 1.0e5, 2.1e11, 0.28
    res = hertz(n, r, r, math.inf, E=e, nu=nu)
    e_star = e / (2.0 * (1.0 - nu**2))
    a = (3.0 * n * r / (4.0 * e_star)) ** (1.0 / 3.0)
    assert res.semi_axis_long == pytest.approx(a, rel=1e-9)
    assert res.semi_axis_lat == pytest.approx(a, rel=1e-9)
    assert res.approach == pytest.approx(a * a / r, rel=1e-9)
    assert res.peak_pressure == pytest.approx(1.5 * n / (math.pi * a * a), rel=1e-12)
    k = hertz_stiffness(r, r, math.inf, E=e, nu=nu)
    assert k * res.approach**1.5 == pytest.approx(n, rel=1e-9)


def test_hertz_matches_contact_reference() -> None:
    """CONTACT's case 1: curvatures A1, B1 (1/mm) with FN = 82 kN give a = 8 mm, b = 4 mm."""
    case = contact_cases(contact_reference())[0]
    a1, b1 = case["a1_per_mm"] * 1e3, case["b1_per_mm"] * 1e3  # 1/m
    e = 2.0 * G_REF * (1.0 + NU_REF)
    res = hertz(82e3, 1.0 / (2.0 * a1), 1.0 / (2.0 * b1), math.inf, E=e, nu=NU_REF)
    # A1, B1 are printed with 4 digits: a, b agree to about 1e-3.
    assert res.semi_axis_long == pytest.approx(8e-3, rel=2e-3)
    assert res.semi_axis_lat == pytest.approx(4e-3, rel=2e-3)
    assert res.approach == pytest.approx(case["approach_mm"] * 1e-3, rel=2e-3)
    assert res.peak_pressure == pytest.approx(case["pmax_mpa"] * 1e6, rel=2e-3)


# --- Kalker ----------------------------------------------------------------------------------


def test_kalker_table_nodes() -> None:
    # Kalker (1990) table E.3, circle, nu = 0.25.
    c = kalker_coefficients(1.0, 0.25)
    assert c == pytest.approx((4.12, 3.67, 1.47, 1.19), rel=1e-12)
    # b/a = 0.5, nu = 0: C11 = 4.37.
    assert kalker_coefficients(2.0, 0.0).c11 == pytest.approx(4.37, rel=1e-12)


def test_linear_theory_formula() -> None:
    a, b, g = 6e-3, 5e-3, G_REF
    c = kalker_coefficients(a / b, NU_REF)
    f = linear_creep_forces(a, b, 1e-3, 2e-3, 0.5, nu=NU_REF, shear_modulus=g)
    s = math.sqrt(a * b)
    assert f.fx == pytest.approx(-g * a * b * c.c11 * 1e-3)
    assert f.fy == pytest.approx(-g * a * b * (c.c22 * 2e-3 + s * c.c23 * 0.5))
    assert f.mz == pytest.approx(-g * s**3 * (-c.c23 * 2e-3 + s * c.c33 * 0.5))


# --- FASTSIM ---------------------------------------------------------------------------------

REF = {"a": 8e-3, "b": 4e-3, "normal_force": 82e3, "shear_modulus": G_REF, "mu": 0.3}


@pytest.mark.parametrize("creep", [(1e-7, 0.0, 0.0), (0.0, 1e-7, 0.0), (0.0, 0.0, 1e-5)])
def test_fastsim_tends_to_linear_theory(creep: tuple[float, float, float]) -> None:
    f = fastsim(**REF, creepage_long=creep[0], creepage_lat=creep[1], spin=creep[2], grid=(50, 50))
    lin = linear_creep_forces(4e-3 * 2, 4e-3, *creep, shear_modulus=G_REF)
    assert f.fx + f.fy == pytest.approx(lin.fx + lin.fy, rel=0.01)
    which = ("longitudinal", "lateral", "spin")[next(i for i, c in enumerate(creep) if c)]
    deviation = abs((f.fx + f.fy) / (lin.fx + lin.fy) - 1)
    case = record(f"fastsim_linear_{which}", __file__)
    case.within("deviation", deviation, "", 2, "<", 0.01).check()


def test_fastsim_saturates_at_mu_n() -> None:
    for bound in ("parabolic", "elliptic"):
        f = fastsim(**REF, creepage_long=0.05, creepage_lat=0.05, spin=0.0, bound=bound)
        assert math.hypot(f.fx, f.fy) == pytest.approx(0.3 * 82e3, rel=1e-9)


@pytest.mark.parametrize(("bound", "bound_code"), [("parabolic", 3), ("elliptic", 2)])
def test_fastsim_matches_contact_fine_grid(bound: str, bound_code: int) -> None:
    """CONTACT's FASTSIM on its 220 x 220 grid (cases 5 and 6 of the `fastsim` example)."""
    cases = contact_cases(contact_reference())
    # Case 5 (parabolic) or 6 (elliptic): the first FASTSIM (M=3) case on the 220 x 220 grid.
    case = next(c for c in cases if c["mater"] == 3 and c["bound"] == bound_code and c["mx"] == 220)
    creep = {"creepage_long": 0.0, "creepage_lat": -6.25e-4, "spin": 0.625}
    f = fastsim(**REF, **creep, grid=(200, 200), bound=bound)  # type: ignore[arg-type]
    assert f.fy / (0.3 * 82e3) == pytest.approx(case["fy_ratio"], rel=0.02)
    assert f.mz == pytest.approx(case["mz_nmm"] * 1e-3, rel=0.03)
    assert abs(f.fx) < 1e-9 * abs(f.fy)


def test_fastsim_default_grid_is_close_to_converged() -> None:
    creep = {"creepage_long": 2e-4, "creepage_lat": -6.25e-4, "spin": 0.625}
    coarse = fastsim(**REF, **creep)
    fine = fastsim(**REF, **creep, grid=(400, 400))
    assert coarse.fy == pytest.approx(fine.fy, rel=0.02)
    assert coarse.fx == pytest.approx(fine.fx, rel=0.02)


def test_kalker_factor_softens_creep_curve() -> None:
    creep = {"creepage_long": 1e-4, "creepage_lat": 0.0, "spin": 0.0}
    full = fastsim(**REF, **creep)
    reduced = fastsim(**REF, **creep, kalker_factor=0.5)
    assert abs(reduced.fx) < abs(full.fx)


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"a": math.nan}, "a"),
        ({"a": 0.0}, "a"),
        ({"b": -1.0}, "b"),
        ({"mu": -0.1}, "mu"),
        ({"normal_force": math.inf}, "normal_force"),
        ({"grid": (0, 10)}, "grid[0]"),
        ({"grid": (10, -3)}, "grid[1]"),
        ({"bound": "square"}, "bound"),
        ({"kalker_factor": 0.0}, "kalker_factor"),
        ({"nu": 0.7}, "nu"),
        ({"spin": math.nan}, "spin"),
    ],
)
def test_fastsim_bad_input_names_argument(kwargs: dict[str, object], name: str) -> None:
    args: dict[str, object] = {**REF, "creepage_long": 0.0, "creepage_lat": 0.0, "spin": 0.0}
    args.update(kwargs)
    with pytest.raises(ParameterError, match=re.escape(f"`{name}`")):
        fastsim(**args)  # type: ignore[arg-type]


def test_hertz_and_kalker_bad_input() -> None:
    with pytest.raises(ParameterError, match="normal_force"):
        hertz(math.nan, 0.46, 0.3, 0.3)
    with pytest.raises(ParameterError, match="r_wheel_transverse"):
        hertz(1e5, 0.46, -0.1, 0.3)
    with pytest.raises(ParameterError, match="`E`"):
        hertz(1e5, 0.46, 0.3, 0.3, E=-1.0)
    with pytest.raises(ParameterError, match="`nu`"):
        hertz(1e5, 0.46, 0.3, 0.3, nu=0.5)
    with pytest.raises(ParameterError, match="a_over_b"):
        kalker_coefficients(-1.0)


# --- Creepages -------------------------------------------------------------------------------


def test_creepages_simple_cases() -> None:
    v, r0, l0 = 30.0, 0.625, 0.7465
    lat = wheelset_creepages(v, "left", l0, r0, lateral_velocity=0.3)
    assert lat == pytest.approx((0.0, 0.3 / v, 0.0), abs=1e-12)
    yaw = wheelset_creepages(v, "left", l0, r0, yaw=0.003)
    assert yaw.lateral == pytest.approx(-math.sin(0.003), abs=1e-12)
    dr = wheelset_creepages(v, "right", -l0, r0 + 0.002, nominal_radius=r0)
    assert dr.longitudinal == pytest.approx(-0.002 / r0, abs=1e-12)
    spin = wheelset_creepages(v, "left", l0, r0, contact_angle=0.05)
    assert spin.spin == pytest.approx(-math.sin(0.05) / r0, abs=1e-12)
    with pytest.raises(ParameterError, match="side"):
        wheelset_creepages(v, "middle", l0, r0)  # type: ignore[arg-type]
    with pytest.raises(ParameterError, match="speed"):
        wheelset_creepages(0.0, "left", l0, r0)


# --- FaStrip ----------------------------------------------------------------------------------


def test_fastrip_matches_contacts_fastrip_fine_grid() -> None:
    case = next(c for c in contact_cases(contact_reference()) if c["mater"] == 5 and c["mx"] == 220)
    f = fastrip(**REF, creepage_long=0.0, creepage_lat=-6.25e-4, spin=0.625, grid=(200, 200))
    assert f.fy / (0.3 * 82e3) == pytest.approx(case["fy_ratio"], rel=0.01)
    assert f.mz == pytest.approx(case["mz_nmm"] * 1e-3, rel=0.01)


def test_fastrip_tends_to_linear_theory_and_saturates() -> None:
    f = fastrip(**REF, creepage_long=1e-9, creepage_lat=0.0, spin=0.0, grid=(10, 200))
    lin = linear_creep_forces(8e-3, 4e-3, 1e-9, 0.0, 0.0, shear_modulus=82e9)
    assert f.fx == pytest.approx(lin.fx, rel=2e-3)
    full = fastrip(**REF, creepage_long=0.05, creepage_lat=0.05, spin=0.0)
    assert math.hypot(full.fx, full.fy) == pytest.approx(0.3 * 82e3, rel=1e-9)
    # Where both slide entirely they share the traction direction (FASTSIM's, elliptic bound).
    both = {"creepage_long": 0.05, "creepage_lat": 0.05, "spin": 0.0}
    assert full.fy / full.fx == pytest.approx(
        fastsim(**REF, **both, bound="elliptic").fy / fastsim(**REF, **both, bound="elliptic").fx
    )


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"a": math.nan}, "a"),
        ({"mu": -0.1}, "mu"),
        ({"grid": (10, 0)}, "grid[1]"),
        ({"kalker_factor": 0.0}, "kalker_factor"),
        ({"spin": math.inf}, "spin"),
    ],
)
def test_fastrip_bad_input_names_argument(kwargs: dict[str, object], name: str) -> None:
    args: dict[str, object] = {**REF, "creepage_long": 0.0, "creepage_lat": 0.0, "spin": 0.0}
    args.update(kwargs)
    with pytest.raises(ParameterError, match=re.escape(f"`{name}`")):
        fastrip(**args)  # type: ignore[arg-type]
