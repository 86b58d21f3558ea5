"""The classical 17-degree-of-freedom linear lateral model of a two-bogie vehicle.

Coordinates (Garg & Dukkipati, *Dynamics of Railway Vehicle Systems*, Academic Press 1984,
ch. on the lateral stability of a passenger car; Iwnicki (ed.), *Handbook of Railway Vehicle
Dynamics*, 2006): four wheelsets (lateral y, yaw ψ), two bogie frames (y, ψ, roll φ) and the
car body (y, ψ, φ): 8 + 6 + 3 = 17. Axes: x forward (the running direction at V > 0), y to the
left, z up; ψ about z, φ about x, right-handed. Order of the coordinates: wheelsets 0-3 (front
to rear: the leading bogie's two, then the trailing bogie's), bogies 0-1, car body.

The equations are assembled from each element's energy (Lagrange, as the textbook's are
written term by term): a point at (x, y, z) from a body's centre of gravity moves laterally by
y_B + x ψ − z φ, longitudinally by −y ψ, vertically by y φ; a spring k between two points adds
k g gᵀ to K, with g the gradient of its deflection over the coordinates (a damper likewise to C);
a rotational element (anti-roll bar, anti-bending stiffness) acts on the difference of two
angles. Gravity: a vertical spring of preload P acting on a body at height z from its centre of
gravity adds P z (upper body) or −P z (lower body) to that body's roll stiffness, so a body on
springs below its centre of gravity loses W·h.

Wheel-rail forces of wheelset i (Wickens 2003, ch. 5; per contact f11, f22, f23, two contacts):
    F_y = −2 f22 (ẏ − V ψ)/|V| − 2 sgn(V) f23 ψ̇/|V|               (spin term optional)
    M_z = −2 f11 l0 (λ V y / r0 + l0 ψ̇)/|V| + 2 sgn(V) f23 (ẏ − V ψ)/|V|
with λ the conicity, r0 the rolling radius, l0 the contact semi-distance; gravitational
stiffness −k_g y optional. Running backwards (V < 0) is the mirror image: under x → −x
(ψ → −ψ, positions x → −x) the model at −V is the model at V.
All quantities SI: masses kg, inertias kg·m², lengths m, stiffnesses N/m and N·m/rad, damping
N·s/m, speeds m/s.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .state_space import Matrices
from .vehicle1_parameters import Element, G, Vehicle1

N_DOF = 17


@dataclass(frozen=True)
class BodyDofs:
    """Indices of a body's y, ψ, φ coordinates (φ None for a wheelset), its longitudinal
    position x (m, from the car body's centre) and centre-of-gravity height (m)."""

    y: int
    psi: int
    phi: int | None
    x: float
    height: float

    @property
    def roll(self) -> int:
        """The roll coordinate's index (bogies and car body; a wheelset has none)."""
        if self.phi is None:
            raise ValueError("a wheelset has no roll coordinate")
        return self.phi


def layout(v: Vehicle1) -> tuple[list[BodyDofs], list[BodyDofs], BodyDofs]:
    """The wheelsets, the bogies and the car body with their coordinates."""
    bogies = [
        BodyDofs(8 + 3 * j, 9 + 3 * j, 10 + 3 * j, x, v.bogie.height)
        for j, x in enumerate((v.bogie_semi_distance, -v.bogie_semi_distance))
    ]
    wheelsets = []
    for j, bogie in enumerate(bogies):
        for k, dx in enumerate((v.wheelbase_semi, -v.wheelbase_semi)):
            i = 2 * j + k
            wheelsets.append(BodyDofs(2 * i, 2 * i + 1, None, bogie.x + dx, v.rolling_radius))
    carbody = BodyDofs(14, 15, 16, 0.0, v.carbody.height)
    return wheelsets, bogies, carbody


def _gradient(body: BodyDofs, point: tuple[float, float, float], direction: str) -> np.ndarray:
    """Gradient over the coordinates of a body point's displacement along x, y or z; the point
    is given in vehicle axes (x from the car body's centre, z above the rail)."""
    g = np.zeros(N_DOF)
    px, py, pz = point[0] - body.x, point[1], point[2] - body.height
    if direction == "y":
        g[body.y] = 1.0
        g[body.psi] = px
        if body.phi is not None:
            g[body.phi] = -pz
    elif direction == "x":
        g[body.psi] = -py
    else:
        if body.phi is not None:
            g[body.phi] = py
    return g


def suspension(v: Vehicle1) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """M, C, K of the suspension and gravity alone (no wheel-rail forces)."""
    wheelsets, bogies, carbody = layout(v)
    m, c, k = np.zeros((N_DOF, N_DOF)), np.zeros((N_DOF, N_DOF)), np.zeros((N_DOF, N_DOF))
    for w in wheelsets:
        m[w.y, w.y], m[w.psi, w.psi] = v.wheelset.mass, v.wheelset.yaw_inertia
    for b in [*bogies, carbody]:
        body = v.carbody if b is carbody else v.bogie
        m[b.y, b.y], m[b.psi, b.psi] = body.mass, body.yaw_inertia
        m[b.roll, b.roll] = body.roll_inertia

    def spring(
        lower: BodyDofs,
        upper: BodyDofs,
        point: tuple[float, float, float],
        direction: str,
        element: Element,
    ) -> None:
        g = _gradient(upper, point, direction) - _gradient(lower, point, direction)
        k[:] += element.stiffness * np.outer(g, g)
        c[:] += element.damping * np.outer(g, g)

    def preload(lower: BodyDofs, upper: BodyDofs, z: float, force: float) -> None:
        if not v.gravity:
            return
        if upper.phi is not None:
            k[upper.phi, upper.phi] += force * (z - upper.height)
        if lower.phi is not None:
            k[lower.phi, lower.phi] -= force * (z - lower.height)

    w_car, w_bogie = v.carbody.mass * G, v.bogie.mass * G
    for j, b in enumerate(bogies):
        for w in wheelsets[2 * j : 2 * j + 2]:
            for side in (1.0, -1.0):
                point = (w.x, side * v.primary_semi_spacing, v.primary_height)
                spring(w, b, point, "y", v.primary_lateral)
                spring(w, b, point, "x", v.primary_longitudinal)
                spring(w, b, point, "z", v.primary_vertical)
                preload(w, b, v.primary_height, (w_car / 2 + w_bogie) / 4)
        for side in (1.0, -1.0):
            point = (b.x, side * v.secondary_semi_spacing, v.secondary_height)
            spring(b, carbody, point, "y", v.secondary_lateral)
            spring(b, carbody, point, "x", v.secondary_longitudinal)
            spring(b, carbody, point, "z", v.secondary_vertical)
            preload(b, carbody, v.secondary_height, w_car / 4)
        for angle, stiffness in (("phi", v.anti_roll_per_bogie), ("psi", v.anti_bending_per_bogie)):
            g = np.zeros(N_DOF)
            g[getattr(carbody, angle)], g[getattr(b, angle)] = 1.0, -1.0
            k[:] += stiffness * np.outer(g, g)
    return m, c, k


def creep_terms(v: Vehicle1, conicity: float, speed: float) -> tuple[np.ndarray, np.ndarray]:
    """The wheel-rail forces' damping and stiffness matrices at ``speed`` (m/s)."""
    cr = v.creep()
    f11, f22, f23 = cr.f11, cr.f22, (cr.f23 if v.spin else 0.0)
    r0, l0 = v.rolling_radius, v.contact_semi_distance
    av, s = abs(speed), np.sign(speed)
    c, k = np.zeros((N_DOF, N_DOF)), np.zeros((N_DOF, N_DOF))
    for w in layout(v)[0]:
        y, p = w.y, w.psi
        c[y, y] += 2 * f22 / av
        k[y, p] += -2 * f22 * s
        k[y, y] += v.gravitational_stiffness
        c[p, p] += 2 * f11 * l0**2 / av
        k[p, y] += 2 * f11 * l0 * conicity * s / r0
        c[y, p] += 2 * s * f23 / av
        c[p, y] += -2 * s * f23 / av
        k[p, p] += 2 * f23
    return c, k


def model(v: Vehicle1, conicity: float) -> Matrices:
    """The model as a function of speed: V -> (M, C, K) (SI), for ``state_space``."""
    m, cs, ks = suspension(v)

    def matrices(speed: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        cc, kc = creep_terms(v, conicity, speed)
        return m, cs + cc, ks + kc

    return matrices


def mirror(v: Vehicle1) -> np.ndarray:
    """The fore-aft mirror x → −x as a matrix on the coordinates: wheelsets and bogies swap
    front for rear, yaw angles change sign, lateral and roll stay."""
    wheelsets, bogies, carbody = layout(v)
    t = np.zeros((N_DOF, N_DOF))
    for group in (wheelsets, bogies):
        for a, b in zip(group, group[::-1], strict=True):
            t[a.y, b.y] = 1.0
            t[a.psi, b.psi] = -1.0
            if a.phi is not None:
                t[a.phi, b.phi] = 1.0
    t[carbody.y, carbody.y], t[carbody.psi, carbody.psi] = 1.0, -1.0
    t[carbody.phi, carbody.phi] = 1.0
    return t


def running_gear_dofs(v: Vehicle1) -> list[int]:
    """The wheelsets' and bogies' lateral and yaw coordinates."""
    wheelsets, bogies, _ = layout(v)
    return [i for b in [*wheelsets, *bogies] for i in (b.y, b.psi)]
