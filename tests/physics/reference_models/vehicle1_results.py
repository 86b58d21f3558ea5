"""Vehicle 1's reference results from the linear models, for the record and for the core's
coach to be checked against: per conicity the linear critical speed and the hunting frequency
there, the bogie kinematic mode at low speed against Wickens' rigid-bogie wavelength, and the
steady-curving offsets and angles of attack.

Run ``python -m reference_models.vehicle1_results`` from the ``tests`` directory to print the
table. Speeds m/s (and km/h), frequencies Hz, wavelengths m, offsets mm, angles mrad.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import state_space as ss
from .closed_forms import rigid_bogie_wavelength
from .lateral_vehicle_model import model
from .steady_curving import vehicle_curving
from .vehicle1_parameters import CONICITIES, Vehicle1

#: The low speed at which the kinematic mode is read, m/s.
LOW_SPEED = 2.0
#: The curve of the curving table, radius (m).
CURVE_RADIUS = 3000.0
#: The cant deficiency case: 100 mm on the 1.5 m between rolling circles, g·0.1/1.5 (m/s²).
UNBALANCED_ACCELERATION = 9.81 * 0.100 / 1.5


@dataclass(frozen=True)
class Row:
    """One conicity's results (SI unless named)."""

    conicity: float
    critical_speed: float
    hunting_frequency: float
    kinematic_wavelength: float
    kinematic_frequency: float
    rigid_bogie_wavelength: float
    offsets: np.ndarray
    attack_angles: np.ndarray
    offsets_cant_deficiency: np.ndarray
    attack_angles_cant_deficiency: np.ndarray


def row(v: Vehicle1, conicity: float) -> Row:
    """The results of one conicity."""
    matrices = model(v, conicity)
    vc = ss.critical_speed(matrices)
    values = ss.eigen(matrices, vc)[0]
    hunting = values[np.argmax(values.real)]
    kinematic = ss.kinematic_mode(matrices, LOW_SPEED)
    cr = v.creep()
    curving = vehicle_curving(v, conicity, CURVE_RADIUS)
    deficient = vehicle_curving(v, conicity, CURVE_RADIUS, UNBALANCED_ACCELERATION)
    return Row(
        conicity=conicity,
        critical_speed=vc,
        hunting_frequency=abs(hunting.imag) / (2 * np.pi),
        kinematic_wavelength=ss.wavelength(kinematic, LOW_SPEED),
        kinematic_frequency=kinematic.imag / (2 * np.pi),
        rigid_bogie_wavelength=rigid_bogie_wavelength(
            v.rolling_radius, v.contact_semi_distance, conicity, v.wheelbase_semi, cr.f22 / cr.f11
        ),
        offsets=curving.offsets,
        attack_angles=curving.attack_angles,
        offsets_cant_deficiency=deficient.offsets,
        attack_angles_cant_deficiency=deficient.attack_angles,
    )


def table(v: Vehicle1 | None = None) -> list[Row]:
    """The rows for the conicities 0.05, 0.1, 0.2, 0.3."""
    v = v or Vehicle1()
    return [row(v, lam) for lam in CONICITIES]


def _pairs(offsets: np.ndarray, angles: np.ndarray) -> str:
    return ", ".join(f"{y * 1e3:.2f}/{p * 1e3:.3f}" for y, p in zip(offsets, angles, strict=True))


def format_table(rows: list[Row]) -> str:
    """The rows as two plain-text tables: stability, then curving."""
    lines = ["conicity | V_crit m/s (km/h) | f_hunt Hz | L_kin m at 2 m/s (f Hz) | L rigid bogie m"]
    for r in rows:
        lines.append(
            f"{r.conicity:.2f} | {r.critical_speed:.2f} ({r.critical_speed * 3.6:.1f}) | "
            f"{r.hunting_frequency:.3f} | {r.kinematic_wavelength:.3f} "
            f"({r.kinematic_frequency:.4f}) | {r.rigid_bogie_wavelength:.3f}"
        )
    lines.append(
        f"R {CURVE_RADIUS:.0f} m, y mm / psi mrad of wheelsets 1-4: balance speed | "
        f"{UNBALANCED_ACCELERATION:.3f} m/s2 unbalanced"
    )
    for r in rows:
        lines.append(
            f"{r.conicity:.2f} | {_pairs(r.offsets, r.attack_angles)} | "
            f"{_pairs(r.offsets_cant_deficiency, r.attack_angles_cant_deficiency)}"
        )
    return "\n".join(lines)


if __name__ == "__main__":
    vehicle = Vehicle1()
    cr = vehicle.creep()
    print(
        f"wheel load {vehicle.wheel_load:.0f} N; ellipse a {cr.ellipse.a * 1e3:.3f} mm, "
        f"b {cr.ellipse.b * 1e3:.3f} mm; f11 {cr.f11:.4e} N, f22 {cr.f22:.4e} N, "
        f"f23 {cr.f23:.4e} N m"
    )
    print(format_table(table(vehicle)))
