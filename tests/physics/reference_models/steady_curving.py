"""Linear steady curving (Boocock, "Steady-state motion of railway vehicles on curved track",
J. Mech. Eng. Sci. 11 (1969) 556-566; as given in Wickens, *Fundamentals of Rail Vehicle
Dynamics*, 2003, ch. on curving): wheelset lateral offsets and angles of attack on a curve of
radius R with linear creep, no flange contact.

Coordinates: each body's y (m) is its offset from the track centreline at its own position x
(positive to the left) and ψ (rad) its yaw from the local tangent; a curve to the left has
R > 0 (the outer rail is on the right, −y). In axes that follow the tangent at the vehicle's
centre the track runs at x²/(2R) with the heading x/R, so a body at x_k sits at
y_k + x_k²/(2R), ψ_k + x_k/R there: the suspension (linear in those axes) pulls with
−K_s (q + q_c), q_c the bodies' x²/(2R) and x/R. A wheelset rolling round the curve yaws at
V/R, so its longitudinal creepage gains l0/R: its yaw moment gains −2 f11 l0²/R (and the spin
term, when it is on, adds −2 f23/R to the lateral force). An unbalanced lateral acceleration
a (m/s², cant deficiency × g / track gauge base) pushes every body outward with m·a.

Two formulations, written separately so that each checks the other:
- ``vehicle_curving``: the 17-coordinate model of ``lateral_vehicle_model`` solved for its
  static equilibrium, with any coordinates clamped at given values;
- ``boocock_bogie``: Boocock's equations written out for one two-axle bogie whose secondary
  suspension acts on a car body held at a given place: per wheelset i at s_i = ±a from the
  bogie centre, with Δ_i = y_i + s_i²/(2R) − y_b − s_i ψ_b the primary lateral deflection and
  ε_i = ψ_i + s_i/R − ψ_b the yaw against the frame,
      2 f22 ψ_i − k_g y_i − k_py Δ_i − m_w a = 0
      −2 f11 l0 (λ y_i / r0 + l0/R) − k_pψ ε_i = 0
  and the frame
      Σ k_py Δ_i − k_sy (y_b − y_c) − m_b a = 0
      Σ (s_i k_py Δ_i + k_pψ ε_i) − k_sψ (ψ_b − ψ_c) = 0
  (k_py, k_pψ = 2 k_x b² per wheelset; k_sy, k_sψ = 2 k_sx b_s² + anti-bending per bogie;
  y_c, ψ_c the car body's offset and yaw at the pivot from the bogie's local track).
The closed forms they are checked against are in ``closed_forms``. All SI.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .lateral_vehicle_model import N_DOF, creep_terms, layout, suspension
from .vehicle1_parameters import Vehicle1


@dataclass(frozen=True)
class Curving:
    """Wheelset offsets y (m, to the left of the centreline) and angles of attack ψ (rad, from
    the local tangent), front to rear, and the whole coordinate vector."""

    offsets: np.ndarray
    attack_angles: np.ndarray
    coordinates: np.ndarray


def curve_offsets(v: Vehicle1, radius: float) -> np.ndarray:
    """q_c: every body's x²/(2R) in y and x/R in ψ."""
    wheelsets, bogies, carbody = layout(v)
    q = np.zeros(N_DOF)
    for b in [*wheelsets, *bogies, carbody]:
        q[b.y], q[b.psi] = b.x**2 / (2 * radius), b.x / radius
    return q


def vehicle_curving(
    v: Vehicle1,
    conicity: float,
    radius: float,
    unbalanced_acceleration: float = 0.0,
    clamped: dict[int, float] | None = None,
    speed: float = 30.0,
) -> Curving:
    """The 17-coordinate model's steady state on the curve (``speed`` only sets the sign of the
    creep terms, which are speed-independent at steady state). ``unbalanced_acceleration``
    (m/s², ≥ 0 outward); ``clamped``: coordinates held at the given values."""
    wheelsets, bogies, carbody = layout(v)
    _, _, ks = suspension(v)
    _, kc = creep_terms(v, conicity, speed)
    k = ks + kc
    f = -ks @ curve_offsets(v, radius)
    cr = v.creep()
    outward = -np.sign(radius) * unbalanced_acceleration
    for w in wheelsets:
        f[w.psi] += -2 * cr.f11 * v.contact_semi_distance**2 / radius
        if v.spin:
            f[w.y] += -2 * cr.f23 / radius
        f[w.y] += v.wheelset.mass * outward
    for b in bogies:
        f[b.y] += v.bogie.mass * outward
    f[carbody.y] += v.carbody.mass * outward
    q = np.zeros(N_DOF)
    clamped = clamped or {}
    fixed = sorted(clamped)
    free = [i for i in range(N_DOF) if i not in fixed]
    for i in fixed:
        q[i] = clamped[i]
    q[free] = np.linalg.solve(k[np.ix_(free, free)], f[free] - k[np.ix_(free, fixed)] @ q[fixed])
    return Curving(
        offsets=np.array([q[w.y] for w in wheelsets]),
        attack_angles=np.array([q[w.psi] for w in wheelsets]),
        coordinates=q,
    )


@dataclass(frozen=True)
class BoocockBogie:
    """Inputs of Boocock's two-axle bogie equations, SI (per wheelset / per bogie totals)."""

    semi_wheelbase: float
    rolling_radius: float
    contact_semi_distance: float
    f11: float
    f22: float
    primary_lateral: float
    primary_yaw: float
    secondary_lateral: float = 0.0
    secondary_yaw: float = 0.0
    gravitational_stiffness: float = 0.0
    wheelset_mass: float = 0.0
    bogie_mass: float = 0.0

    @classmethod
    def of(cls, v: Vehicle1) -> BoocockBogie:
        """Vehicle 1's bogie."""
        cr = v.creep()
        return cls(
            semi_wheelbase=v.wheelbase_semi,
            rolling_radius=v.rolling_radius,
            contact_semi_distance=v.contact_semi_distance,
            f11=cr.f11,
            f22=cr.f22,
            primary_lateral=2 * v.primary_lateral.stiffness,
            primary_yaw=2 * v.primary_longitudinal.stiffness * v.primary_semi_spacing**2,
            secondary_lateral=2 * v.secondary_lateral.stiffness,
            secondary_yaw=2 * v.secondary_longitudinal.stiffness * v.secondary_semi_spacing**2
            + v.anti_bending_per_bogie,
            gravitational_stiffness=v.gravitational_stiffness,
            wheelset_mass=v.wheelset.mass,
            bogie_mass=v.bogie.mass,
        )


def boocock_bogie(
    p: BoocockBogie,
    conicity: float,
    radius: float,
    unbalanced_acceleration: float = 0.0,
    body_offset: float = 0.0,
    body_yaw: float = 0.0,
) -> np.ndarray:
    """[y1, ψ1, y2, ψ2, y_b, ψ_b] (m, rad; wheelset 1 leading at s = +a) from the six
    equations of the module docstring; the car body at ``body_offset``, ``body_yaw`` from the
    bogie's local track at the pivot."""
    a, kappa = p.semi_wheelbase, 1.0 / radius
    l0, r0, lam = p.contact_semi_distance, p.rolling_radius, conicity
    out = -np.sign(radius) * unbalanced_acceleration
    j, rhs = np.zeros((6, 6)), np.zeros(6)
    for i, s in enumerate((a, -a)):
        iy, ip = 2 * i, 2 * i + 1
        # Δ_i = y_i − y_b − s ψ_b + s²κ/2 ; ε_i = ψ_i − ψ_b + sκ.
        delta = np.zeros(6)
        delta[iy], delta[4], delta[5] = 1.0, -1.0, -s
        delta_c = s * s * kappa / 2
        eps = np.zeros(6)
        eps[ip], eps[5] = 1.0, -1.0
        eps_c = s * kappa
        # Wheelset lateral: 2 f22 ψ_i − k_g y_i − k_py Δ_i = m_w a_out... moved to the right.
        j[iy, ip] += 2 * p.f22
        j[iy, iy] -= p.gravitational_stiffness
        j[iy] -= p.primary_lateral * delta
        rhs[iy] += p.primary_lateral * delta_c - p.wheelset_mass * out
        # Wheelset yaw: −2 f11 l0 (λ y_i/r0 + l0 κ) − k_pψ ε_i = 0.
        j[ip, iy] -= 2 * p.f11 * l0 * lam / r0
        j[ip] -= p.primary_yaw * eps
        rhs[ip] += 2 * p.f11 * l0 * l0 * kappa + p.primary_yaw * eps_c
        # Frame lateral and yaw: the reactions of the primary.
        j[4] += p.primary_lateral * delta
        rhs[4] -= p.primary_lateral * delta_c
        j[5] += s * p.primary_lateral * delta + p.primary_yaw * eps
        rhs[5] -= s * p.primary_lateral * delta_c + p.primary_yaw * eps_c
    j[4, 4] -= p.secondary_lateral
    rhs[4] -= p.secondary_lateral * body_offset + p.bogie_mass * out
    j[5, 5] -= p.secondary_yaw
    rhs[5] -= p.secondary_yaw * body_yaw
    return np.linalg.solve(j, rhs)
