"""Statistics of what the study compares: means and 95 % intervals over track seeds, and paired
tests of which yaw damper is better.

One 500 m record of one synthesised track gives noisy PSD peaks (the same case changes by a
factor 2-5 from one track to the next), so every compared quantity is run on ``n`` tracks (ChaCha
streams ``0 … n-1`` of the track seed, :func:`loco.studies.seeds.run_over_tracks`) and reported
as a mean with its 95 % interval.

Interval (:func:`mean_interval`): Student's t interval of the mean, mean ± t(0.975, n−1)·s/√n
with s the sample standard deviation (ddof 1). It assumes the per-track values are roughly normal;
with 3-8 tracks nothing better is identifiable, and it is the interval the reader can check by
hand.

Positive quantities (PSD peaks, rms, W_y, A_yb: :func:`geometric_interval`) vary by factors from
track to track, and the t interval of their mean can reach below zero. They are given as the
geometric mean exp(mean(ln x)) with exp(mean(ln x) ± t(0.975, n−1)·s_ln/√n), the t interval of the
logs taken back: it is never below zero and is the interval of the median of a log-normal
quantity (the same scale as the paired tests' ratios below).

Dominant frequencies (:func:`median_values`) are not averaged: on one track the PSD peak is the
carbody's sway near 1 Hz, on the next a bogie's mode near 10 Hz, and their mean is neither. They
are given as the median over the tracks with every track's value.

Paired test (:func:`paired_test`): every damper runs on the *same* tracks (common random numbers),
so the comparison of dampers a and b is on the per-track differences, which removes the
track-to-track variation the two share. The quantities are positive and vary by factors from
track to track, so the test works on the log ratio d_i = ln(a_i / b_i): Student's paired t test of
mean(d) = 0 (``scipy.stats.ttest_1samp`` on d), whose interval exp(mean(d) ± t·s_d/√n) is the 95 %
interval of the geometric-mean ratio a/b. The Wilcoxon signed-rank test (``scipy.stats.wilcoxon``,
exact) is given beside it as a distribution-free check; with n tracks its smallest two-sided p is
2/2ⁿ (0.25 for 3, 0.125 for 4, 0.008 for 8), so it can only confirm a difference from 6 tracks on.

Ranking (:func:`rank`): the dampers are ordered by mean (lower is better), the three pairwise
t-test p values of a scenario are adjusted by Holm's step-down method (Holm 1979, Scand. J.
Statist. 6:65-70; it controls the family-wise error without assuming independence), and the
ranking is called significant when every neighbouring pair of the order differs at
:data:`ALPHA` after the adjustment, partly significant when some do (the report marks each step
``<`` when it is significant and ``≈`` when it is not).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from scipy import stats

__all__ = [
    "ALPHA",
    "CONFIDENCE",
    "Interval",
    "PairedTest",
    "Ranking",
    "geometric_interval",
    "holm",
    "mean_interval",
    "median_values",
    "paired_test",
    "rank",
    "track_values_text",
]

FloatArray = npt.NDArray[np.float64]

#: Confidence level of every interval of the study.
CONFIDENCE = 0.95
#: Significance level of the paired tests (family-wise, per ranking).
ALPHA = 0.05


@dataclass(frozen=True)
class Interval:
    """Mean of ``n`` finite values and its Student t interval (``low``, ``high``; NaN for
    n < 2); ``std`` is the sample standard deviation (ddof 1)."""

    mean: float
    low: float
    high: float
    std: float
    n: int


def mean_interval(values: npt.ArrayLike, confidence: float = CONFIDENCE) -> Interval:
    """Mean and Student t interval of the finite entries of ``values`` (NaN = failed run, left
    out)."""
    x = np.asarray(values, dtype=np.float64).ravel()
    x = x[np.isfinite(x)]
    n = len(x)
    if n == 0:
        return Interval(np.nan, np.nan, np.nan, np.nan, 0)
    mean = float(x.mean())
    if n < 2:
        return Interval(mean, np.nan, np.nan, np.nan, n)
    std = float(x.std(ddof=1))
    half = float(stats.t.ppf(0.5 + confidence / 2, n - 1)) * std / np.sqrt(n)
    return Interval(mean, mean - half, mean + half, std, n)


def geometric_interval(values: npt.ArrayLike, confidence: float = CONFIDENCE) -> Interval:
    """Geometric mean and its interval (the t interval of the logs, taken back) of the finite
    entries of ``values``, a positive quantity; ``std`` is the sample standard deviation of the
    logs. A value at or below zero has no logarithm: then the arithmetic :func:`mean_interval`
    is given, its interval cut at zero."""
    x = np.asarray(values, dtype=np.float64).ravel()
    x = x[np.isfinite(x)]
    if len(x) and (x <= 0).any():
        ci = mean_interval(x, confidence)
        return Interval(ci.mean, max(ci.low, 0.0), ci.high, ci.std, ci.n)
    logs = mean_interval(np.log(x), confidence) if len(x) else mean_interval(x)
    return Interval(
        float(np.exp(logs.mean)),
        float(np.exp(logs.low)),
        float(np.exp(logs.high)),
        logs.std,
        logs.n,
    )


def median_values(values: npt.ArrayLike) -> tuple[float, list[float]]:
    """The median of the finite entries of ``values`` (NaN when none) and every entry (NaN for
    a failed run), in track order."""
    x = np.asarray(values, dtype=np.float64).ravel()
    finite = x[np.isfinite(x)]
    median = float(np.median(finite)) if len(finite) else float("nan")
    return median, [float(v) for v in x]


def track_values_text(values: Sequence[float], digits: int = 3) -> str:
    """Per-track values as ``"1.12, 10.4, -"`` (a dash for a failed run)."""
    return ", ".join(f"{v:.{digits}g}" if np.isfinite(v) else "-" for v in values)


@dataclass(frozen=True)
class PairedTest:
    """Paired comparison of ``a`` with ``b`` over the tracks both finished (``n``).

    ``ratio`` is the geometric mean of a_i / b_i with its 95 % interval (``ratio_low``,
    ``ratio_high``); ``p_t`` the two-sided p of the paired t test on ln(a_i / b_i), ``p_holm`` that
    p after Holm's adjustment within its ranking (= ``p_t`` outside one), ``p_wilcoxon`` the
    exact two-sided Wilcoxon signed-rank p.
    """

    a: str
    b: str
    n: int
    ratio: float
    ratio_low: float
    ratio_high: float
    p_t: float
    p_wilcoxon: float
    p_holm: float

    @property
    def significant(self) -> bool:
        """Whether a and b differ at :data:`ALPHA` (after Holm's adjustment)."""
        return bool(self.p_holm < ALPHA)


def paired_test(
    a: npt.ArrayLike, b: npt.ArrayLike, *, names: tuple[str, str] = ("a", "b")
) -> PairedTest:
    """Paired t test (and Wilcoxon signed-rank) of ``a`` against ``b``, same tracks in the same
    order, on the log ratios; pairs where either value is NaN or not > 0 are left out."""
    x = np.asarray(a, dtype=np.float64).ravel()
    y = np.asarray(b, dtype=np.float64).ravel()
    if x.shape != y.shape:
        raise ValueError(f"paired_test: {x.shape} values against {y.shape}")
    ok = np.isfinite(x) & np.isfinite(y) & (x > 0) & (y > 0)
    d = np.log(x[ok]) - np.log(y[ok])
    n = len(d)
    nan = float("nan")
    if n < 2:
        return PairedTest(*names, n, nan, nan, nan, nan, nan, nan)
    spread = mean_interval(d)
    if spread.std <= 1e-12 * max(1.0, abs(spread.mean)):
        # The same ratio on every track (to rounding): no spread to test against, the t
        # statistic is undefined or rounding noise; the ratio is known exactly.
        p_t = 1.0 if abs(spread.mean) <= 1e-12 else 0.0
    else:
        p_t = float(stats.ttest_1samp(d, 0.0).pvalue)
    zero = np.abs(d) <= 1e-12
    p_w = 1.0 if zero.all() else float(stats.wilcoxon(d[~zero], method="exact").pvalue)
    return PairedTest(
        names[0],
        names[1],
        n,
        float(np.exp(spread.mean)),
        float(np.exp(spread.low)),
        float(np.exp(spread.high)),
        p_t,
        p_w,
        p_t,
    )


def holm(p_values: Sequence[float]) -> FloatArray:
    """Holm's step-down adjusted p values (same order as given; NaN stays NaN)."""
    p = np.asarray(p_values, dtype=np.float64)
    out = np.full_like(p, np.nan)
    finite = np.flatnonzero(np.isfinite(p))
    order = finite[np.argsort(p[finite], kind="stable")]
    m = len(order)
    running = 0.0
    for k, i in enumerate(order):
        running = max(running, min(1.0, (m - k) * p[i]))
        out[i] = running
    return out


@dataclass(frozen=True)
class Ranking:
    """Order of the candidates by mean ``metric`` (best, i.e. lowest, first), the Holm-adjusted
    pairwise tests and whether the order is significant (every neighbouring pair differs)."""

    label: str
    metric: str
    order: tuple[str, ...]
    means: dict[str, float]
    tests: tuple[PairedTest, ...]
    n: int

    def test(self, a: str, b: str) -> PairedTest:
        """The test of the pair (a, b) in either order."""
        for t in self.tests:
            if {t.a, t.b} == {a, b}:
                return t
        raise KeyError((a, b))

    @property
    def significant(self) -> bool:
        """Every neighbouring pair of :attr:`order` differs at :data:`ALPHA` after Holm."""
        pairs = zip(self.order, self.order[1:], strict=False)
        return len(self.order) > 1 and all(self.test(a, b).significant for a, b in pairs)

    def rows(self) -> list[dict[str, object]]:
        """One table row per pairwise test: label, metric, pair, geometric-mean ratio a/b with its
        interval, p values (t, Holm, Wilcoxon), whether the pair differs, the ranking and whether
        it is significant."""
        return [
            {"scenario": self.label, "metric": self.metric, "a": t.a, "b": t.b, "n_tracks": t.n,
             "ratio_a_b": t.ratio, "ratio_low": t.ratio_low, "ratio_high": t.ratio_high,
             "p_t": t.p_t, "p_holm": t.p_holm, "p_wilcoxon": t.p_wilcoxon,
             "differ": t.significant, "ranking": " < ".join(self.order),
             "ranking_significant": self.significant}
            for t in self.tests
        ]  # fmt: skip

    def statement(self) -> str:
        """One sentence for the report, e.g. ``S_low, W_y: FSD < YD1 < YD2 (significant ...)``."""
        parts = [self.order[0]]
        for a, b in zip(self.order, self.order[1:], strict=False):
            t = self.test(a, b)
            parts.append(f"{'<' if t.significant else '≈'} {b}")
        steps = [
            self.test(a, b).significant for a, b in zip(self.order, self.order[1:], strict=False)
        ]
        verdict = (
            "significant"
            if self.significant
            else ("partly significant" if any(steps) else "not significant")
        )
        pairs = "; ".join(
            f"{t.a}/{t.b} ratio {t.ratio:.2f} [{t.ratio_low:.2f}, {t.ratio_high:.2f}], "
            f"Holm p {t.p_holm:.3g}"
            for t in self.tests
        )
        return (
            f"{self.label}, {self.metric}: {' '.join(parts)}: ranking {verdict} at "
            f"{ALPHA:g} over {self.n} tracks (paired t on log ratios, Holm; {pairs})"
        )


def rank(values: Mapping[str, npt.ArrayLike], *, label: str = "", metric: str = "") -> Ranking:
    """Rank the candidates of ``values`` (name -> per-track values, same tracks in the same
    order; lower is better) and test every pair."""
    names = list(values)
    means = {k: mean_interval(values[k]).mean for k in names}
    order = tuple(sorted(names, key=lambda k: (not np.isfinite(means[k]), means[k])))
    raw = [
        paired_test(values[a], values[b], names=(a, b))
        for i, a in enumerate(order)
        for b in order[i + 1 :]
    ]
    adjusted = holm([t.p_t for t in raw])
    tests = tuple(
        PairedTest(t.a, t.b, t.n, t.ratio, t.ratio_low, t.ratio_high, t.p_t, t.p_wilcoxon, float(p))
        for t, p in zip(raw, adjusted, strict=True)
    )
    n = min((t.n for t in tests), default=0)
    return Ranking(label, metric, order, means, tests, n)
