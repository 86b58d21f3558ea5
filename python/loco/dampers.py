"""Yaw dampers: Maxwell elements, the frequency-selective (FSD) damper, the hydraulic orifice
model, and the bench that drives them.

All quantities are SI: damping in N·s/m, stiffness in N/m, mass in kg, frequency in Hz, time in s,
displacement in m, areas in m², density in kg/m³, kinematic viscosity in m²/s. The force is
positive in tension (it resists elongation). The models and their sources are documented in the
Rust core, ``crates/loco-core/src/dampers``.

Presets: :data:`YD1` (200 kN·s/m), :data:`YD2` (800 kN·s/m), both with a series stiffness of
22.5 kN/mm, and :data:`FSD` (c1 = 200, c2 = 800 kN·s/m, m = 15 kg, k = 15 kN/mm, f_p = 2 Hz,
switching delay 0.05 s) with its valve decided by the rms-frequency estimate;
:data:`FSD_HYDRAULIC` is the same FSD with the hydraulic frequency valve (auxiliary chamber,
orifice, spring-returned piston) derived for f_p at :data:`REFERENCE_STROKE_AMPLITUDE`.
:data:`COMPARED` are the dampers the studies compare, ``FSD-H`` among them.
:data:`TRIGGERS` are the trigger names (``fsd(trigger=...)``, the study file's ``fsd_trigger``).
"""

from __future__ import annotations

import copyreg
import inspect
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from loco import _loco
from loco._loco import Damper, ParameterError

__all__ = [
    "COMPARED",
    "FSD",
    "FSD_HYDRAULIC",
    "PRESETS",
    "REFERENCE_STROKE_AMPLITUDE",
    "TRIGGERS",
    "YD1",
    "YD2",
    "BenchResult",
    "Damper",
    "bench",
    "bench_recorded",
    "bench_sweep",
    "describe",
    "fsd",
    "hydraulic",
    "label",
    "maxwell",
    "maxwell_closed_form",
    "valve_opening_band",
]

YD1: Damper = _loco.damper_preset("YD1")
"""Conventional yaw damper YD1: 200 kN·s/m in series with 22.5 kN/mm."""
YD2: Damper = _loco.damper_preset("YD2")
"""Conventional yaw damper YD2: 800 kN·s/m in series with 22.5 kN/mm."""
FSD: Damper = _loco.damper_preset("FSD")
"""The spec's frequency-selective yaw damper."""
PRESETS: dict[str, Damper] = {n: _loco.damper_preset(n) for n in _loco.damper_preset_names()}
"""The spec's yaw dampers by name (SPEC §4), in the order the studies compare them; the same
names a scenario takes (``Scenario(yaw_damper="FSD")``, the study file's ``yaw_damper``)."""
FSD_HYDRAULIC: Damper = _loco.damper_preset("FSD", "hydraulic")
"""The spec's FSD with the hydraulic frequency valve (trigger ``"hydraulic"``)."""
TRIGGERS: tuple[str, ...] = tuple(_loco.fsd_trigger_names())
"""FSD trigger names, the default first: ``"rms-frequency"``, ``"hydraulic"``."""
REFERENCE_STROKE_AMPLITUDE: float = _loco.fsd_reference_stroke_amplitude()
"""Stroke amplitude (m) at which the hydraulic valve's cut-off is f_p: the measured yaw damper
stroke of the S_low sway (``experiments/fsd_reference_stroke.py``)."""
COMPARED: dict[str, Damper] = dict(_loco.compared_dampers())
"""The yaw dampers the studies compare, by label, in order: the :data:`PRESETS` and ``FSD-H``
(:data:`FSD_HYDRAULIC`), from the core's one list."""


def describe(damper: Damper) -> dict[str, Any]:
    """``{"kind": ..., **parameters}``: the damper law as a JSON-ready dict (study settings)."""
    return {"kind": damper.kind, **damper.parameters()}


def label(damper: Damper | None) -> str:
    """The :data:`COMPARED` label of ``damper`` (same kind and parameters), else its kind; None
    is the vehicle file's yaw damper."""
    if damper is None:
        return "vehicle file's yaw damper"
    wanted = describe(damper)
    return next((n for n, d in COMPARED.items() if describe(d) == wanted), damper.kind)


_HYDRAULIC_DEFAULTS = _loco.damper_hydraulic_defaults()

_F64 = NDArray[np.float64]
_BenchTuple = tuple[
    _F64, _F64, _F64, _F64, _F64, _F64, tuple[float, float, float] | None, float, _F64
]


def maxwell(
    damping: float,
    series_stiffness: float,
    *,
    knee_velocity: float | None = None,
    blow_off_damping: float | None = None,
) -> Damper:
    """A damper ``damping`` (N·s/m) in series with ``series_stiffness`` (N/m).

    With ``knee_velocity`` (m/s) and ``blow_off_damping`` (N·s/m) the law is piecewise linear: the
    relief valve opens above the knee. Raises :class:`loco.ParameterError` naming a bad field.
    """
    return _loco.damper_maxwell(damping, series_stiffness, knee_velocity, blow_off_damping)


def fsd(
    *,
    low_damping: float = 200e3,
    high_damping: float = 800e3,
    equivalent_mass: float = 15.0,
    equivalent_stiffness: float = 15e6,
    cutoff_frequency: float = 2.0,
    switching_delay: float = 0.05,
    start_closed: bool = True,
    hysteresis_ratio: float = 0.1,
    highpass_corner: float = 0.5,
    averaging_time: float = 0.25,
    min_stroke_rms: float = 1e-5,
    warmup_time: float = 0.75,
    trigger: str = TRIGGERS[0],
    reference_stroke_amplitude: float | None = None,
    orifice_area: float | None = None,
    aux_piston_area: float | None = None,
    opening_stroke: float | None = None,
    spring_stiffness: float | None = None,
) -> Damper:
    """A frequency-selective damper; the defaults are the spec's FSD.

    ``low_damping`` c1 (valve open, below ``cutoff_frequency`` f_p) must be below
    ``high_damping`` c2. ``equivalent_mass`` may be 0 (massless Maxwell element). A switch takes
    ``switching_delay`` (s). ``trigger`` (one of :data:`TRIGGERS`) decides the valve:

    - ``"rms-frequency"``: the stroke's frequency estimated as rms velocity over rms
      displacement after a high-pass at ``highpass_corner`` (Hz), averaged over two stages of
      ``averaging_time`` (s); switches outside the band f_p·(1 ± ``hysteresis_ratio``).
    - ``"hydraulic"``: the damper force fills an auxiliary chamber through an orifice; its
      spring-returned piston opens the bypass past its opening stroke. The orifice (m²) and
      spring (N/m) are derived so that a sine stroke of ``reference_stroke_amplitude`` (m,
      default :data:`REFERENCE_STROKE_AMPLITUDE`) has its cut-off at f_p; ``orifice_area``,
      ``aux_piston_area`` (m²), ``opening_stroke`` (m) and ``spring_stiffness`` (N/m) override
      the derived or default values.
    """
    return _loco.damper_fsd(
        low_damping,
        high_damping,
        equivalent_mass,
        equivalent_stiffness,
        cutoff_frequency,
        switching_delay,
        start_closed,
        hysteresis_ratio,
        highpass_corner,
        averaging_time,
        min_stroke_rms,
        warmup_time,
        trigger,
        reference_stroke_amplitude,
        orifice_area,
        aux_piston_area,
        opening_stroke,
        spring_stiffness,
    )


def valve_opening_band(
    damper: Damper, amplitudes: ArrayLike
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(lower, upper) frequency (Hz) between which a steady sine stroke of each amplitude (m)
    opens the hydraulic valve of ``damper`` (an FSD with ``trigger="hydraulic"``); the upper one
    is the cut-off f_c(amplitude). NaN where it opens nowhere in 0.05–50 Hz."""
    x = np.ascontiguousarray(amplitudes, dtype=np.float64)
    return _loco.fsd_valve_opening_band(damper, x)


def _default(name: str, value: float | None) -> float:
    if value is not None:
        return value
    default = _HYDRAULIC_DEFAULTS[name]
    assert isinstance(default, float)
    return default


def hydraulic(
    *,
    piston_area: float | None = None,
    rod_area: float | None = None,
    rebound_orifice_area: float | None = None,
    compression_orifice_area: float | None = None,
    bottom_valve_area: float | None = None,
    oil_density: float | None = None,
    oil_kinematic_viscosity: float | None = None,
    flow_coefficient: float | None = None,
    series_stiffness: float | None = None,
    open_area_ratio: float | None = None,
    cutoff_frequency: float = 2.0,
    switching_delay: float = 0.05,
    start_closed: bool = True,
) -> Damper:
    """A hydraulic orifice damper (force ~ velocity²) in series with its joint stiffness.

    Unset geometry takes the documented yaw-damper default (piston Ø50 mm, rod Ø25 mm, rebound
    orifice Ø0.7 mm, ISO VG 32 oil, C_d = 0.61, 22.5 kN/mm). ``open_area_ratio`` (> 1) adds a
    frequency valve that multiplies every flow area by that ratio when open: a hydraulic FSD.
    """
    return _loco.damper_hydraulic(
        _default("piston_area", piston_area),
        _default("rod_area", rod_area),
        _default("rebound_orifice_area", rebound_orifice_area),
        _default("compression_orifice_area", compression_orifice_area),
        _default("bottom_valve_area", bottom_valve_area),
        _default("oil_density", oil_density),
        _default("oil_kinematic_viscosity", oil_kinematic_viscosity),
        _default("flow_coefficient", flow_coefficient),
        _default("series_stiffness", series_stiffness),
        open_area_ratio,
        cutoff_frequency,
        switching_delay,
        start_closed,
    )


@dataclass(frozen=True)
class BenchResult:
    """Time histories of a bench run and, for a sine, the equivalent linear element."""

    time: NDArray[np.float64]
    """Time (s)."""
    displacement: NDArray[np.float64]
    """Elongation (m)."""
    velocity: NDArray[np.float64]
    """Elongation rate (m/s)."""
    force: NDArray[np.float64]
    """Force (N, positive in tension)."""
    scale_factor: NDArray[np.float64]
    """Frequency-valve scale factor: 0 open (low damping) to 1 closed; 1 without a valve."""
    estimated_frequency: NDArray[np.float64]
    """The trigger's frequency estimate (Hz, NaN without a valve or before it can judge)."""
    equivalent_damping: float | None
    """In-quadrature part of the force over the last cycles, c_eq (N·s/m); sine only."""
    equivalent_stiffness: float | None
    """In-phase part, k_eq (N/m); sine only."""
    energy_per_cycle: float | None
    """Energy dissipated per cycle over the last cycles (J); sine only."""
    dissipated_energy: float
    """Energy dissipated over the whole run (J)."""
    valve_volume: NDArray[np.float64]
    """Hydraulic valve: volume displaced by the auxiliary piston (m³; the bypass is open past
    the parameter ``opening_volume``); 0 for other dampers."""


def _check_count(name: str, value: int, minimum: int) -> int:
    """Counts are checked here: a negative Python int would not convert to the core's usize."""
    if value < minimum:
        raise ParameterError(f"invalid parameter `{name}`: must be >= {minimum}, got {value}")
    return value


def _result(raw: _BenchTuple) -> BenchResult:
    time, x, v, force, scale, f_est, equivalent, energy, volume = raw
    c_eq, k_eq, e_cycle = equivalent if equivalent is not None else (None, None, None)
    return BenchResult(time, x, v, force, scale, f_est, c_eq, k_eq, e_cycle, energy, volume)


def bench(
    damper: Damper,
    frequency: float,
    amplitude: float,
    cycles: int = 10,
    *,
    steps_per_cycle: int = 4000,
    samples_per_cycle: int = 400,
    equivalent_cycles: int = 2,
) -> BenchResult:
    """Drives ``damper`` with ``x = amplitude·sin(2π·frequency·t)`` for ``cycles`` periods.

    The internal states are integrated with RK4 at ``steps_per_cycle`` steps per period or finer
    (the damper's fastest pole sets the limit); ``samples_per_cycle`` are recorded. The
    equivalent damping, stiffness and energy per cycle are taken over the last
    ``equivalent_cycles`` periods.
    """
    return _result(
        _loco.damper_bench_sine(
            damper,
            frequency,
            amplitude,
            _check_count("cycles", cycles, 1),
            _check_count("steps_per_cycle", steps_per_cycle, 8),
            _check_count("samples_per_cycle", samples_per_cycle, 4),
            _check_count("equivalent_cycles", equivalent_cycles, 1),
        )
    )


def bench_sweep(
    damper: Damper,
    start_frequency: float,
    end_frequency: float,
    amplitude: float,
    duration: float,
    *,
    steps_per_cycle: int = 4000,
    samples_per_cycle: int = 400,
) -> BenchResult:
    """Drives ``damper`` with a linear frequency sweep of constant ``amplitude`` (m)."""
    return _result(
        _loco.damper_bench_sweep(
            damper,
            start_frequency,
            end_frequency,
            amplitude,
            duration,
            _check_count("steps_per_cycle", steps_per_cycle, 8),
            _check_count("samples_per_cycle", samples_per_cycle, 4),
        )
    )


def bench_recorded(damper: Damper, time: ArrayLike, displacement: ArrayLike) -> BenchResult:
    """Drives ``damper`` through a recorded elongation (m) at strictly increasing times (s)."""
    t = np.ascontiguousarray(time, dtype=np.float64)
    x = np.ascontiguousarray(displacement, dtype=np.float64)
    return _result(_loco.damper_bench_recorded(damper, t, x))


def maxwell_closed_form(
    damping: float, stiffness: float, frequency: float, mass: float = 0.0
) -> tuple[float, float]:
    """Equivalent (damping N·s/m, stiffness N/m) of a spring in series with a linear damper.

    Complex stiffness ``k·(iωc - mω²)/(k - mω² + iωc)`` with the mass ``m`` (kg) at the node
    between them; for ``m = 0``: ``c/(1 + (ωc/k)²)`` and ``k·(ωc/k)²/(1 + (ωc/k)²)``.
    """
    w = 2.0 * np.pi * frequency
    z = stiffness * (1j * w * damping - mass * w**2) / (stiffness - mass * w**2 + 1j * w * damping)
    return float(z.imag / w), float(z.real)


def _rebuild(kind: str, parameters: dict[str, Any]) -> Damper:
    """A damper from its :attr:`~loco._loco.Damper.kind` and parameters (unpickling)."""
    builders: dict[str, Callable[..., Damper]] = {
        "maxwell": maxwell,
        "fsd": fsd,
        "hydraulic": hydraulic,
    }
    build = builders[kind]
    accepted = inspect.signature(build).parameters
    return build(**{k: v for k, v in parameters.items() if v is not None and k in accepted})


def _reduce(damper: Damper) -> tuple[Any, tuple[str, dict[str, Any]]]:
    args = (damper.kind, damper.parameters())
    if _rebuild(*args).parameters() != args[1]:
        raise ParameterError(
            f"invalid parameter `yaw_damper`: this {damper.kind} damper cannot be rebuilt from "
            "its parameters in another process; run it with local threads"
        )
    return _rebuild, args


# A damper pickles by its kind and parameters (rebuilt and validated where it is unpickled), so
# scenarios travel to process pools and Dask workers; tests check the round trip is exact.
copyreg.pickle(Damper, _reduce)
