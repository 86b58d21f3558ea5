"""EN 14363-style processing of the curving channels and its limit values.

The processing (EN 14363:2016, as summarised for UIC 518 / EN 14363 acceptance tests in
the GENSYS course notes, gensys.se/course/UIC518_tests.html): ΣY and Y/Q are averaged over a
**2 m sliding window** sampled **every 0.5 m**; their **0.15 % and 99.85 % percentiles** per
section of track are the assessed values; the quasi-static guiding force Y_qst is the
**50 % percentile** (median) of the wheel's lateral force in the section. (The standard low-passes
the measured signals at 20 Hz first; a simulated record at 500 Hz has no measurement noise, and
the 2 m window, 13 ms at 150 km/h, is itself a low pass, so no filter is applied here.)

Why in Python and not in the core: the processing needs the designed track's sections (which part
of the record is the full curve) and the vehicle class's limit values, which are the study's; a
run's core metrics are one fixed row per run that every batch and campaign file shares (a curve
assessment per section does not fit it). Nothing here is a new physical quantity: every signal
is a core channel (``loco.wheel_channels()``).

Limit values, each with its source. What the searched public texts confirm (the
standard's own text was not among them, so its clause numbers are not cited here):

- ΣY (track shift, Prud'homme): ``(ΣY_2m)lim = α·(10 + 2·Q0/3)`` kN with 2·Q0 the static axle
  load in kN. The form is Prud'homme's criterion: H = 10 + (axle load)/3 kN (Civil Engineering =
  Siviele Ingenieurswese 27(5), journals.co.za/content/civeng/27/5/AJA10212019_14454, lateral
  track resistance tests: "the well-known Prud'homme formula ... H = 10 + axle load/3 kN"), and
  as the UIC 716 limit "(Sum of Y forces) < k·(10 + 2Q/3)" (railwaynews.net, "UIC 716
  Track-Vehicle Force Limits"). α = 1.0 for locomotives, power heads and passenger vehicles and
  0.85 for freight wagons is **not confirmed** by those texts (they give the factor, not its
  values); it is the values as recalled from EN 14363 / UIC 518.
- Y/Q (flange climbing, Nadal): ``(Y/Q)_2m,lim = 0.8`` on the 2 m sliding mean, with ΣY_2m
  assessed after rejecting 0.15 % of the extreme values (UIC 518:2009 as summarised at
  railwaynews.net, "UIC 518: Dynamic Behaviour Testing ...": "the moving average Y/Q must not
  exceed 0.8, with a window width Δx = 2 m"). The on-track assessment covers curves of
  R ≥ 250 m: smaller radii (test zone 5) are "not part of the acceptance testing according to
  EN 14363" (CEN/TS 17843:2022's scope, standards.iteh.ai), so :func:`yq_limit` refuses them
  (the 1.2 this module gave for R < 250 m had no source; it is the twist test's flange-climbing
  limit as recalled, a stationary test, not a running one).
- Y_qst (quasi-static guiding force): ``(Y_qst)lim = 60 kN``, assessed in the small-radius zone
  250 m ≤ R < 400 m. The TSI LOC&PAS sets a Y_qst limit ("In case the Yqst value exceeds the
  limit value expressed above, the operational performance of the unit ... may be limited by the
  network", its English text at wordscope.be), but the value 60 kN and the radius range are
  **not confirmed** by the searched texts; they are as recalled. For the larger radii studied
  here it is a reference line, not a verdict.

- Q_max, Q_qst and ÿ*_qst (track loading and the carbody's quasi-static lateral acceleration):
  the maximum wheel force ``(Q_max)lim = 90 kN + Q0``, at most 200 kN up to 160 km/h, 190 kN to
  200 km/h, 180 kN to 250 km/h, 170 kN to 300 km/h and 160 kN above; the quasi-static wheel force
  ``(Q_qst)lim = 145 kN``; ``(ÿ*_qst)lim = 1.5 m/s²`` in the carbody. These are the values as
  commonly quoted from UIC 518 / EN 14363 in the vehicle-dynamics literature, **not confirmed**
  by the searched texts (which give the processing: Q at its 99.85 % percentile, Q_qst and
  ÿ*_qst at 50 %, the GENSYS notes above); like α they are secondary and said so wherever
  they are shown (:mod:`loco.assessment`).

- Ride characteristics of the normal method: the carbody floor accelerations ÿ* (lateral) and
  z̈* (vertical) **band-passed 0.4–10 Hz**, assessed per section by the larger magnitude of their
  **0.15 % and 99.85 % percentiles** and by their **rms** (the GENSYS notes' processing). Limits
  ``ÿ*_max 3.0``, ``s(ÿ*) 0.5``, ``z̈*_max 3.0`` and ``s(z̈*) 1.0 m/s²`` for locomotives and
  passenger vehicles: the values as recalled from the vehicle-dynamics literature quoting
  EN 14363 / UIC 518, **not confirmed** by a searched text.

EN 14363:2016 supersedes EN 14363:2005 and EN 15686/15687:2010 (BS EN 14363:2016's national
foreword); the 2 m / 0.5 m / 0.15 % / 99.85 % / 50 % processing above is as the GENSYS notes give
it for UIC 518 and EN 14363.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "ALPHA_FREIGHT",
    "ALPHA_LOCOMOTIVE",
    "MIN_ASSESSED_RADIUS",
    "PERCENTILES",
    "QQST_LIMIT",
    "QST_RADII",
    "Q_MAX_CAPS",
    "Q_MAX_CAP_ABOVE",
    "Q_PERCENTILE",
    "RIDE_BAND_HZ",
    "RIDE_LIMITS",
    "SAMPLE_SPACING",
    "WINDOW",
    "YDD_QST_LIMIT",
    "YQST_LIMIT",
    "YQ_LIMIT",
    "SectionValues",
    "q_max_limit",
    "quasi_static_assessed",
    "ride_filtered",
    "ride_values",
    "section_bounds",
    "section_values",
    "sliding_mean",
    "sum_y_limit",
    "yq_limit",
]

FloatArray = NDArray[np.float64]

#: Sliding window of ΣY and Y/Q, m (UIC 518 / EN 14363, GENSYS notes; module docstring).
WINDOW = 2.0
#: Spacing of the sliding means, m (the same).
SAMPLE_SPACING = 0.5
#: Percentiles per section, % (the same: F1 = 0.15 %, F2 = 99.85 %).
PERCENTILES = (0.15, 99.85)
#: α of the ΣY limit for locomotives, power heads and passenger vehicles (as recalled from
#: EN 14363 / UIC 518; not confirmed, module docstring).
ALPHA_LOCOMOTIVE = 1.0
#: α of the ΣY limit for freight wagons (as recalled; not confirmed).
ALPHA_FREIGHT = 0.85
#: Nadal flange-climbing limit of (Y/Q)_2m, –, for the curves EN 14363 assesses (R ≥ 250 m;
#: UIC 518:2009, module docstring).
YQ_LIMIT = 0.8
#: Smallest radius EN 14363's running tests assess, m (below: test zone 5, CEN/TS 17843).
MIN_ASSESSED_RADIUS = 250.0
#: Quasi-static guiding force limit, N, 250 m ≤ R < 400 m (as recalled; the TSI LOC&PAS sets a
#: Y_qst limit, its value is not confirmed, module docstring).
YQST_LIMIT = 60e3
#: Radii (m) of the small-radius zone where Y_qst and Q_qst are assessed: [250, 400).
QST_RADII = (250.0, 400.0)
#: Quasi-static wheel force limit, N (as commonly quoted; not confirmed, module docstring).
QQST_LIMIT = 145e3
#: Quasi-static lateral acceleration limit in the carbody, m/s² (as commonly quoted; not
#: confirmed, module docstring).
YDD_QST_LIMIT = 1.5
#: Band of the ride characteristics, Hz (GENSYS notes: 0.4–10 Hz).
RIDE_BAND_HZ = (0.4, 10.0)
#: Ride characteristics' limits, m/s², for locomotives and passenger vehicles: the maximum
#: (percentile) and rms of ÿ* and z̈* (as recalled; not confirmed, module docstring).
RIDE_LIMITS: dict[str, float] = {
    "ydd_max": 3.0,
    "ydd_rms": 0.5,
    "zdd_max": 3.0,
    "zdd_rms": 1.0,
}
#: Percentile of the maximum wheel force Q_max, % (GENSYS notes: F2 = 99.85 %).
Q_PERCENTILE = 99.85
#: The cap of Q_max's limit by speed: (highest speed in m/s, cap in N), in increasing speed; above
#: the last, :data:`Q_MAX_CAP_ABOVE` (as commonly quoted; not confirmed, module docstring).
Q_MAX_CAPS = ((160 / 3.6, 200e3), (200 / 3.6, 190e3), (250 / 3.6, 180e3), (300 / 3.6, 170e3))
#: Cap of Q_max's limit above the last speed of :data:`Q_MAX_CAPS`, N.
Q_MAX_CAP_ABOVE = 160e3


def sum_y_limit(axle_load: float, alpha: float = ALPHA_LOCOMOTIVE) -> float:
    """Prud'homme's track-shift limit ``α·(10 + 2Q0/3)`` kN, in N, for a static axle load
    ``axle_load`` = 2·Q0 (N)."""
    return alpha * (10e3 + axle_load / 3.0)


def q_max_limit(speed: float, wheel_load: float) -> float:
    """The maximum wheel force's limit ``90 kN + Q0`` (N) for a static wheel load ``wheel_load``
    = Q0 (N), capped by the speed ``speed`` (m/s, :data:`Q_MAX_CAPS`)."""
    cap = next((c for v, c in Q_MAX_CAPS if speed <= v), Q_MAX_CAP_ABOVE)
    return min(90e3 + wheel_load, cap)


def quasi_static_assessed(radius: float) -> bool:
    """Whether Y_qst and Q_qst are assessed on a curve of ``radius`` (m): the small-radius zone
    :data:`QST_RADII`."""
    return QST_RADII[0] <= abs(radius) < QST_RADII[1]


def yq_limit(radius: float) -> float:
    """The flange-climbing limit of (Y/Q)_2m for a curve of radius ``radius`` (m; inf for
    straight track). Raises ``ValueError`` below :data:`MIN_ASSESSED_RADIUS`, which EN 14363's
    running tests do not assess."""
    if abs(radius) < MIN_ASSESSED_RADIUS:
        raise ValueError(
            f"radius {radius:g} m: EN 14363's running tests assess R >= {MIN_ASSESSED_RADIUS:g} m "
            "(smaller radii, test zone 5, are outside it: CEN/TS 17843)"
        )
    return YQ_LIMIT


def sliding_mean(
    distance: FloatArray,
    signal: FloatArray,
    start: float,
    end: float,
    *,
    window: float = WINDOW,
    spacing: float = SAMPLE_SPACING,
) -> tuple[FloatArray, FloatArray]:
    """Means of ``signal`` over windows of ``window`` m whose starts are ``spacing`` m apart, every
    window inside ``[start, end]`` (m, along ``distance``, increasing).

    The mean over [a, a + window] is the exact integral of the signal's linear interpolant
    divided by the window (trapezoids, the window's ends interpolated), so it does not depend on
    how the samples fall against the windows. Returns (window centres, means); empty when the
    section is shorter than one window.
    """
    s = np.asarray(distance, dtype=np.float64)
    x = np.asarray(signal, dtype=np.float64)
    if s.shape != x.shape or s.ndim != 1:
        raise ValueError("distance and signal must be 1-D arrays of the same length")
    if s.size < 2 or np.any(np.diff(s) <= 0.0):
        raise ValueError("distance must increase, with at least two samples")
    lo, hi = max(start, float(s[0])), min(end, float(s[-1]))
    n = int(np.floor((hi - lo - window) / spacing + 1e-9)) + 1
    if n <= 0:
        return np.empty(0), np.empty(0)
    a: FloatArray = lo + spacing * np.arange(n, dtype=np.float64)
    cumulative = np.concatenate([[0.0], np.cumsum(0.5 * (x[1:] + x[:-1]) * np.diff(s))])

    def integral(p: FloatArray) -> FloatArray:
        i = np.clip(np.searchsorted(s, p, side="right") - 1, 0, s.size - 2)
        frac = p - s[i]
        slope = (x[i + 1] - x[i]) / (s[i + 1] - s[i])
        out: FloatArray = cumulative[i] + frac * (x[i] + 0.5 * slope * frac)
        return out

    means: FloatArray = (integral(a + window) - integral(a)) / window
    return a + 0.5 * window, means


@dataclass(frozen=True)
class SectionValues:
    """EN 14363 values of one signal in one section.

    ``low`` and ``high`` are the 0.15 % and 99.85 % percentiles of the 2 m sliding means;
    ``median`` the 50 % percentile of the unaveraged signal (the quasi-static value); ``n_means``
    how many sliding means the percentiles are of. Units: the signal's.
    """

    low: float
    high: float
    median: float
    n_means: int

    @property
    def extreme(self) -> float:
        """The larger magnitude of the two percentiles (the value assessed against a limit)."""
        return max(abs(self.low), abs(self.high))


def section_values(
    distance: FloatArray, signal: FloatArray, start: float, end: float
) -> SectionValues:
    """The EN 14363 values of ``signal`` in the section ``[start, end]`` (m along ``distance``);
    NaN when the section holds no full window."""
    _, means = sliding_mean(distance, signal, start, end)
    inside = (distance >= start) & (distance <= end)
    if means.size == 0:
        return SectionValues(np.nan, np.nan, np.nan, 0)
    low, high = np.percentile(means, PERCENTILES)
    return SectionValues(float(low), float(high), float(np.median(signal[inside])), means.size)


def section_bounds(sections: Sequence[float]) -> list[tuple[float, float]]:
    """(start, end) in m of consecutive sections of these lengths (m) from s = 0."""
    ends = np.cumsum(sections)
    starts = np.concatenate([[0.0], ends[:-1]])
    return [(float(a), float(b)) for a, b in zip(starts, ends, strict=True)]


def ride_filtered(signal: FloatArray, sampling_rate: float) -> FloatArray:
    """``signal`` (m/s², sampled at ``sampling_rate`` Hz) band-passed over
    :data:`RIDE_BAND_HZ` by a 4th-order Butterworth filter run forward and back (no phase lag;
    the vertical accelerometer's g falls out with the band's lower edge)."""
    from scipy.signal import butter, sosfiltfilt

    sos = butter(4, RIDE_BAND_HZ, btype="bandpass", fs=sampling_rate, output="sos")
    if signal.size <= 27:  # sosfiltfilt's default padding needs a longer record
        return np.full(signal.shape, np.nan)
    out: FloatArray = sosfiltfilt(sos, signal)
    return out


def ride_values(filtered: FloatArray) -> tuple[float, float]:
    """The ride characteristics of one section of a :func:`ride_filtered` signal: the larger
    magnitude of its :data:`PERCENTILES` and its rms (m/s²; NaN for an empty section)."""
    if filtered.size == 0 or not np.isfinite(filtered).all():
        return float("nan"), float("nan")
    low, high = np.percentile(filtered, PERCENTILES)
    return max(abs(float(low)), abs(float(high))), float(np.sqrt(np.mean(filtered**2)))
