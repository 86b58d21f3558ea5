"""Metrics: Sperling hand-worked cases, PSD, dominant frequency, stability, comfort, errors."""

from __future__ import annotations

import numpy as np
import pytest

import loco
from loco import metrics
from verification_records import record

FS = 500.0


def sine(a: float, f: float, seconds: float = 9.0, fs: float = FS) -> np.ndarray:
    t = np.arange(round(seconds * fs)) / fs
    return a * np.sin(2 * np.pi * f * t + 0.7)


def hand_sperling(a: float, f: float, lateral: bool = True) -> float:
    # GB/T 5599-2019: W = 3.57 (A^3 F(f) / f)^0.1, weighting of the direction.
    if lateral:
        weight = 0.8 * f**2 if f < 5.4 else (650 / f**2 if f < 26 else 1.0)
    else:
        weight = 0.325 * f**2 if f < 5.9 else (400 / f**2 if f < 20 else 1.0)
    return 3.57 * (a**3 * weight / f) ** 0.1


@pytest.mark.parametrize(
    ("a", "f", "direction"),
    [
        (0.3, 1.2, "lateral"),  # on a 0.2 Hz bin of the 5 s segments
        (0.3, 1.3, "lateral"),  # half a bin off
        (0.15, 11.11, "lateral"),
        (0.5, 7.77, "vertical"),
        (0.2, 30.05, "vertical"),
    ],
)
def test_sperling_single_sine_matches_formula(a: float, f: float, direction: str) -> None:
    w = metrics.sperling(sine(a, f), FS, direction)
    expected = hand_sperling(a, f, direction == "lateral")
    assert len(w.segments) == 2
    np.testing.assert_allclose(w.segments, expected, rtol=1e-3)
    assert w.max == pytest.approx(expected, rel=1e-3)
    deviation = float(np.max(np.abs(np.asarray(w.segments) / expected - 1)))
    (
        record(f"sperling_{direction}_{str(f).replace('.', 'p')}_hz", __file__)
        .value("hand_value", expected, "", 4)
        .below("deviation", deviation, "", 1e-9, "<", 1e-3)
        .check()
    )


def test_sperling_hand_value_and_rating() -> None:
    # A = 0.3 m/s², 1.2 Hz lateral: F = 1.152, A³F/f = 0.02592, W = 3.57·0.02592^0.1 = 2.4776.
    w = metrics.sperling(sine(0.3, 1.2), FS)
    assert w.mean == pytest.approx(2.4776, abs=2e-3)
    assert w.rating == "excellent"
    assert metrics.sperling(sine(1.0, 1.2), FS).rating != "excellent"


def test_psd_and_dominant_frequency() -> None:
    x = sine(0.5, 6.37)
    f, p = metrics.psd(x, FS)
    assert np.sum(p) * f[1] == pytest.approx(0.125, rel=5e-3)  # A²/2
    d = metrics.dominant_frequency(x, FS)
    assert d.frequency == pytest.approx(6.37, abs=0.025)
    assert d.peak == pytest.approx(p.max())


def test_bogie_stability_of_hunting_and_of_quiet_running() -> None:
    hunting = metrics.bogie_stability(sine(9.0, 6.0), FS, speed=200 / 3.6, bogie_mass=5000.0)
    assert hunting.gbt_unstable and hunting.en_unstable
    assert hunting.f0 == pytest.approx(6.0, abs=0.03)
    assert hunting.limit == pytest.approx(5.5)
    quiet = metrics.bogie_stability(sine(1.0, 6.0), FS, speed=200 / 3.6, bogie_mass=5000.0)
    assert not quiet.gbt_unstable and not quiet.en_unstable
    assert quiet.max_consecutive_cycles == 0


def test_weighted_rms_and_nmv() -> None:
    # Wd at 1 Hz is 1.011 (ISO 2631-1 Table 3): weighted rms of a 1 Hz sine = 1.011 A/√2.
    r = metrics.weighted_rms(sine(0.2, 1.0), FS, "wd")
    assert r.p95 == pytest.approx(1.011 * 0.2 / np.sqrt(2), rel=3e-3)
    nmv = metrics.comfort_nmv(FS, ay=sine(0.2, 1.0))
    assert nmv == pytest.approx(6 * r.p95, rel=1e-9)


def test_run_metrics_row() -> None:
    row = metrics.run_metrics(
        FS, 200 / 3.6, sine(0.3, 1.3), sine(2.0, 6.0), 12_000.0, carbody_vertical=sine(0.2, 2.0)
    )
    assert list(row) == metrics.run_metric_names()
    assert row["wy_max"] == pytest.approx(hand_sperling(0.3, 1.3), rel=1e-3)
    assert row["ayb_f0_hz"] == pytest.approx(6.0, abs=0.03)
    assert row["ayb_en_unstable"] == 0.0


@pytest.mark.parametrize(
    ("x", "fs", "match"),
    [
        (np.zeros(0), FS, "too short"),
        (np.zeros(100), FS, "too short"),
        (np.r_[np.zeros(3000), np.nan, np.zeros(2000)], FS, "element 3000"),
        (np.zeros(5000), 0.0, "fs"),
        (np.zeros(5000), -1.0, "fs"),
    ],
)
def test_bad_records_raise_parameter_error(x: np.ndarray, fs: float, match: str) -> None:
    with pytest.raises(loco.ParameterError, match=match):
        metrics.sperling(x, fs)
    with pytest.raises(loco.ParameterError):
        metrics.bogie_stability(x, fs, 50.0, 5000.0)


def test_bad_options_raise() -> None:
    with pytest.raises(loco.ParameterError, match="direction"):
        metrics.sperling(sine(0.1, 1.0), FS, "up")
    with pytest.raises(loco.ParameterError, match="weighting"):
        metrics.weighted_rms(sine(0.1, 1.0), FS, "wk")
    with pytest.raises(loco.ParameterError):
        metrics.psd(np.zeros((10, 10)), FS)
