"""Wheel-rail contact mechanics: Hertz ellipse, creepages, Kalker's linear theory, FASTSIM, FaStrip.

Units are SI: forces in N, lengths in m, moduli and pressures in Pa, spin creepage in 1/m.
Frames follow ``docs/CONVENTIONS.md`` (x forward, y left, z up). The creep forces are those the
rail exerts on the wheel, opposing the creepages (Kalker's sign convention):
``Fx = -G·a·b·C11·ξ`` at small creepage.

Bad input (NaN, non-positive semi-axes or radii, negative loads, ``mu < 0``, a grid smaller
than 1) raises :class:`loco.ParameterError` naming the argument; a zero normal force (contact
lost) gives zero creep forces.
"""

from __future__ import annotations

from typing import Literal, NamedTuple

from loco import _loco

__all__ = [
    "CreepForces",
    "Creepages",
    "Fastrip",
    "Fastsim",
    "HertzResult",
    "KalkerCoefficients",
    "fastrip",
    "fastsim",
    "hertz",
    "hertz_stiffness",
    "kalker_coefficients",
    "linear_creep_forces",
    "wheelset_creepages",
]

STEEL_YOUNGS_MODULUS = 2.1e11
"""Young's modulus of wheel and rail steel (Pa)."""
STEEL_POISSON_RATIO = 0.28
"""Poisson's ratio of wheel and rail steel (-)."""
STEEL_SHEAR_MODULUS = 8.2e10
"""Shear modulus of wheel and rail steel (Pa), as in the Manchester benchmark."""


class HertzResult(NamedTuple):
    """Hertz contact for one load."""

    semi_axis_long: float
    """Semi-axis a in the rolling direction (m)."""
    semi_axis_lat: float
    """Semi-axis b in the lateral direction (m)."""
    peak_pressure: float
    """Peak (centre) pressure p0 (Pa)."""
    approach: float
    """Mutual approach of wheel and rail δ (m)."""


class KalkerCoefficients(NamedTuple):
    """Creepage coefficients of Kalker's linear theory (dimensionless)."""

    c11: float
    c22: float
    c23: float
    c33: float


class CreepForces(NamedTuple):
    """Tangential forces of the rail on the wheel in the contact plane."""

    fx: float
    """Longitudinal force (N)."""
    fy: float
    """Lateral force (N)."""
    mz: float
    """Spin moment about the contact normal (N·m)."""


class Creepages(NamedTuple):
    """Creepages at one contact."""

    longitudinal: float
    """ξ (-)."""
    lateral: float
    """η (-)."""
    spin: float
    """φ (1/m)."""


def hertz(
    normal_force: float,
    r_wheel_rolling: float,
    r_wheel_transverse: float,
    r_rail_transverse: float,
    E: float = STEEL_YOUNGS_MODULUS,
    nu: float = STEEL_POISSON_RATIO,
) -> HertzResult:
    """Hertz contact ellipse between wheel and a straight rail.

    Radii in m, signed: convex positive, concave negative, ``math.inf`` for a straight profile.
    """
    return HertzResult(
        *_loco.hertz_contact(
            normal_force, r_wheel_rolling, r_wheel_transverse, r_rail_transverse, E, nu
        )
    )


def hertz_stiffness(
    r_wheel_rolling: float,
    r_wheel_transverse: float,
    r_rail_transverse: float,
    E: float = STEEL_YOUNGS_MODULUS,
    nu: float = STEEL_POISSON_RATIO,
) -> float:
    """Normal contact stiffness K_H (N·m^-1.5) of the law N = K_H·δ^1.5."""
    return _loco.hertz_stiffness(r_wheel_rolling, r_wheel_transverse, r_rail_transverse, E, nu)


def kalker_coefficients(a_over_b: float, nu: float = STEEL_POISSON_RATIO) -> KalkerCoefficients:
    """Kalker's C11, C22, C23, C33 (Kalker 1990, table E.3) interpolated in a/b and ν."""
    return KalkerCoefficients(*_loco.kalker_coefficients(a_over_b, nu))


def linear_creep_forces(
    a: float,
    b: float,
    creepage_long: float,
    creepage_lat: float,
    spin: float,
    nu: float = STEEL_POISSON_RATIO,
    shear_modulus: float = STEEL_SHEAR_MODULUS,
) -> CreepForces:
    """Creep forces of Kalker's linear theory (no friction limit)."""
    return CreepForces(
        *_loco.linear_creep_forces(a, b, creepage_long, creepage_lat, spin, nu, shear_modulus)
    )


class _Solver:
    """A creep-force solver built once; :meth:`creep_forces` evaluates a contact."""

    _native: _loco.CreepSolver

    def creep_forces(
        self,
        a: float,
        b: float,
        normal_force: float,
        creepages: Creepages | tuple[float, float, float],
        mu: float = 0.3,
    ) -> CreepForces:
        """Creep forces on an ellipse of semi-axes ``a`` (rolling direction) and ``b`` (m)
        under ``normal_force`` (N) at ``creepages`` (ξ, η, φ) with friction coefficient ``mu``."""
        xi, eta, phi = creepages
        return CreepForces(*self._native.creep_forces(a, b, normal_force, (xi, eta, phi), mu))


class Fastsim(_Solver):
    """Kalker's FASTSIM, built once for a material, a ``grid = (nx, ny)`` discretisation, a
    traction bound and a coefficient factor.

    ``nx`` elements per strip along the rolling direction, ``ny`` strips; rolling in +x (the
    leading edge is at x = +a). ``kalker_factor`` divides the flexibilities (1: Kalker's values).
    Poisson's ratio ``nu`` (–) and ``shear_modulus`` (Pa) are the wheel and rail steel's.
    """

    def __init__(
        self,
        *,
        nu: float = STEEL_POISSON_RATIO,
        shear_modulus: float = STEEL_SHEAR_MODULUS,
        grid: tuple[int, int] = (10, 10),
        bound: Literal["parabolic", "elliptic"] = "parabolic",
        kalker_factor: float = 1.0,
    ) -> None:
        nx, ny = grid
        self._native = _loco.CreepSolver.fastsim(nu, shear_modulus, (nx, ny), bound, kalker_factor)


class Fastrip(_Solver):
    """FaStrip (Sichani, Enblom & Berg 2016, as modified in CONTACT), built once for a material,
    a ``grid = (nx, ny)`` and a coefficient factor.

    Strip theory with spin in the adhesion zone of every strip, FASTSIM's traction direction on
    the elliptic bound in the slip zone; ``nx`` elements per strip for the slip zone, ``ny``
    strips. ``kalker_factor`` scales the creepage coefficients (1: Kalker's).
    """

    def __init__(
        self,
        *,
        nu: float = STEEL_POISSON_RATIO,
        shear_modulus: float = STEEL_SHEAR_MODULUS,
        grid: tuple[int, int] = (10, 10),
        kalker_factor: float = 1.0,
    ) -> None:
        nx, ny = grid
        self._native = _loco.CreepSolver.fastrip(nu, shear_modulus, (nx, ny), kalker_factor)


def fastsim(
    a: float,
    b: float,
    normal_force: float,
    creepage_long: float,
    creepage_lat: float,
    spin: float,
    mu: float = 0.3,
    nu: float = STEEL_POISSON_RATIO,
    shear_modulus: float = STEEL_SHEAR_MODULUS,
    grid: tuple[int, int] = (10, 10),
    bound: Literal["parabolic", "elliptic"] = "parabolic",
    kalker_factor: float = 1.0,
) -> CreepForces:
    """One contact's creep forces by :class:`Fastsim` (a solver built for this call; build one
    :class:`Fastsim` to evaluate many contacts)."""
    solver = Fastsim(
        nu=nu, shear_modulus=shear_modulus, grid=grid, bound=bound, kalker_factor=kalker_factor
    )
    return solver.creep_forces(a, b, normal_force, (creepage_long, creepage_lat, spin), mu)


def fastrip(
    a: float,
    b: float,
    normal_force: float,
    creepage_long: float,
    creepage_lat: float,
    spin: float,
    mu: float = 0.3,
    nu: float = STEEL_POISSON_RATIO,
    shear_modulus: float = STEEL_SHEAR_MODULUS,
    grid: tuple[int, int] = (10, 10),
    kalker_factor: float = 1.0,
) -> CreepForces:
    """One contact's creep forces by :class:`Fastrip` (a solver built for this call; build one
    :class:`Fastrip` to evaluate many contacts)."""
    solver = Fastrip(nu=nu, shear_modulus=shear_modulus, grid=grid, kalker_factor=kalker_factor)
    return solver.creep_forces(a, b, normal_force, (creepage_long, creepage_lat, spin), mu)


def wheelset_creepages(
    speed: float,
    side: Literal["left", "right"],
    lateral_position: float,
    rolling_radius: float,
    contact_angle: float = 0.0,
    lateral_velocity: float = 0.0,
    yaw: float = 0.0,
    yaw_rate: float = 0.0,
    roll_rate: float = 0.0,
    spin_rate: float | None = None,
    nominal_radius: float | None = None,
) -> Creepages:
    """Creepages at a wheelset contact on straight track with a fixed rail.

    ``spin_rate`` (rad/s) defaults to pure rolling on ``nominal_radius`` (default: the contact's
    own rolling radius), i.e. ``speed / nominal_radius``.
    """
    if spin_rate is None:
        spin_rate = speed / (rolling_radius if nominal_radius is None else nominal_radius)
    return Creepages(
        *_loco.wheelset_creepages(
            speed,
            lateral_velocity,
            yaw,
            yaw_rate,
            roll_rate,
            spin_rate,
            side,
            lateral_position,
            rolling_radius,
            contact_angle,
        )
    )
