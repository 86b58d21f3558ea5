"""Stability of the locomotive: eigenvalues about equilibrium and the critical speed.

The state matrix comes from the Rust model itself (central differences of the full nonlinear
right-hand side about the static equilibrium on perfect track, `loco._loco.linearise`), so the
eigenvalues belong to exactly the model the time integration runs; numpy/LAPACK computes them.
The nonlinear critical speed comes from a time simulation whose speed falls linearly after a
lateral disturbance (`loco._loco.ramp_down`): the speed at which the hunting limit cycle dies out.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco.modes import Mode, body_masses, energy_shares
from loco.simulation import Scenario
from loco.vehicle import Locomotive

__all__ = ["Eigen", "Mode", "RampDown", "critical_speed", "eigen", "ramp_down", "with_conicity"]

FloatArray = npt.NDArray[np.float64]


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


def with_conicity(scenario: Scenario, conicity: float | None) -> Scenario:
    """``scenario`` with its wheel and rail replaced by a conical wheel of equivalent conicity
    ``conicity`` (–) on a knife-edge rail (Δr = 2·conicity·y exactly, no flange); unchanged when
    ``conicity`` is None."""
    if conicity is None:
        return scenario
    wheel, rail = _loco.conical_profiles(float(conicity))
    return dataclasses.replace(scenario, scenario=None, wheel=wheel, rail=rail)


def eigen(vehicle: Locomotive, scenario: Scenario, *, conicity: float | None = None) -> Eigen:
    """Eigenvalues of the vehicle linearised about equilibrium at ``scenario.speed`` (m/s) with
    the scenario's wheel/rail pair (and so its equivalent conicity) and yaw damper.

    ``conicity`` (–, in (0, 1]) replaces the scenario's wheel and rail by a conical wheel of that
    equivalent conicity on a knife-edge rail: eigenvalues at a given speed and conicity, the
    classical stability map. Each mode says which bodies move by their shares of its kinetic
    energy (:mod:`loco.modes`)."""
    scenario = with_conicity(scenario, conicity)
    a = _loco.linearise(
        scenario.native(),
        toml_text=vehicle.toml_text,
        origin=vehicle.origin,
        overrides=dict(vehicle.overrides),
    )
    bodies = body_masses(vehicle.toml_text, vehicle.origin, dict(vehicle.overrides))
    values, vectors = np.linalg.eig(a)
    modes = []
    for k, lam in enumerate(values):
        if lam.imag <= 1e-6:  # one of each conjugate pair; real (overdamped) roots skipped
            continue
        shares, motions = energy_shares(vectors[:, k], bodies)
        modes.append(
            Mode(
                frequency=float(abs(lam.imag) / (2 * np.pi)),
                damping_ratio=float(-lam.real / abs(lam)),
                eigenvalue=complex(lam),
                bodies=shares,
                motions=motions,
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
    conicity: float | None = None,
) -> float:
    """Critical speed (m/s) of the vehicle in the scenario's wheel/rail pair and yaw damper.

    ``method="linear"``: where the least damped mode in ``band`` (Hz) loses its damping, by
    bisection between ``low`` and ``high`` (m/s) to ``tolerance`` (m/s). Returns ``inf`` when the
    vehicle is stable at ``high`` and ``low`` when it is already unstable there.

    ``method="nonlinear"``: the speed at which the hunting limit cycle dies out in a ramp-down
    (:func:`ramp_down`) from ``scenario.speed`` to ``low`` at ``deceleration`` (m/s²) after a
    ``disturbance`` (m). Returns ``inf`` when the vehicle does not hunt at ``scenario.speed`` and
    ``low`` when it still hunts there. On worn wheels (subcritical hunting) it lies at or below
    the linear critical speed.

    ``conicity`` (–) replaces the scenario's wheel and rail by a conical wheel of that equivalent
    conicity on a knife-edge rail (see :func:`eigen`); it has no flange, so it is refused with
    ``method="nonlinear"``, whose large disturbance reaches the flanges."""
    if method == "nonlinear":
        if conicity is not None:
            raise _loco.ParameterError(
                "invalid parameter `conicity`: only with method='linear' (the conical wheel "
                "has no flange to bound a limit cycle)"
            )
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

    scenario = with_conicity(scenario, conicity)

    def zeta(speed: float) -> float:
        s = dataclasses.replace(scenario, speed=speed)
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
