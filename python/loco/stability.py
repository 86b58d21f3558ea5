"""Stability of the locomotive: eigenvalues about equilibrium and the critical speed.

The state matrix comes from the Rust model itself (central differences of the full nonlinear
right-hand side about the static equilibrium on perfect track, `loco._loco.linearise`), so the
eigenvalues belong to exactly the model the time integration runs; numpy/LAPACK computes them.
The nonlinear critical speed comes from a time simulation whose speed falls linearly after a
lateral disturbance (`loco._loco.ramp_down`): the speed at which the hunting limit cycle dies out.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco.simulation import Scenario
from loco.vehicle import Locomotive, dof_names

__all__ = ["Eigen", "Mode", "RampDown", "critical_speed", "eigen", "ramp_down"]

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


@dataclass(frozen=True)
class RampDown:
    """A speed ramp-down: the nonlinear critical speed (m/s) and the record behind it.

    ``outcome`` is ``"died_out"`` (the hunting limit cycle died out at ``critical_speed``),
    ``"stable_at_start"`` (no hunting at the start speed: ``critical_speed`` is ``inf``) or
    ``"hunts_at_end"`` (still hunting at the end speed, which ``critical_speed`` then is).
    ``speed`` (m/s) and ``amplitude`` (m) give each window's centre speed and hunting amplitude
    (half the peak-to-peak wheelset lateral displacement, largest of the four wheelsets).
    """

    critical_speed: float
    outcome: str
    speed: FloatArray
    amplitude: FloatArray


def ramp_down(
    vehicle: Locomotive,
    scenario: Scenario,
    end_speed: float = 20.0,
    deceleration: float = 0.5,
    hold: float = 3.0,
    max_hold: float = 30.0,
    disturbance: float = 8e-3,
    window: float = 1.0,
    threshold: float = 5e-4,
) -> RampDown:
    """Nonlinear critical speed by a speed ramp-down on perfect track.

    Every wheelset starts displaced by ``disturbance`` (m) along its rails; the speed stays at
    ``scenario.speed`` (m/s) for at least ``hold`` (s) and until the hunting amplitude has
    settled (at most ``max_hold``, s), then falls by ``deceleration`` (m/s²) down to ``end_speed``
    (m/s). Hunting has died out in the first window of ``window`` (s) whose amplitude is below
    ``threshold`` (m). The disturbance must be large: the default, 8 mm, reaches the flanges of
    worn wheels and finds the largest limit cycle, the one that survives down to the lowest speed.

    The detection follows the dying cycle's collapse, so the result is low by roughly
    ``deceleration`` times a few seconds (S_high with YD1, linear critical speed 39.2 m/s: 39.0,
    38.0 and 36.5 m/s at 0.25, 0.5 and 1 m/s² from 1.3 times that); halve ``deceleration`` to
    check it. Start well above the linear critical speed. Ctrl-C stops the run."""
    speed, outcome, speeds, amplitudes = _loco.ramp_down(
        scenario.native(),
        toml_text=vehicle.toml_text,
        origin=vehicle.origin,
        overrides=dict(vehicle.overrides),
        end_speed=float(end_speed),
        deceleration=float(deceleration),
        hold=float(hold),
        max_hold=float(max_hold),
        disturbance=float(disturbance),
        window=float(window),
        threshold=float(threshold),
    )
    return RampDown(critical_speed=speed, outcome=outcome, speed=speeds, amplitude=amplitudes)


def critical_speed(
    vehicle: Locomotive,
    scenario: Scenario,
    low: float = 20.0,
    high: float = 110.0,
    tolerance: float = 0.5,
    band: tuple[float, float] = (0.3, 20.0),
    *,
    method: str = "linear",
    deceleration: float = 0.5,
    disturbance: float = 8e-3,
) -> float:
    """Critical speed (m/s) of the vehicle in the scenario's wheel/rail pair and yaw damper.

    ``method="linear"``: where the least damped mode in ``band`` (Hz) loses its damping, by
    bisection between ``low`` and ``high`` (m/s) to ``tolerance`` (m/s). Returns ``inf`` when the
    vehicle is stable at ``high`` and ``low`` when it is already unstable there.

    ``method="nonlinear"``: the speed at which the hunting limit cycle dies out in a ramp-down
    (:func:`ramp_down`) from ``scenario.speed`` to ``low`` at ``deceleration`` (m/s²) after a
    ``disturbance`` (m). Returns ``inf`` when the vehicle does not hunt at ``scenario.speed`` and
    ``low`` when it still hunts there. On worn wheels (subcritical hunting) it lies at or below
    the linear critical speed."""
    if method == "nonlinear":
        return ramp_down(
            vehicle,
            scenario,
            end_speed=low,
            deceleration=deceleration,
            disturbance=disturbance,
        ).critical_speed
    if method != "linear":
        raise _loco.ParameterError(
            f"invalid parameter `method`: expected 'linear' or 'nonlinear', got '{method}'"
        )

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
