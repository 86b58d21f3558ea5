"""Stability of the locomotive: eigenvalues about equilibrium and the critical speed.

The state matrix comes from the Rust model itself (central differences of the full nonlinear
right-hand side about the static equilibrium on perfect track, `loco._loco.linearise`), so the
eigenvalues belong to exactly the model the time integration runs. :func:`eigen` takes them and
the mode shapes from numpy/LAPACK; the linear critical speed is a bisection in the core
(`loco._loco.linear_critical_speed`, vehicle built once, its own eigenvalue solver).
The nonlinear critical speed comes from a time simulation whose speed falls linearly after a
lateral disturbance (`loco._loco.ramp_down`): the speed at which the hunting limit cycle dies out.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco.modes import (
    MOTIONS,
    Mode,
    ModeEnergies,
    ModeRule,
    describe_rule,
    mode_energies,
    mode_rules,
)
from loco.simulation import Scenario
from loco.vehicle import Locomotive

__all__ = [
    "CriticalSpeed",
    "Eigen",
    "Mode",
    "ModeRule",
    "RampDown",
    "critical_speed",
    "describe_rule",
    "eigen",
    "mode_rules",
    "ramp_down",
    "with_conicity",
]

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class Eigen:
    """All oscillatory modes at one speed, sorted by damping ratio (least damped first)."""

    speed: float
    modes: list[Mode]
    #: The modes' kinetic-energy shares as arrays in the order of ``modes`` (what the core's
    #: mode rules read), kept by :func:`eigen`; rebuilt from ``modes`` when absent.
    _energies: ModeEnergies | None = field(default=None, repr=False, compare=False)

    def __repr__(self) -> str:
        try:
            m = self.least_damped()
            least = f", least damped {m.frequency:.3f} Hz at ζ={m.damping_ratio:.4f} (0.3–20 Hz)"
        except _loco.ParameterError:
            least = ""
        return f"Eigen(speed={self.speed:g} m/s, {len(self.modes)} modes{least})"

    def least_damped(self, min_frequency: float = 0.3, max_frequency: float = 20.0) -> Mode:
        """The least damped mode within a frequency band (hunting and body modes, not drift), by
        the core's rule (the one the linear critical speed uses)."""
        index = _loco.least_damped_mode(
            np.array([m.frequency for m in self.modes], dtype=np.float64),
            np.array([m.damping_ratio for m in self.modes], dtype=np.float64),
            (float(min_frequency), float(max_frequency)),
        )
        if index is None:
            raise _loco.ParameterError("invalid parameter `band`: no mode in the frequency band")
        return self.modes[index]

    def carbody_mode(self) -> Mode:
        """The carbody-coupled lateral mode (carbody hunting, the low-conicity problem).

        Rule (the core's ``carbody`` mode rule, :func:`mode_rules`): among the modes of
        0.3–3 Hz with at least 30 % of their kinetic energy in the carbody, at least 2 % in the
        wheelsets (the contact drives it; the carbody's sway modes on its springs have 0–2 %) and
        at least 80 % in lateral, roll and yaw motion, the least damped. Raises
        :class:`loco.ParameterError` when no mode passes (at moderate and high conicity with low
        yaw damping the kinematic mode lives in the bogies and the carbody only sways)."""
        return self._pick("carbody")

    def bogie_mode(self) -> Mode:
        """The bogie mode (bogie and wheelset hunting, the high-conicity problem).

        Rule (the core's ``bogie`` mode rule, :func:`mode_rules`): among the modes of 1–10 Hz
        with at most 25 % of their kinetic energy in the carbody, at least 10 % in the bogie
        frames (the motors' lateral modes on their mounts have 2–8 %), at least 2 % in the
        wheelsets and at least 80 % in lateral, roll and yaw motion, the least damped. At low
        conicity, where the kinematic motion lies in the carbody mode, this is the running gear's
        least damped lateral mode. Raises :class:`loco.ParameterError` when no mode passes."""
        return self._pick("bogie")

    def _pick(self, rule: str) -> Mode:
        """The mode the core's rule ``rule`` picks."""
        if not self.modes:
            raise _loco.ParameterError(f"invalid parameter `modes`: no modes for the {rule} rule")
        e = self._energies
        if e is None:
            names = list(self.modes[0].bodies)
            e = ModeEnergies(
                names=names,
                kinds=[self.modes[0].kinds[n] for n in names],
                shares=np.array([[m.bodies[n] for n in names] for m in self.modes]),
                motions=np.array(
                    [[[m.motions[n][k] for k in MOTIONS] for n in names] for m in self.modes]
                ),
            )
        index = _loco.select_mode(
            rule,
            e.kinds,
            np.array([m.frequency for m in self.modes]),
            np.array([m.damping_ratio for m in self.modes]),
            e.shares,
            e.motions,
        )
        if index is None:
            raise _loco.ParameterError(
                f"invalid parameter `{rule}_mode`: no mode at {self.speed:g} m/s passes the "
                f"{rule} mode rule ({describe_rule(rule)})"
            )
        return self.modes[index]


def with_conicity(scenario: Scenario, conicity: float | None) -> Scenario:
    """``scenario`` with its wheel and rail replaced by a conical wheel of equivalent conicity
    ``conicity`` (–) on a knife-edge rail (Δr = 2·conicity·y exactly, no flange); unchanged when
    ``conicity`` is None."""
    if conicity is None:
        return scenario
    wheel, rail = _loco.conical_profiles(float(conicity))
    return scenario.replace(name=None, wheel=wheel, rail=rail)


def eigen(vehicle: Locomotive, scenario: Scenario, *, conicity: float | None = None) -> Eigen:
    """Eigenvalues of the vehicle linearised about equilibrium at ``scenario.speed`` (m/s) with
    the scenario's wheel/rail pair (and so its equivalent conicity) and yaw damper.

    ``conicity`` (–, in (0, 1]) replaces the scenario's wheel and rail by a conical wheel of that
    equivalent conicity on a knife-edge rail: eigenvalues at a given speed and conicity, the
    classical stability map. Each mode says which bodies move by their shares of its kinetic
    energy (:mod:`loco.modes`)."""
    scenario = with_conicity(scenario, conicity)
    a = _loco.linearise(vehicle.native, scenario.native())
    values, vectors = np.linalg.eig(a)
    # The core's rule: one of each conjugate pair, with its frequency and damping ratio; real
    # (overdamped) roots are not modes of oscillation.
    keep, frequencies, damping_ratios = _loco.oscillatory_modes(
        np.ascontiguousarray(values.real, dtype=np.float64),
        np.ascontiguousarray(values.imag, dtype=np.float64),
    )
    energies = mode_energies(vectors[:, keep].T, vehicle.native)
    kinds = dict(zip(energies.names, energies.kinds, strict=True))
    modes = []
    for i, k in enumerate(keep):
        lam = values[k]
        modes.append(
            Mode(
                frequency=frequencies[i],
                damping_ratio=damping_ratios[i],
                eigenvalue=complex(lam),
                bodies=energies.bodies(i),
                motions=energies.body_motions(i),
                kinds=kinds,
            )
        )
    order = sorted(range(len(modes)), key=lambda i: modes[i].damping_ratio)
    sorted_energies = ModeEnergies(
        names=energies.names,
        kinds=energies.kinds,
        shares=energies.shares[order],
        motions=energies.motions[order],
    )
    return Eigen(
        speed=float(scenario.speed), modes=[modes[i] for i in order], _energies=sorted_energies
    )


class CriticalSpeed(float):
    """A critical speed (m/s) that says whether it was found inside the search.

    It is a ``float`` (compare it, print it, do arithmetic with it) with the search's result:
    ``found`` is true when the loss of stability was located inside the searched speeds.
    Otherwise the value is a bound, not a critical speed, and ``outcome`` says which:

    - ``"stable_at_high"`` (linear) / ``"stable_at_start"`` (nonlinear): stable up to the search
      limit ``limit`` (m/s); the value is ``inf`` — the critical speed lies above ``limit``, it
      was *not* found below it.
    - ``"unstable_at_low"`` (linear) / ``"hunts_at_end"`` (nonlinear): already unstable at the
      lowest searched speed ``limit``; the value is ``limit`` — the critical speed is at or below.
    - ``"found"`` (linear) / ``"died_out"`` (nonlinear): the critical speed itself.

    ``reason`` is the sentence to show a user.
    """

    outcome: str
    limit: float
    method: str

    FOUND = ("found", "died_out")

    def __new__(cls, value: float, outcome: str, limit: float, method: str) -> CriticalSpeed:
        out = super().__new__(cls, value)
        out.outcome = outcome
        out.limit = float(limit)
        out.method = method
        return out

    @property
    def found(self) -> bool:
        """Whether the critical speed lies inside the searched speeds (else the value is a
        bound)."""
        return self.outcome in self.FOUND

    @property
    def reason(self) -> str:
        """What the value means, in words."""
        v = float(self)
        if self.found:
            return f"{self.method} critical speed {v:.2f} m/s ({v * 3.6:.0f} km/h)"
        if self.outcome in ("stable_at_high", "stable_at_start"):
            return (
                f"no {self.method} critical speed found up to the search limit {self.limit:.2f} m/s"
                f" ({self.limit * 3.6:.0f} km/h): stable there, the critical speed is above it"
            )
        return (
            f"already unstable at the lowest searched speed {self.limit:.2f} m/s "
            f"({self.limit * 3.6:.0f} km/h): the {self.method} critical speed is at or below it"
        )

    def __repr__(self) -> str:
        return f"CriticalSpeed({float(self)!r}, {self.outcome!r}: {self.reason})"

    def __reduce__(self) -> tuple[object, ...]:
        return (CriticalSpeed, (float(self), self.outcome, self.limit, self.method))


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

    def __repr__(self) -> str:
        return (
            f"RampDown(critical_speed={self.critical_speed:.2f} m/s, outcome={self.outcome!r}, "
            f"{len(self.speed)} windows)"
        )


def _given(**settings: float | tuple[float, float] | None) -> dict[str, object]:
    """The settings the caller gave (not None), as floats; the core supplies the others."""
    return {
        k: tuple(float(x) for x in v) if isinstance(v, tuple) else float(v)
        for k, v in settings.items()
        if v is not None
    }


def ramp_down(
    vehicle: Locomotive,
    scenario: Scenario,
    end_speed: float | None = None,
    deceleration: float | None = None,
    hold: float | None = None,
    max_hold: float | None = None,
    disturbance: float | None = None,
    window: float | None = None,
    threshold: float | None = None,
) -> RampDown:
    """Nonlinear critical speed by a speed ramp-down on perfect track.

    Every wheelset starts displaced by ``disturbance`` (m) along its rails; the speed stays at
    ``scenario.speed`` (m/s) for at least ``hold`` (s) and until the hunting amplitude has
    settled (at most ``max_hold``, s), then falls by ``deceleration`` (m/s²) down to ``end_speed``
    (m/s). Hunting has died out in the first window of ``window`` (s) whose amplitude is below
    ``threshold`` (m). A setting left as None takes the core's default (``RampSettings`` in
    ``loco_core::vehicle::runs::critical_speed``: 20 m/s at 0.5 m/s² after 3–30 s, 8 mm, 1 s
    windows, 0.5 mm). The disturbance must be large: the default reaches the flanges of worn
    wheels and finds the largest limit cycle, the one that survives down to the lowest speed.

    The detection follows the dying cycle's collapse, so the result is low by roughly
    ``deceleration`` times a few seconds (S_high with YD1, linear critical speed 34.2 m/s: 33.5,
    32.8 and 32.0 m/s at 0.25, 0.5 and 1 m/s² from 1.3 times that); halve ``deceleration`` to
    check it. Start well above the linear critical speed. Ctrl-C stops the run."""
    speed, outcome, speeds, amplitudes = _loco.ramp_down(
        vehicle.native,
        scenario.native(),
        **_given(
            end_speed=end_speed,
            deceleration=deceleration,
            hold=hold,
            max_hold=max_hold,
            disturbance=disturbance,
            window=window,
            threshold=threshold,
        ),  # type: ignore[arg-type]
    )
    return RampDown(critical_speed=speed, outcome=outcome, speed=speeds, amplitude=amplitudes)


def critical_speed(
    vehicle: Locomotive,
    scenario: Scenario,
    low: float | None = None,
    high: float | None = None,
    tolerance: float | None = None,
    band: tuple[float, float] | None = None,
    *,
    method: str = "linear",
    deceleration: float | None = None,
    disturbance: float | None = None,
    conicity: float | None = None,
    guess: float | None = None,
) -> CriticalSpeed:
    """Critical speed (m/s) of the vehicle in the scenario's wheel/rail pair and yaw damper, as a
    :class:`CriticalSpeed`: a float that also says whether it was found (``.found``,
    ``.outcome``, ``.reason``) or is only a bound of the search.

    ``method="linear"``: where the least damped mode in ``band`` (Hz) loses its damping, by
    bisection between ``low`` and ``high`` (m/s) to ``tolerance`` (m/s), in the core with the
    vehicle built once. Returns ``inf`` (outcome ``"stable_at_high"``: no critical speed below
    the search limit ``high``) when the vehicle is stable at ``high``, and ``low`` (outcome
    ``"unstable_at_low"``) when it is already unstable there. With ``guess`` (m/s, a speed near
    the expected critical speed, such as the nominal vehicle's when screening its inputs) the
    search brackets the loss of damping around it and interpolates: about four linearisations
    instead of ten, the same speed within ``tolerance``.

    ``method="nonlinear"``: the speed at which the hunting limit cycle dies out in a ramp-down
    (:func:`ramp_down`) from ``scenario.speed`` to ``low`` at ``deceleration`` (m/s²) after a
    ``disturbance`` (m). Returns ``inf`` (outcome ``"stable_at_start"``) when the vehicle does not
    hunt at ``scenario.speed`` and the end speed (``"hunts_at_end"``) when it still hunts there.
    On worn wheels (subcritical hunting) it lies at or below the linear critical speed.

    A setting left as None takes the core's default (``LinearSearch`` and ``RampSettings``:
    20–110 m/s to 0.5 m/s in 0.3–20 Hz; a ramp to 20 m/s at 0.5 m/s² after 8 mm).

    ``conicity`` (–) replaces the scenario's wheel and rail by a conical wheel of that equivalent
    conicity on a knife-edge rail (see :func:`eigen`); it has no flange, so it is refused with
    ``method="nonlinear"``, whose large disturbance reaches the flanges."""
    if method == "nonlinear":
        if guess is not None:
            raise _loco.ParameterError("invalid parameter `guess`: only with method='linear'")
        if conicity is not None:
            raise _loco.ParameterError(
                "invalid parameter `conicity`: only with method='linear' (the conical wheel "
                "has no flange to bound a limit cycle)"
            )
        ramp = ramp_down(
            vehicle,
            scenario,
            end_speed=low,
            deceleration=deceleration,
            disturbance=disturbance,
        )
        # Stable at the start speed: it is the bound; hunting at the end: the end speed is.
        stable = ramp.outcome == "stable_at_start"
        limit = float(scenario.speed) if stable else ramp.critical_speed
        return CriticalSpeed(ramp.critical_speed, ramp.outcome, limit, "nonlinear")
    if method != "linear":
        raise _loco.ParameterError(
            f"invalid parameter `method`: expected 'linear' or 'nonlinear', got '{method}'"
        )
    scenario = with_conicity(scenario, conicity)
    speed, outcome, searched_low, searched_high = _loco.linear_critical_speed(
        vehicle.native,
        scenario.native(),
        **_given(low=low, high=high, tolerance=tolerance, band=band, guess=guess),  # type: ignore[arg-type]
    )
    limit = searched_high if outcome == "stable_at_high" else searched_low
    return CriticalSpeed(speed, outcome, limit, "linear")
