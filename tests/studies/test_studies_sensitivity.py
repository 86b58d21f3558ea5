"""Sobol' indices through the study code path, checked on the Ishigami function."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
import numpy.typing as npt

from loco.studies.parameters import StudyParameter
from loco.studies.sampling import latin_hypercube
from loco.studies.sobol import (
    plot_convergence,
    plot_indices,
    sobol_convergence,
    sobol_direct,
    sobol_on_surrogate,
)

PI_BOX = [StudyParameter(f"x{i}", -np.pi, np.pi, "rad", "rad", 1.0) for i in (1, 2, 3)]
UNIT_BOX = [StudyParameter(f"u{i}", 0.0, 1.0, "-", "-", 1.0) for i in (1, 2, 3)]

# Ishigami & Homma (1990), a = 7, b = 0.1: analytic indices (Sobol' & Levitan 1999).
S1_EXACT = np.array([0.3139, 0.4424, 0.0])
ST_EXACT = np.array([0.5576, 0.4424, 0.2437])


def ishigami(x: npt.NDArray[np.float64], names: Sequence[str]) -> npt.NDArray[np.float64]:
    assert list(names) == ["x1", "x2", "x3"]
    y = np.sin(x[:, 0]) + 7.0 * np.sin(x[:, 1]) ** 2 + 0.1 * x[:, 2] ** 4 * np.sin(x[:, 0])
    return y[:, None]


def test_ishigami_direct_matches_analytic() -> None:
    (ind,) = sobol_direct(ishigami, ["f"], PI_BOX, n_base=4096, seed=0)
    assert ind.n_evaluations == 4096 * 5 and ind.n_dropped == 0
    np.testing.assert_allclose(ind.S1, S1_EXACT, atol=0.02)
    np.testing.assert_allclose(ind.ST, ST_EXACT, atol=0.02)
    # The bootstrap intervals cover the exact values and are not degenerate.
    assert np.all(np.abs(ind.S1 - S1_EXACT) <= ind.S1_conf)
    assert np.all(np.abs(ind.ST - ST_EXACT) <= ind.ST_conf)
    assert np.all(ind.ST_conf > 0)
    frame = ind.to_frame()
    assert len(frame) == 6 and set(frame["index"]) == {"S1", "ST"}


def test_failed_blocks_are_dropped_whole() -> None:
    def failing(x: npt.NDArray[np.float64], names: Sequence[str]) -> npt.NDArray[np.float64]:
        y = ishigami(x, names)
        y[::97] = np.nan
        return y

    (ind,) = sobol_direct(failing, ["f"], PI_BOX, n_base=2048, seed=0)
    rows = np.arange(2048 * 5)
    expected_dropped = len(np.unique(rows[::97] // 5))
    assert ind.n_dropped == expected_dropped
    assert np.all(np.isfinite(ind.ST))
    np.testing.assert_allclose(ind.ST, ST_EXACT, atol=0.04)


def test_convergence_frame_and_plot(tmp_path: Path) -> None:
    frame = sobol_convergence(ishigami, ["f"], PI_BOX, n_bases=(64, 256, 2048), progress=False)
    assert sorted(set(frame["n_base"])) == [64, 256, 2048]
    assert len(frame) == 3 * 2 * 3
    last = frame[(frame["n_base"] == 2048) & (frame["index"] == "ST")]
    np.testing.assert_allclose(last["value"], ST_EXACT, atol=0.03)
    # Confidence intervals narrow as the sample grows.
    conf = frame[frame["index"] == "ST"].groupby("n_base")["conf"].mean()
    assert conf[2048] < conf[64]
    path = tmp_path / "conv.png"
    plot_convergence(frame, path)
    assert path.stat().st_size > 1000


def test_surrogate_indices_match_direct(tmp_path: Path) -> None:
    def smooth(x: npt.NDArray[np.float64], names: Sequence[str]) -> npt.NDArray[np.float64]:
        y = np.exp(x[:, 0]) + 0.5 * x[:, 1] ** 2 + 0.2 * x[:, 0] * x[:, 2]
        return y[:, None]

    (direct,) = sobol_direct(smooth, ["g"], UNIT_BOX, n_base=4096, seed=1)
    x = latin_hypercube(200, UNIT_BOX, seed=2)
    (sur,), models = sobol_on_surrogate(x, smooth(x, []), ["g"], UNIT_BOX, n_base=2048, seed=1)
    assert len(models) == 1
    np.testing.assert_allclose(sur.ST, direct.ST, atol=0.03)
    np.testing.assert_allclose(sur.S1, direct.S1, atol=0.03)
    path = tmp_path / "ind.png"
    plot_indices([("direct", direct), ("surrogate", sur)], path)
    assert path.stat().st_size > 1000
