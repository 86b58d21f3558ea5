"""Linear creep coefficients from Hertz's contact ellipse and Kalker's table.

Hertz (K. L. Johnson, *Contact Mechanics*, Cambridge 1985, §4.2): two bodies of the same
material (Young's modulus E, Poisson's ratio ν; 1/E* = 2(1 − ν²)/E) with relative curvature sums
A (rolling direction x) and B (lateral y), pressed by N, touch on an ellipse whose semi-axes
a ≥ b obey, with eccentricity e (e² = 1 − b²/a²) and the complete elliptic integrals K(e), E(e),

    B/A = ((a/b)² E − K) / (K − E)          (A the smaller sum, a along it)
    a³  = 3 N (K − E) / (2π E* e² A)

(from Johnson's A = (p0/E*)(b/(e²a²))(K − E) and p0 = 3N/(2πab)); for A = B the circle
a³ = 3NR/(4E*) with R = 1/(2A).

Kalker's linear theory (J. J. Kalker, *Three-Dimensional Elastic Bodies in Rolling Contact*,
Kluwer 1990, Table E.3; first in his 1967 Delft thesis; reproduced in Garg & Dukkipati 1984 and
Iwnicki 2006): per contact, with shear modulus G and c = √(ab),
f11 = G c² C11, f22 = G c² C22, f23 = G c³ C23. The column ν = 0.25 of the table is used, with
ν = 0.25 in Hertz too (one Poisson's ratio throughout; the column for steel that Garg &
Dukkipati quote); the numbers were read from the copy of Table E.3 in the open-source CONTACT
library (eve70a/CONTACT, ``m_hertz.f90``). Between the rows (g = 0.1 … 1.0 in each branch,
g = a/b for a ≤ b, g = b/a for b ≤ a) the coefficients are interpolated linearly in g.

Units: N in N, curvatures in 1/m, lengths in m, E and G in Pa, f11 and f22 in N, f23 in N·m.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

#: Rows g = 0.1, 0.2, ..., 1.0 of Kalker's Table E.3.
TABLE_G = np.linspace(0.1, 1.0, 10)
#: Kalker 1990, Table E.3, ν = 0.25, branch a/b ≤ 1 (a along the rolling direction).
A_LE_B = {
    "c11": [3.31, 3.37, 3.44, 3.53, 3.62, 3.72, 3.81, 3.91, 4.01, 4.12],
    "c22": [2.52, 2.63, 2.75, 2.88, 3.01, 3.14, 3.28, 3.41, 3.54, 3.67],
    "c23": [0.473, 0.603, 0.715, 0.823, 0.929, 1.03, 1.14, 1.25, 1.36, 1.47],
}
#: Kalker 1990, Table E.3, ν = 0.25, branch b/a ≤ 1.
B_LE_A = {
    "c11": [11.7, 7.78, 6.34, 5.57, 5.10, 4.78, 4.54, 4.36, 4.22, 4.12],
    "c22": [12.8, 8.14, 6.40, 5.48, 4.90, 4.50, 4.21, 3.99, 3.81, 3.67],
    "c23": [14.6, 6.63, 4.32, 3.24, 2.62, 2.23, 1.95, 1.75, 1.59, 1.47],
}
#: The Poisson's ratio of the table column used.
KALKER_POISSON = 0.25


@dataclass(frozen=True)
class Steel:
    """Wheel and rail steel. E = 2.1e11 Pa is the value the handbooks quote for rail steel
    (Iwnicki 2006, ch. on wheel-rail contact); ν = 0.25 is the column of Kalker's table used."""

    youngs_modulus: float = 2.1e11
    poisson: float = KALKER_POISSON

    @property
    def shear_modulus(self) -> float:
        """G = E / (2(1 + ν)), Pa."""
        return self.youngs_modulus / (2.0 * (1.0 + self.poisson))

    @property
    def contact_modulus(self) -> float:
        """E* with 1/E* = 2(1 − ν²)/E (two bodies of the same steel), Pa."""
        return self.youngs_modulus / (2.0 * (1.0 - self.poisson**2))


@dataclass(frozen=True)
class Ellipse:
    """Hertz contact ellipse: semi-axes a (rolling direction) and b (lateral), m."""

    a: float
    b: float


def hertz_ellipse(load: float, curv_x: float, curv_y: float, steel: Steel = Steel()) -> Ellipse:
    """Semi-axes (m) of the Hertz ellipse under ``load`` (N) for the relative curvature sums
    ``curv_x`` (rolling direction) and ``curv_y`` (lateral), 1/m."""
    e_star = steel.contact_modulus
    small, large = sorted((curv_x, curv_y))
    if np.isclose(small, large, rtol=1e-12):
        radius = (3.0 * load / (8.0 * e_star * small)) ** (1.0 / 3.0)
        return Ellipse(radius, radius)

    def mismatch(e2: float) -> float:
        k, e = ellipk(e2), ellipe(e2)
        return (e / (1.0 - e2) - k) / (k - e) - large / small

    e2 = brentq(mismatch, 1e-12, 1.0 - 1e-15, xtol=1e-15, rtol=1e-14)
    k, e = ellipk(e2), ellipe(e2)
    major = (3.0 * load * (k - e) / (2.0 * np.pi * e_star * e2 * small)) ** (1.0 / 3.0)
    minor = major * np.sqrt(1.0 - e2)
    # The major axis lies along the direction of the smaller curvature sum.
    return Ellipse(major, minor) if curv_x <= curv_y else Ellipse(minor, major)


def kalker_coefficients(a: float, b: float) -> dict[str, float]:
    """Kalker's C11, C22, C23 (ν = 0.25) for semi-axes a (rolling direction) and b, linear in
    g between the table rows; outside g ∈ [0.1, 1] the table has no rows, which is refused."""
    table, g = (A_LE_B, a / b) if a <= b else (B_LE_A, b / a)
    if g < TABLE_G[0] - 1e-12:
        raise ValueError(f"axis ratio {g:.3f} below Kalker's table (0.1)")
    return {name: float(np.interp(g, TABLE_G, column)) for name, column in table.items()}


@dataclass(frozen=True)
class CreepCoefficients:
    """Per-contact linear creep coefficients: f11, f22 (N), f23 (N·m), and the ellipse."""

    f11: float
    f22: float
    f23: float
    ellipse: Ellipse


def creep_coefficients(
    load: float, curv_x: float, curv_y: float, steel: Steel = Steel()
) -> CreepCoefficients:
    """Kalker's linear coefficients at one contact under the normal ``load`` (N) with the
    relative curvature sums ``curv_x`` and ``curv_y`` (1/m)."""
    ell = hertz_ellipse(load, curv_x, curv_y, steel)
    c = kalker_coefficients(ell.a, ell.b)
    g, cc = steel.shear_modulus, np.sqrt(ell.a * ell.b)
    return CreepCoefficients(
        f11=g * cc**2 * c["c11"], f22=g * cc**2 * c["c22"], f23=g * cc**3 * c["c23"], ellipse=ell
    )
