"""NSGA-II through the study code path on bi-objective problems with known Pareto fronts."""

from __future__ import annotations

import warnings
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import numpy.typing as npt

from loco.studies.parameters import StudyParameter
from loco.studies.pareto import nsga2, pick_spread, plot_pareto, verify_points

F64 = npt.NDArray[np.float64]
BOX = [StudyParameter(f"x{i}", 0.0, 100.0, "kN/mm", "N/m", 1e6) for i in range(3)]
A = np.array([2e7, 3e7, 5e6])
B = np.array([6e7, 1e7, 8e6])
SCALE = 1e7


def quadratic_pair(x: F64, names: Sequence[str]) -> F64:
    """f1 = |x − a|², f2 = |x − b|² (scaled): Pareto set the segment ab, front
    √f1 + √f2 = |a − b| (closed form)."""
    return np.column_stack(
        [np.sum(((x - A) / SCALE) ** 2, axis=1), np.sum(((x - B) / SCALE) ** 2, axis=1)]
    )


def zdt1(x: F64, names: Sequence[str]) -> F64:
    """ZDT1 (Zitzler, Deb & Thiele 2000) on [0, 1]^k: front f2 = 1 − √f1 at g = 1."""
    f1 = x[:, 0]
    g = 1.0 + 9.0 * x[:, 1:].mean(axis=1)
    return np.column_stack([f1, g * (1.0 - np.sqrt(f1 / g))])


def test_quadratic_pair_front_and_set(tmp_path: Path) -> None:
    res = nsga2(quadratic_pair, ["f1", "f2"], BOX, pop_size=40, n_gen=100, seed=2, progress=False)
    d = np.linalg.norm((A - B) / SCALE)
    assert len(res.f) >= 20
    # Relative distance to the exact front: never below it, close to it.
    excess = (np.sqrt(res.f[:, 0]) + np.sqrt(res.f[:, 1])) / d - 1.0
    assert excess.min() > -1e-9
    assert np.median(excess) < 0.015 and excess.max() < 0.05
    # Every Pareto point lies near the segment ab. A step δ off it costs only O(δ²/d) in the
    # objectives, so a front within 5 % allows δ up to about d·√(0.05/2) ≈ 0.16 d.
    t = ((res.x - A) @ (B - A)) / np.dot(B - A, B - A)
    off = np.linalg.norm(res.x - (A + t[:, None] * (B - A)), axis=1) / SCALE
    assert off.max() < 0.16 * d and np.median(off) < 0.05 * d and t.min() > -0.01 and t.max() < 1.01
    # The front spans most of the segment.
    assert t.min() < 0.1 and t.max() > 0.9
    np.testing.assert_allclose(res.x_units, res.x / 1e6)
    frame = res.to_frame()
    assert list(frame.columns[:5]) == ["f1", "f2", "x0", "x1", "x2"]
    assert "x0 [kN/mm]" in frame.columns
    # Deterministic for a seed.
    again = nsga2(quadratic_pair, ["f1", "f2"], BOX, pop_size=40, n_gen=100, seed=2, progress=False)
    np.testing.assert_array_equal(res.f, again.f)
    path = tmp_path / "pareto.png"
    plot_pareto(res, path)
    assert path.stat().st_size > 1000


def test_zdt1_front() -> None:
    box = [StudyParameter(f"z{i}", 0.0, 1.0, "-", "-", 1.0) for i in range(4)]
    res = nsga2(zdt1, ["f1", "f2"], box, pop_size=40, n_gen=150, seed=1, progress=False)
    gap = res.f[:, 1] - (1.0 - np.sqrt(res.f[:, 0]))
    assert gap.min() > -1e-9  # nothing beats the true front
    assert np.median(gap) < 0.02
    assert res.f[:, 0].min() < 0.05 and res.f[:, 0].max() > 0.9


def test_spread_and_verification() -> None:
    res = nsga2(quadratic_pair, ["f1", "f2"], BOX, pop_size=40, n_gen=40, seed=3, progress=False)
    idx = pick_spread(res, 5)
    assert len(idx) == 5 and idx[0] == 0 and idx[-1] == len(res.f) - 1
    assert np.all(np.diff(idx) > 0)

    def biased(x: F64, names: Sequence[str]) -> F64:
        return quadratic_pair(x, names) + 0.1

    exact = verify_points(res, idx, quadratic_pair)
    np.testing.assert_allclose(exact["f1_error"], 0.0, atol=1e-12)
    off = verify_points(res, idx, biased)
    np.testing.assert_allclose(off["f2_error"], -0.1, atol=1e-12)
    assert list(off["pareto_index"]) == list(idx)


def test_failed_points_are_infeasible() -> None:
    box = [StudyParameter(f"z{i}", 0.0, 1.0, "-", "-", 1.0) for i in range(3)]

    def failing_zdt1(x: F64, names: Sequence[str]) -> F64:
        f = zdt1(x, names)
        f[x[:, 0] > 0.8] = np.nan  # a failed simulation
        return f

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        res = nsga2(failing_zdt1, ["f1", "f2"], box, pop_size=30, n_gen=30, seed=0, progress=False)
    assert np.isfinite(res.f).all() and np.all(res.x[:, 0] <= 0.8)
    assert res.f[:, 0].max() > 0.6
