"""Equivalent conicity (EN 15302) of a wheel/rail pair or of a sampled Δr(y).

Two methods, both computed in ``loco_core::contact``:

- ``"nonlinear"``: the standard's kinematic method. The wheelset's kinematic equation of motion
  with the nonlinear rolling radius difference Δr(y) is integrated over one half period between
  the turning points of amplitude ŷ (half the peak-to-peak swing); the wavelength λ gives
  tan γe from Klingel's formula λ = 2π·√(r0·e/tan γe). Verified against the nine benchmark
  cases E1–E9 of EN 15302.
- ``"harmonic"``: harmonic linearisation (first harmonic of Δr over a sinusoidal swing).

Profiles are :class:`loco.profiles.Profile` objects or built-in names (``loco.profiles.
builtin_names()``). Track keywords are those of :func:`loco.contact.rolling_radius_difference`
(SI units; defaults: the study's 1435 mm gauge at 16 mm, 1:40, back-to-back 1353 mm, 625 mm).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco import contact as _contact
from loco import profiles as _profiles
from loco._loco import Profile

__all__ = [
    "ConicityCurve",
    "conicity_curve",
    "conicity_from_delta_r",
    "equivalent_conicity",
]

_FloatArray = npt.NDArray[np.float64]

#: Amplitudes of the EN 15302 benchmark tables: 1.0 … 7.5 mm every 0.1 mm (m).
BENCHMARK_AMPLITUDES: _FloatArray = np.round(np.arange(10, 76) * 1e-4, 6)

#: Sampling step of Δr(y) (m): the 0.1 mm of the EN 15302 benchmark grids.
DEFAULT_STEP = 1.0e-4

#: Lateral margin of the Δr samples beyond the largest amplitude (m): room for the off-centre
#: swing of asymmetric wheelsets.
_MARGIN = 4.5e-3


def _profile(value: Profile | str) -> Profile:
    return _profiles.builtin(value) if isinstance(value, str) else value


def _lateral_grid(amplitude_max: float, step: float) -> _FloatArray:
    if not (np.isfinite(step) and step > 0):
        raise _loco.ParameterError(f"invalid parameter `step`: must be > 0, got {step}")
    half = amplitude_max + _MARGIN
    n = int(np.ceil(half / step))
    return np.arange(-n, n + 1, dtype=np.float64) * step


def conicity_from_delta_r(
    y: npt.ArrayLike, dr: npt.ArrayLike, amplitudes: npt.ArrayLike, method: str = "nonlinear"
) -> _FloatArray:
    """tan γe at each amplitude (m) of Δr = ``dr`` (m) sampled at the increasing ``y`` (m).

    Raises :class:`loco.ParameterError` naming ``amplitude`` when a swing leaves the samples.
    """
    return _loco.conicity_from_delta_r(
        np.ascontiguousarray(y, dtype=np.float64),
        np.ascontiguousarray(dr, dtype=np.float64),
        np.ascontiguousarray(np.atleast_1d(amplitudes), dtype=np.float64),
        method,
    )


def equivalent_conicity(
    wheel: Profile | str,
    rail: Profile | str,
    amplitude: float = 0.003,
    *,
    method: str = "nonlinear",
    step: float = DEFAULT_STEP,
    **track: Any,
) -> float:
    """Equivalent conicity tan γe (-) of ``wheel`` on ``rail`` at wheelset amplitude
    ``amplitude`` (m), by ``method`` ('nonlinear', the EN 15302 reference, or 'harmonic').

    Δr(y) is computed by :func:`loco.contact.rolling_radius_difference` every ``step`` m over
    ±(amplitude + 4.5 mm) with the track keywords ``track``.
    """
    ys = _lateral_grid(float(amplitude), step)
    dr = _contact.rolling_radius_difference(_profile(wheel), _profile(rail), ys, **track)
    return float(conicity_from_delta_r(ys, dr, [amplitude], method)[0])


@dataclass(frozen=True)
class ConicityCurve:
    """Δr(y) of a wheel/rail pair and its equivalent conicity against amplitude.

    ``y`` (m) and ``delta_r`` (m, left − right); ``amplitudes`` (m) with ``nonlinear`` and
    ``harmonic`` tan γe (-), NaN where a swing of that amplitude leaves the sampled ``y``.
    """

    y: _FloatArray
    delta_r: _FloatArray
    amplitudes: _FloatArray
    nonlinear: _FloatArray
    harmonic: _FloatArray

    def at(self, amplitude: float, method: str = "nonlinear") -> float:
        """tan γe at ``amplitude`` (m), which must be one of :attr:`amplitudes`."""
        values = self.nonlinear if method == "nonlinear" else self.harmonic
        i = int(np.argmin(np.abs(self.amplitudes - amplitude)))
        if abs(self.amplitudes[i] - amplitude) > 1e-12:
            raise _loco.ParameterError(f"invalid parameter `amplitude`: {amplitude} not computed")
        return float(values[i])


def _curve(y: _FloatArray, dr: _FloatArray, amplitudes: _FloatArray, method: str) -> _FloatArray:
    out = np.full(amplitudes.shape, np.nan)
    for i, a in enumerate(amplitudes):
        try:
            out[i] = conicity_from_delta_r(y, dr, [a], method)[0]
        except _loco.ParameterError as err:
            if "amplitude" not in str(err):
                raise
    return out


def conicity_curve(
    wheel: Profile | str,
    rail: Profile | str,
    amplitudes: npt.ArrayLike = BENCHMARK_AMPLITUDES,
    *,
    step: float = DEFAULT_STEP,
    **track: Any,
) -> ConicityCurve:
    """Δr(y) of ``wheel`` on ``rail`` and tan γe against ``amplitudes`` (m; default 1 … 7.5 mm)
    by both methods. Track keywords as for :func:`loco.contact.rolling_radius_difference`."""
    amps = np.atleast_1d(np.asarray(amplitudes, dtype=np.float64))
    if amps.size == 0 or not np.all(np.isfinite(amps)) or np.any(amps <= 0):
        raise _loco.ParameterError("invalid parameter `amplitudes`: must be finite and > 0")
    ys = _lateral_grid(float(amps.max()), step)
    dr = _contact.rolling_radius_difference(_profile(wheel), _profile(rail), ys, **track)
    return ConicityCurve(
        y=ys,
        delta_r=dr,
        amplitudes=amps,
        nonlinear=_curve(ys, dr, amps, "nonlinear"),
        harmonic=_curve(ys, dr, amps, "harmonic"),
    )
