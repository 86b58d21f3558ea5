"""EN 14363 processing (``loco.studies.en14363``) against independent calculations: the 2 m
sliding mean every 0.5 m by brute force and in closed form, the percentiles by numpy, the limit
values by hand."""

from __future__ import annotations

import numpy as np
import pytest

from loco.studies import en14363


def test_sliding_mean_equals_brute_force_trapezoids_on_aligned_samples() -> None:
    """Samples every 0.1 m: each 2 m window is 20 intervals, each 0.5 m step 5 samples, so the
    mean is numpy's trapezoid rule over the window's 21 samples, divided by 2 m."""
    rng = np.random.default_rng(3)
    s = 10.0 + 0.1 * np.arange(1001)  # 10 … 110 m
    x = rng.normal(size=s.size)
    centres, means = en14363.sliding_mean(s, x, 20.0, 60.0)
    first = 100  # s = 20 m
    n = int((60.0 - 20.0 - 2.0) / 0.5) + 1
    expected = [np.trapezoid(x[first + 5 * k : first + 5 * k + 21], dx=0.1) / 2.0 for k in range(n)]
    assert means.size == n == 77
    np.testing.assert_allclose(means, expected, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(centres, 21.0 + 0.5 * np.arange(n), atol=1e-12)


def test_sliding_mean_of_a_sine_matches_its_integral_off_the_sample_grid() -> None:
    """Samples every 0.37 m (not commensurate with the windows); the mean of sin(2π s/λ) over
    [a, a + 2] is λ (cos 2πa/λ − cos 2π(a + 2)/λ) / (4π)."""
    wavelength = 25.0
    s = 0.37 * np.arange(400)
    x = np.sin(2 * np.pi * s / wavelength)
    centres, means = en14363.sliding_mean(s, x, 5.0, 120.0)
    a = centres - 1.0
    k = 2 * np.pi / wavelength
    exact = (np.cos(k * a) - np.cos(k * (a + 2.0))) / (2.0 * k)
    # The trapezoid rule's error on a sine sampled 68 times a wavelength: about (k h)² / 12.
    np.testing.assert_allclose(means, exact, atol=(k * 0.37) ** 2 / 12 * 1.1)
    assert a[0] == pytest.approx(5.0) and a[-1] + 2.0 <= 120.0


def test_a_section_shorter_than_one_window_has_no_values() -> None:
    s = np.linspace(0.0, 10.0, 101)
    assert en14363.sliding_mean(s, s, 3.0, 4.5)[1].size == 0
    values = en14363.section_values(s, s, 3.0, 4.5)
    assert values.n_means == 0 and np.isnan(values.high)


def test_section_percentiles_are_numpys_of_the_sliding_means() -> None:
    rng = np.random.default_rng(11)
    s = 0.05 * np.arange(8000)
    x = 40e3 + 5e3 * rng.standard_normal(s.size)
    _, means = en14363.sliding_mean(s, x, 100.0, 300.0)
    inside = (s >= 100.0) & (s <= 300.0)
    values = en14363.section_values(s, x, 100.0, 300.0)
    assert values.low == np.percentile(means, 0.15)
    assert values.high == np.percentile(means, 99.85)
    assert values.median == np.median(x[inside])
    assert values.extreme == max(abs(values.low), abs(values.high))
    # 2 m of 0.05 m samples averages 40 values: the means scatter 5e3/√40 ≈ 0.8e3 around 40e3.
    assert 40e3 < values.high < 40e3 + 4 * 5e3 / np.sqrt(40)


def test_limits_by_hand() -> None:
    # Axle load 180 kN: α (10 + 180/3) = 70 kN for a locomotive, 59.5 kN for a freight wagon.
    assert en14363.sum_y_limit(180e3) == pytest.approx(70e3)
    assert en14363.sum_y_limit(180e3, en14363.ALPHA_FREIGHT) == pytest.approx(59.5e3)
    assert en14363.yq_limit(600.0) == 0.8 and en14363.yq_limit(-300.0) == 0.8
    with pytest.raises(ValueError, match="radius 200 m"):
        en14363.yq_limit(200.0)
    assert en14363.YQST_LIMIT == 60e3


def test_section_bounds_follow_the_lengths() -> None:
    assert en14363.section_bounds([20.0, 60.0, 200.0]) == [(0.0, 20.0), (20.0, 80.0), (80.0, 280.0)]


def test_bad_axes_are_refused() -> None:
    with pytest.raises(ValueError, match="increase"):
        en14363.sliding_mean(np.array([0.0, 1.0, 1.0]), np.zeros(3), 0.0, 1.0)
    with pytest.raises(ValueError, match="same length"):
        en14363.sliding_mean(np.arange(3.0), np.zeros(4), 0.0, 1.0)
