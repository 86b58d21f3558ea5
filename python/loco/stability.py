"""Linear stability of the locomotive: eigenvalues about equilibrium and the critical speed.

The state matrix comes from the Rust model itself (central differences of the full nonlinear
right-hand side about the static equilibrium on perfect track, `loco._loco.linearise`), so the
eigenvalues belong to exactly the model the time integration runs; numpy/LAPACK computes them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco.simulation import Scenario
from loco.vehicle import Locomotive, dof_names

__all__ = ["Eigen", "Mode", "critical_speed", "eigen"]

FloatArray = npt.NDArray[np.float64]
N_DOF = 90


@dataclass(frozen=True)
class Mode:
    """One oscillatory mode: frequency (Hz), damping ratio (–) and the bodies that move."""

    frequency: float
    damping_ratio: float
    eigenvalue: complex
    bodies: dict[str, float]

    def describe(self, top: int = 3) -> str:
        """``"1.23 Hz, ζ = 4.5 %: carbody 62 %, frame1 20 %, ..."``."""
        parts = sorted(self.bodies.items(), key=lambda kv: -kv[1])[:top]
        share = ", ".join(f"{b} {100 * v:.0f} %" for b, v in parts)
        return f"{self.frequency:.3f} Hz, ζ = {100 * self.damping_ratio:.2f} %: {share}"


@dataclass(frozen=True)
class Eigen:
    """All oscillatory modes at one speed, sorted by damping ratio (least damped first)."""

    speed: float
    modes: list[Mode]

    def least_damped(self, min_frequency: float = 0.3, max_frequency: float = 20.0) -> Mode:
        """The least damped mode within a frequency band (hunting and body modes, not drift)."""
        band = [m for m in self.modes if min_frequency <= m.frequency <= max_frequency]
        if not band:
            raise _loco.ParameterError("invalid parameter `band`: no mode in the frequency band")
        return band[0]


def _body_shares(vector: npt.NDArray[np.complex128], names: list[str]) -> dict[str, float]:
    """Share of each body in the mode's displacements (by |amplitude|², translations in m and
    rotations in rad weighted alike)."""
    weights = np.abs(vector[:N_DOF]) ** 2
    total = float(weights.sum()) or 1.0
    shares: dict[str, float] = {}
    for name, w in zip(names, weights, strict=True):
        body = name.split(".")[0]
        shares[body] = shares.get(body, 0.0) + float(w) / total
    return shares


def eigen(vehicle: Locomotive, scenario: Scenario) -> Eigen:
    """Eigenvalues of the vehicle linearised about equilibrium at ``scenario.speed`` (m/s) with
    the scenario's wheel/rail pair (and so its equivalent conicity) and yaw damper."""
    a = _loco.linearise(
        scenario.native(),
        toml_text=vehicle.toml_text,
        origin=vehicle.origin,
        overrides=dict(vehicle.overrides),
    )
    values, vectors = np.linalg.eig(a)
    names = dof_names()
    modes = []
    for k, lam in enumerate(values):
        if lam.imag <= 1e-6:  # one of each conjugate pair; real (overdamped) roots skipped
            continue
        modes.append(
            Mode(
                frequency=float(abs(lam.imag) / (2 * np.pi)),
                damping_ratio=float(-lam.real / abs(lam)),
                eigenvalue=complex(lam),
                bodies=_body_shares(vectors[:, k], names),
            )
        )
    modes.sort(key=lambda m: m.damping_ratio)
    return Eigen(speed=float(scenario.speed), modes=modes)


def critical_speed(
    vehicle: Locomotive,
    scenario: Scenario,
    low: float = 20.0,
    high: float = 110.0,
    tolerance: float = 0.5,
    band: tuple[float, float] = (0.3, 20.0),
) -> float:
    """Linear critical speed (m/s): where the least damped mode in ``band`` (Hz) loses its
    damping, by bisection between ``low`` and ``high`` (m/s). Returns ``inf`` when the vehicle
    is stable at ``high`` and ``low`` when it is already unstable there."""

    def zeta(speed: float) -> float:
        s = Scenario(**{**scenario.__dict__, "speed": speed})
        return eigen(vehicle, s).least_damped(*band).damping_ratio

    if zeta(high) > 0.0:
        return float("inf")
    if zeta(low) <= 0.0:
        return low
    while high - low > tolerance:
        mid = 0.5 * (low + high)
        if zeta(mid) > 0.0:
            low = mid
        else:
            high = mid
    return 0.5 * (low + high)
