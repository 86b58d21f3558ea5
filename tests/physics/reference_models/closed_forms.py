"""The textbook closed forms the models are checked against (SI).

Kinematic (creep-dominated, inertia-free) wavelengths, m:

- Klingel (1883), the free coned wheelset: L = 2π √(r0 l0 / λ).
- Wickens (*Fundamentals of Rail Vehicle Dynamics*, 2003, ch. on the bogie; also Iwnicki
  (ed.), *Handbook of Railway Vehicle Dynamics*, 2006), the rigid two-axle bogie of semi-
  wheelbase a with f11 = f22: L = 2π √(r0 l0 / λ · (1 + a²/l0²)).
- The same with f11 ≠ f22, derived here from the rigid bogie's creep equilibrium (no inertia,
  no suspension): the lateral forces sum to zero, so ẏ = V ψ at the bogie centre, and the yaw
  moments, −4 f22 a² ψ̇/V − 4 f11 l0 (λ y / r0 + l0 ψ̇/V) = 0, give
  L = 2π √(r0 l0 / λ · (1 + (f22/f11) a²/l0²)), which is Wickens' form at f11 = f22.

Steady curving offsets, m (curve to the left for R > 0, offsets positive to the left):
- a wheelset free in yaw rolls round the curve where its rolling radius difference 2λy
  matches the rails' path difference 2 r0 l0/R: y = −r0 l0/(λR) (Wickens 2003; Iwnicki 2006);
- a rigid two-axle bogie with no secondary and no lateral load (Boocock 1969; Wickens 2003):
  its lateral balance gives ψ_b = 0 (both wheelsets' lateral creep forces cancel), so the
  wheelsets at ±a are at ψ = ∓a/R from their tangents, and its yaw balance,
  −4 f22 a²/R − 4 f11 l0 (λ y/r0 + l0/R) = 0 at the wheelsets' common offset y, gives
  y = −(r0/(λR)) (l0 + (f22/f11) a²/l0).
r0 rolling radius, l0 contact semi-distance, λ conicity, a semi-wheelbase, R radius.
"""

from __future__ import annotations

import numpy as np


def klingel(rolling_radius: float, contact_semi_distance: float, conicity: float) -> float:
    """2π √(r0 l0 / λ), m."""
    return float(2 * np.pi * np.sqrt(rolling_radius * contact_semi_distance / conicity))


def rigid_bogie_wavelength(
    rolling_radius: float,
    contact_semi_distance: float,
    conicity: float,
    semi_wheelbase: float,
    f22_over_f11: float = 1.0,
) -> float:
    """2π √(r0 l0 / λ · (1 + (f22/f11) a²/l0²)), m; Wickens' rigid bogie at f22/f11 = 1."""
    ratio = 1.0 + f22_over_f11 * (semi_wheelbase / contact_semi_distance) ** 2
    return klingel(rolling_radius, contact_semi_distance, conicity) * float(np.sqrt(ratio))


def pure_rolling_offset(
    rolling_radius: float, contact_semi_distance: float, conicity: float, radius: float
) -> float:
    """y = −r0 l0 / (λ R), m."""
    return -rolling_radius * contact_semi_distance / (conicity * radius)


def rigid_bogie_offset(
    rolling_radius: float,
    contact_semi_distance: float,
    conicity: float,
    semi_wheelbase: float,
    radius: float,
    f22_over_f11: float = 1.0,
) -> float:
    """y = −(r0/(λR)) (l0 + (f22/f11) a²/l0), m, both wheelsets of the rigid bogie."""
    l0 = contact_semi_distance
    return -rolling_radius / (conicity * radius) * (l0 + f22_over_f11 * semi_wheelbase**2 / l0)
