"""A single wheelset on springs to a fixed frame: lateral y and yaw ψ, linear creep.

Equations of motion (Wickens, *Fundamentals of Rail Vehicle Dynamics*, Swets & Zeitlinger 2003,
ch. 5, the wheelset with lateral and yaw restraint; Iwnicki (ed.), *Handbook of Railway Vehicle
Dynamics*, CRC 2006, the chapter on the stability of the wheelset), with the speed V (m/s):

    m ÿ + 2 f22 (ẏ − V ψ)/V + (k_y + k_g) y = 0
    I ψ̈ + 2 f11 l0 (l0 ψ̇ + V λ y / r0)/V + k_ψ ψ = 0

m (kg) the mass, I (kg·m²) the yaw inertia, f11, f22 (N) the longitudinal and lateral creep
coefficients of one contact, λ (–) the conicity, r0 (m) the rolling radius, l0 (m) the contact
semi-distance, k_y (N/m) and k_ψ (N·m/rad) the restraints to the frame (k_ψ = 2 k_x b² for
longitudinal springs k_x at ±b), k_g (N/m) the optional gravitational stiffness. Spin creep is
neglected (coned wheels, small contact angle), as in the textbook's simplest model.

Closed forms, derived here from these equations:
- the characteristic polynomial a4 s⁴ + a3 s³ + a2 s² + a1 s + a0 with c1 = 2 f11 l0²/V,
  c2 = 2 f22/V, K = k_y + k_g: a4 = m I, a3 = m c1 + I c2, a2 = m k_ψ + I K + c1 c2,
  a1 = c2 k_ψ + c1 K, a0 = K k_ψ + 4 f11 f22 λ l0 / r0; by Routh-Hurwitz the critical speed
  is where a1 a2 a3 = a0 a3² + a4 a1², which with c1, c2 ∝ 1/V is solved for V² exactly;
- its limit for large creep coefficients, V_c² = (r0 l0/λ) (f22 k_ψ + f11 l0² K) /
  (f11 l0² m + f22 I), for f11 = f22 the textbook's V_c² = (r0 l0/λ)(k_ψ + K l0²)/(I + m l0²);
- Klingel's kinematic wavelength of the free wheelset, 2π √(r0 l0 / λ), and its first
  corrections for inertia: L/L_K ≈ 1 − ε2/2 + 5ε²/8 with ε = ω0 V (m/(2f22) + I/(2 f11 l0²)),
  ε2 = ω0² V² m I / (4 f11 f22 l0²), ω0 = V √(λ/(r0 l0)) (perturbation of the characteristic
  equation about its kinematic root).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np


@dataclass(frozen=True)
class SuspendedWheelset:
    """Parameters (SI). Defaults: the Manchester benchmark's Vehicle 1 wheelset (1813 kg,
    1120 kg·m², r0 = 0.46 m; ``shared/data/manchester_vehicle1``), l0 = 0.75 m (the nominal
    1500 mm between rolling circles of EN 15302 for standard gauge), λ = 0.1, creep
    coefficients of the order of Vehicle 1's (f11 9.8e6 N, f22 9.0e6 N from
    ``contact_coefficients`` at its 54.5 kN wheel load), and a soft restraint, k_y = 1e6 N/m and
    k_ψ = 2e6 N·m/rad: a test case whose critical speed (about 64 m/s) lies inside the scanned
    range. Vehicle 1's own primary stiffnesses (2 × 3.884e6 N/m, 2 × 3.1391e7 N/m at ±1 m)
    hold a wheelset to a fixed frame so firmly that it is stable at every speed."""

    mass: float = 1813.0
    yaw_inertia: float = 1120.0
    rolling_radius: float = 0.46
    contact_semi_distance: float = 0.75
    conicity: float = 0.1
    f11: float = 9.8e6
    f22: float = 9.0e6
    lateral_stiffness: float = 1.0e6
    yaw_stiffness: float = 2.0e6
    gravitational_stiffness: float = 0.0

    @classmethod
    def on_axle_boxes(
        cls, lateral: float, longitudinal: float, semi_spacing: float, **kwargs: float
    ) -> SuspendedWheelset:
        """The wheelset held by two axle boxes, each of ``lateral`` and ``longitudinal``
        stiffness (N/m), at ±``semi_spacing`` (m): k_y = 2 k_lat, k_ψ = 2 k_x b²."""
        return cls(
            lateral_stiffness=2 * lateral,
            yaw_stiffness=2 * longitudinal * semi_spacing**2,
            **kwargs,
        )

    def free(self) -> SuspendedWheelset:
        """The same wheelset with no restraint (Klingel's free wheelset)."""
        return replace(self, lateral_stiffness=0.0, yaw_stiffness=0.0, gravitational_stiffness=0.0)

    def matrices(self, speed: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """M, C, K of [y, ψ] at ``speed`` (m/s); V < 0 runs backwards (creep over |V|)."""
        v, av = speed, abs(speed)
        lam, r0, l0 = self.conicity, self.rolling_radius, self.contact_semi_distance
        m = np.diag([self.mass, self.yaw_inertia])
        c = np.diag([2 * self.f22 / av, 2 * self.f11 * l0**2 / av])
        k = np.array(
            [
                [self.lateral_stiffness + self.gravitational_stiffness, -2 * self.f22 * v / av],
                [2 * self.f11 * l0 * lam * v / (r0 * av), self.yaw_stiffness],
            ]
        )
        return m, c, k

    def klingel_wavelength(self) -> float:
        """2π √(r0 l0 / λ), m."""
        return 2 * np.pi * np.sqrt(self.rolling_radius * self.contact_semi_distance / self.conicity)

    def klingel_correction(self, speed: float) -> float:
        """Predicted L/L_K − 1 of the free wheelset at ``speed`` to second order (–)."""
        l0 = self.contact_semi_distance
        w0 = speed * np.sqrt(self.conicity / (self.rolling_radius * l0))
        eps = w0 * speed * (self.mass / (2 * self.f22) + self.yaw_inertia / (2 * self.f11 * l0**2))
        eps2 = (w0 * speed) ** 2 * self.mass * self.yaw_inertia / (4 * self.f11 * self.f22 * l0**2)
        return -eps2 / 2 + 5 * eps**2 / 8

    def critical_speed_closed_form(self) -> float:
        """The Routh-Hurwitz critical speed (m/s) of the equations above, exact; ``inf`` when
        the crossing condition has no real speed (stable at every speed)."""
        m, i, lam = self.mass, self.yaw_inertia, self.conicity
        r0, l0 = self.rolling_radius, self.contact_semi_distance
        kk, kp = self.lateral_stiffness + self.gravitational_stiffness, self.yaw_stiffness
        c1, c2 = 2 * self.f11 * l0**2, 2 * self.f22  # times 1/V
        a3, a1, b = m * c1 + i * c2, c2 * kp + c1 * kk, m * kp + i * kk
        a0 = kk * kp + 4 * self.f11 * self.f22 * lam * l0 / r0
        denominator = a0 * a3**2 + m * i * a1**2 - a1 * a3 * b
        if denominator <= 0.0:
            return float("inf")
        return float(np.sqrt(a1 * a3 * c1 * c2 / denominator))

    def critical_speed_large_creep(self) -> float:
        """The limit of the critical speed (m/s) for large creep coefficients."""
        m, i, lam = self.mass, self.yaw_inertia, self.conicity
        r0, l0 = self.rolling_radius, self.contact_semi_distance
        kk, kp = self.lateral_stiffness + self.gravitational_stiffness, self.yaw_stiffness
        num = self.f22 * kp + self.f11 * l0**2 * kk
        return float(np.sqrt(r0 * l0 / lam * num / (self.f11 * l0**2 * m + self.f22 * i)))
