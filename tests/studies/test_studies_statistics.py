"""Statistics of the compared quantities against hand-computed cases: the Student t interval of
a known sample, the paired test on constructed pairs, Holm's adjustment, the ranking."""

from __future__ import annotations

import numpy as np
import pytest

from loco.studies.statistics import holm, mean_interval, paired_test, rank


def test_interval_of_a_known_sample() -> None:
    # 1..5: mean 3, s = sqrt(2.5), t(0.975, 4) = 2.776445 -> half-width 1.963243.
    ci = mean_interval([1.0, 2.0, 3.0, 4.0, 5.0])
    assert ci.n == 5 and ci.mean == 3.0 and ci.std == pytest.approx(np.sqrt(2.5))
    assert ci.low == pytest.approx(3.0 - 1.963243, abs=1e-6)
    assert ci.high == pytest.approx(3.0 + 1.963243, abs=1e-6)


def test_interval_drops_failed_runs_and_needs_two() -> None:
    # [1, NaN, 3]: mean 2, s = sqrt(2), t(0.975, 1) = 12.7062 -> half-width 12.7062.
    ci = mean_interval([1.0, np.nan, 3.0])
    assert ci.n == 2 and ci.mean == 2.0
    assert ci.high - ci.mean == pytest.approx(12.7062, abs=1e-4)
    one = mean_interval([np.nan, 4.0])
    assert one.n == 1 and one.mean == 4.0 and np.isnan(one.low) and np.isnan(one.high)
    assert mean_interval([np.nan]).n == 0


def test_paired_test_on_constructed_pairs() -> None:
    b = np.array([1.0, 2.0, 4.0, 8.0])  # the track-to-track spread the pairs share
    a = b * np.array([2.0, 2.2, 1.8, 2.0])
    t = paired_test(a, b, names=("a", "b"))
    # d = ln(a/b) = ln 2 + ln(1, 1.1, 0.9, 1): mean 0.690635, s 0.0819749, t = 16.8498 (3 dof).
    assert t.n == 4 and t.ratio == pytest.approx(np.exp(0.690635), rel=1e-6)
    from scipy import stats

    assert t.p_t == pytest.approx(2 * stats.t.sf(16.8498, 3), rel=1e-3)
    half = 3.182446 * 0.0819749 / 2.0  # t(0.975, 3) s / sqrt(4)
    assert t.ratio_low == pytest.approx(np.exp(0.690635 - half), rel=1e-5)
    assert t.ratio_high == pytest.approx(np.exp(0.690635 + half), rel=1e-5)
    # Exact Wilcoxon with all 4 differences positive: p = 2 / 2^4.
    assert t.p_wilcoxon == pytest.approx(0.125)
    assert t.significant  # p_holm = p_t outside a ranking
    # An unpaired view would see no difference: the shared spread (factor 8) swamps the factor 2.
    assert stats.ttest_ind(np.log(a), np.log(b)).pvalue > 0.05


def test_paired_test_edge_cases() -> None:
    exact = paired_test([2.0, 4.0, 6.0], [1.0, 2.0, 3.0])
    assert exact.ratio == pytest.approx(2.0) and exact.p_t == 0.0
    same = paired_test([1.0, 2.0, 3.0], [1.0, 2.0, 3.0])
    assert same.ratio == 1.0 and same.p_t == 1.0 and same.p_wilcoxon == 1.0
    failed = paired_test([1.0, np.nan, 3.0, 5.0], [2.0, 1.0, np.nan, 4.0])
    assert failed.n == 2  # only the tracks both runs finished
    assert np.isnan(paired_test([1.0], [2.0]).p_t)
    with pytest.raises(ValueError, match="paired_test"):
        paired_test([1.0, 2.0], [1.0])


def test_holm() -> None:
    # Sorted 0.01, 0.03, 0.04 times 3, 2, 1 -> 0.03, 0.06, max(0.06, 0.04); back in given order.
    np.testing.assert_allclose(holm([0.01, 0.04, 0.03]), [0.03, 0.06, 0.06])
    np.testing.assert_allclose(holm([0.5, 0.9]), [1.0, 1.0])
    out = holm([np.nan, 0.02])
    assert np.isnan(out[0]) and out[1] == pytest.approx(0.02)


def test_ranking() -> None:
    rng = np.random.default_rng(0)
    base = np.exp(rng.normal(0.0, 0.8, 8))  # a factor ~5 between tracks
    noise = np.exp(rng.normal(0.0, 0.05, (3, 8)))
    clear = rank({"YD2": 4 * base * noise[2], "FSD": base * noise[0], "YD1": 2 * base * noise[1]},
                 label="S_low", metric="m")  # fmt: skip
    assert clear.order == ("FSD", "YD1", "YD2") and clear.significant
    assert clear.test("YD2", "FSD").ratio == pytest.approx(0.25, rel=0.1)
    text = clear.statement()
    assert text.startswith("S_low, m: FSD < YD1 < YD2: ranking significant at 0.05 over 8")
    wobble = np.tile([1.1, 0.9], 4)  # FSD/YD1 alternates 1.1/0.9 and 0.9/1.1: mean log ratio 0
    tied = rank({"YD1": base * wobble, "FSD": base * wobble[::-1], "YD2": 3 * base * noise[2]})
    assert tied.order[2] == "YD2" and not tied.significant
    assert "≈ FSD < YD2" in tied.statement() or "≈ YD1 < YD2" in tied.statement()
    assert "ranking partly significant" in tied.statement()
    flat = rank({"a": base * wobble, "b": base * wobble[::-1]})
    assert "ranking not significant" in flat.statement()
    assert tied.test("YD1", "FSD").p_t == pytest.approx(1.0)
    assert tied.test("YD1", "YD2").significant and tied.test("FSD", "YD2").significant
    for t in tied.tests:
        assert t.p_holm >= t.p_t
