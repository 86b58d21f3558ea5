"""Ride and stability metrics of acceleration records (m/s²) sampled at ``fs`` Hz.

- :func:`sperling`: Sperling ride index per GB/T 5599-2019 on 5 s segments, with the rating
  of a locomotive (excellent < 2.75, good < 3.10, acceptable < 3.45).
- :func:`psd`, :func:`dominant_frequency`: Welch PSD (periodic Hann window, 50 % overlap,
  segment mean removed, one-sided, power corrected) and its peak.
- :func:`bogie_stability`: bogie frame lateral acceleration statistics (10 Hz low-passed
  peak and the GB/T 8 m/s² × 6 cycles flag; EN 14363 f0 ± 2 Hz band-pass sliding rms over
  100 m against ``(12 - m/5)/2`` m/s², m the bogie mass in t).
- :func:`weighted_rms`, :func:`comfort_nmv`: EN 12299 / ISO 2631-1 weighted rms (Wd lateral,
  Wb vertical) and N_MV.
- :func:`run_metrics`: every metric of a run as a dict (the batch engine's row).

The estimators and their sources are documented in ``loco_core::metrics``. Bad input (empty or
too short records, NaN, non-positive ``fs``) raises :class:`loco.ParameterError`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from loco import _loco

__all__ = [
    "BogieStability",
    "Dominant",
    "SperlingIndex",
    "WeightedRms",
    "bogie_stability",
    "comfort_nmv",
    "dominant_frequency",
    "psd",
    "run_metric_names",
    "run_metrics",
    "sperling",
    "weighted_rms",
]

FloatArray = npt.NDArray[np.float64]


def _record(x: npt.ArrayLike) -> FloatArray:
    a = np.ascontiguousarray(x, dtype=np.float64)
    if a.ndim != 1:
        raise _loco.ParameterError(f"invalid input `x`: expected a 1-D record, got shape {a.shape}")
    return a


@dataclass(frozen=True)
class SperlingIndex:
    """Sperling index of a record."""

    segments: FloatArray
    """Index of each 5 s segment."""
    mean: float
    """Mean of the segment indices."""
    max: float
    """Largest segment index."""
    rating: str
    """Locomotive grade of ``max``: excellent, good, acceptable or unacceptable."""


def sperling(acc: npt.ArrayLike, fs: float, direction: str = "lateral") -> SperlingIndex:
    """Sperling ride index of carbody acceleration ``acc`` (m/s²), ``direction`` ``"lateral"``
    or ``"vertical"``: per 5 s segment, their mean and maximum, and the locomotive rating."""
    segments, mean, worst = _loco.sperling(_record(acc), fs, direction)
    return SperlingIndex(segments, mean, worst, _loco.locomotive_ride_rating(worst))


def psd(
    x: npt.ArrayLike, fs: float, segment_len: int | None = None, overlap: float = 0.5
) -> tuple[FloatArray, FloatArray]:
    """Welch PSD: (frequency Hz, density unit²/Hz). Default segment: the largest power of two
    not above half the record."""
    return _loco.welch_psd(_record(x), fs, segment_len, overlap)


@dataclass(frozen=True)
class Dominant:
    """Dominant frequency of a record."""

    frequency: float
    """Frequency of the PSD peak, Hz (refined between bins)."""
    peak: float
    """Welch PSD at the peak, unit²/Hz."""


def dominant_frequency(
    x: npt.ArrayLike,
    fs: float,
    band: tuple[float, float | None] = (0.2, None),
    segment_len: int | None = None,
) -> Dominant:
    """Frequency (Hz) of the Welch PSD peak within ``band`` (Hz; upper default fs/2)."""
    lo, hi = band
    f, p = _loco.dominant_frequency(_record(x), fs, lo, fs / 2 if hi is None else hi, segment_len)
    return Dominant(f, p)


@dataclass(frozen=True)
class BogieStability:
    """Bogie frame lateral acceleration statistics."""

    peak_lowpassed: float
    """Largest |a| after the 10 Hz low-pass, m/s²."""
    rms_lowpassed: float
    """Rms after the 10 Hz low-pass, m/s²."""
    max_consecutive_cycles: int
    """Longest run of cycles whose low-passed peak reaches 8 m/s²."""
    gbt_unstable: bool
    """GB/T flag: 6 or more such consecutive cycles."""
    f0: float
    """Instability (dominant) frequency, Hz."""
    f0_psd_peak: float
    """Welch PSD at f0, (m/s²)²/Hz."""
    sliding_rms_max: float
    """Largest sliding rms (100 m) of the f0 ± 2 Hz band-passed signal, m/s²."""
    limit: float
    """EN 14363 limit (12 - m/5)/2, m/s²."""
    en_unstable: bool
    """EN 14363 flag: sliding rms above the limit."""
    window_m: float
    """Sliding window used, m (shorter than 100 m for a shorter record)."""


def bogie_stability(
    acc: npt.ArrayLike, fs: float, speed: float, bogie_mass: float
) -> BogieStability:
    """Stability statistics of bogie frame lateral acceleration ``acc`` (m/s²) at ``speed``
    (m/s) for a bogie of ``bogie_mass`` (kg)."""
    d = _loco.bogie_stability(_record(acc), fs, speed, bogie_mass)
    return BogieStability(
        peak_lowpassed=float(d["peak_lowpassed"]),
        rms_lowpassed=float(d["rms_lowpassed"]),
        max_consecutive_cycles=int(d["max_consecutive_cycles"]),
        gbt_unstable=bool(d["gbt_unstable"]),
        f0=float(d["f0"]),
        f0_psd_peak=float(d["f0_psd_peak"]),
        sliding_rms_max=float(d["sliding_rms_max"]),
        limit=float(d["limit"]),
        en_unstable=bool(d["en_unstable"]),
        window_m=float(d["window_m"]),
    )


@dataclass(frozen=True)
class WeightedRms:
    """Frequency-weighted rms of a record, m/s²."""

    blocks: FloatArray
    """Rms of each 5 s block."""
    rms: float
    """Rms over all blocks."""
    p95: float
    """95th percentile of the block values."""


def weighted_rms(acc: npt.ArrayLike, fs: float, weighting: str = "wd") -> WeightedRms:
    """EN 12299 weighted rms of ``acc`` (m/s²), ``weighting`` ``"wd"`` (horizontal) or
    ``"wb"`` (vertical)."""
    blocks, total, p95 = _loco.weighted_rms(_record(acc), fs, weighting)
    return WeightedRms(blocks, total, p95)


def comfort_nmv(
    fs: float,
    ax: npt.ArrayLike | None = None,
    ay: npt.ArrayLike | None = None,
    az: npt.ArrayLike | None = None,
) -> float:
    """EN 12299 mean comfort index N_MV from floor accelerations (m/s²); missing directions
    count as zero."""
    conv = [None if a is None else _record(a) for a in (ax, ay, az)]
    return _loco.comfort_nmv(fs, conv[0], conv[1], conv[2])


def run_metric_names() -> list[str]:
    """Names of the values :func:`run_metrics` returns, in order."""
    return _loco.run_metric_names()


def run_metrics(
    fs: float,
    speed: float,
    carbody_lateral: npt.ArrayLike,
    bogie_lateral: npt.ArrayLike,
    bogie_mass: float,
    carbody_vertical: npt.ArrayLike | None = None,
) -> dict[str, float]:
    """Every metric of one run (the row the batch engine returns), by name."""
    vertical = None if carbody_vertical is None else _record(carbody_vertical)
    values = _loco.run_metrics(
        fs, speed, _record(carbody_lateral), _record(bogie_lateral), bogie_mass, vertical
    )
    return dict(zip(run_metric_names(), (float(v) for v in values), strict=True))
