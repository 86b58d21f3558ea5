"""EN 14363-style processing of the curving channels and its limit values.

The processing (EN 14363:2016 §7.6, as summarised for UIC 518 / EN 14363 acceptance tests in
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

Limit values, each with its source:

- ΣY (track shift, Prud'homme): ``(ΣY_2m)lim = α·(10 + 2·Q0/3)`` kN with 2·Q0 the static axle
  load in kN; α = 1.0 for locomotives, power heads and passenger vehicles, 0.85 for freight
  wagons (EN 14363:2005 §5.3.2.2 and EN 14363:2016 §7.6.3.2; values as recalled, the standard's
  text was not in the searched corpora).
- Y/Q (flange climbing, Nadal): ``(Y/Q)_2m,lim = 0.8`` for curves of R ≥ 250 m (EN 14363:2016
  §7.6.3.1; UIC 518:2009 §5; the 2 m window, as above); 1.2 for R < 250 m.
- Y_qst (quasi-static guiding force): ``(Y_qst)lim = 60 kN`` (EN 14363:2005 §5.3.2.3, the small-
  radius test zone 250 m ≤ R < 400 m; also TSI LOC&PAS 2011 §4.2.3.4.2.2). The standard assesses
  it only in that zone: for the larger radii studied here it is a reference line, not a verdict.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "ALPHA_FREIGHT",
    "ALPHA_LOCOMOTIVE",
    "PERCENTILES",
    "SAMPLE_SPACING",
    "WINDOW",
    "YQST_LIMIT",
    "YQ_LIMIT",
    "YQ_LIMIT_SMALL_RADIUS",
    "SectionValues",
    "section_bounds",
    "section_values",
    "sliding_mean",
    "sum_y_limit",
    "yq_limit",
]

FloatArray = NDArray[np.float64]

#: Sliding window of ΣY and Y/Q, m (EN 14363 §7.6).
WINDOW = 2.0
#: Spacing of the sliding means, m (EN 14363 §7.6).
SAMPLE_SPACING = 0.5
#: Percentiles per section, % (EN 14363 §7.6: F1 = 0.15 %, F2 = 99.85 %).
PERCENTILES = (0.15, 99.85)
#: α of the ΣY limit for locomotives, power heads and passenger vehicles (EN 14363 §7.6.3.2).
ALPHA_LOCOMOTIVE = 1.0
#: α of the ΣY limit for freight wagons (EN 14363 §7.6.3.2).
ALPHA_FREIGHT = 0.85
#: Nadal flange-climbing limit of (Y/Q)_2m for R ≥ 250 m, – (EN 14363 §7.6.3.1).
YQ_LIMIT = 0.8
#: The same for R < 250 m, – (EN 14363 §7.6.3.1).
YQ_LIMIT_SMALL_RADIUS = 1.2
#: Quasi-static guiding force limit, N (EN 14363:2005 §5.3.2.3, 250 m ≤ R < 400 m).
YQST_LIMIT = 60e3


def sum_y_limit(axle_load: float, alpha: float = ALPHA_LOCOMOTIVE) -> float:
    """Prud'homme's track-shift limit ``α·(10 + 2Q0/3)`` kN, in N, for a static axle load
    ``axle_load`` = 2·Q0 (N)."""
    return alpha * (10e3 + axle_load / 3.0)


def yq_limit(radius: float) -> float:
    """The flange-climbing limit of (Y/Q)_2m for a curve of radius ``radius`` (m; inf for
    straight track)."""
    return YQ_LIMIT if abs(radius) >= 250.0 else YQ_LIMIT_SMALL_RADIUS


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
