"""Study parameters (SPEC §6.2 in SI) and the sampling designs."""

from __future__ import annotations

import numpy as np
import pytest

from loco.studies import parameters as sp
from loco.studies.sampling import latin_hypercube, saltelli, saltelli_block_size
from loco.studies.surrogate_samples import extension_design, training_design


def test_six_parameters_in_si() -> None:
    table = sp.parameter_table()
    assert list(table["name"]) == ["K_px", "K_py", "C_sx", "C_sy", "K_ncsx", "K_ncsy"]
    bounds = sp.bounds_si()
    # 10-50 kN/mm = 1e7-5e7 N/m; 200-1200 kN·s/m = 2e5-1.2e6 N·s/m.
    assert bounds[0].tolist() == [1e7, 5e7]
    assert bounds[1].tolist() == [2e6, 1e7]
    assert bounds[2].tolist() == [2e5, 1.2e6]
    assert bounds[3].tolist() == [1e4, 6e4]
    problem = sp.salib_problem()
    assert problem["num_vars"] == 6 and problem["bounds"] == bounds.tolist()
    x = np.array([[30.0, 5.0, 800.0, 40.0, 20.0, 15.0]])
    np.testing.assert_allclose(sp.to_study_units(sp.to_si(x)), x)
    with pytest.raises(ValueError, match="low < high"):
        sp.StudyParameter("bad", 2.0, 1.0, "-", "-", 1.0)


def test_latin_hypercube_strata_and_seed() -> None:
    n = 40
    x = latin_hypercube(n, seed=3)
    assert x.shape == (n, 6)
    bounds = sp.bounds_si()
    u = (x - bounds[:, 0]) / (bounds[:, 1] - bounds[:, 0])
    # One sample in each of the n strata of every column.
    for j in range(6):
        assert sorted(np.floor(u[:, j] * n).astype(int)) == list(range(n))
    np.testing.assert_array_equal(x, latin_hypercube(n, seed=3))
    assert not np.array_equal(x, latin_hypercube(n, seed=4))


def test_saltelli_blocks_are_a_prefix() -> None:
    k = 6
    block = saltelli_block_size(k)
    big = saltelli(16, seed=1)
    small = saltelli(4, seed=1)
    assert big.shape == (16 * block, k)
    np.testing.assert_array_equal(big[: 4 * block], small)
    # Row i + 1 of a block is A with column i taken from B (the block's last row).
    a, b = big[0], big[block - 1]
    for i in range(k):
        expected = a.copy()
        expected[i] = b[i]
        np.testing.assert_array_equal(big[1 + i], expected)
    with pytest.raises(ValueError, match="power of 2"):
        saltelli(12)


def test_surrogate_training_design_extends_the_monte_carlo() -> None:
    """The surrogate's samples are the Monte Carlo's Latin hypercube unchanged, followed by an
    independent one of the rest (the SPEC network's R² stays on the SPEC's 200)."""
    x = training_design(30, 20, seed=3)
    assert x.shape == (30, 6)
    np.testing.assert_array_equal(x[:20], latin_hypercube(20, seed=3))
    np.testing.assert_array_equal(x[20:], extension_design(30, 20, seed=3))
    # Independent of the Monte Carlo's design, and of the Monte Carlo of the next study seed.
    assert not np.isin(x[20:, 0], x[:20, 0]).any()
    assert not np.isin(x[20:, 0], latin_hypercube(20, seed=4)[:, 0]).any()
    # The extension is itself a Latin hypercube: one point in each of its 10 strata per column.
    bounds = sp.bounds_si()
    unit = (x[20:] - bounds[:, 0]) / (bounds[:, 1] - bounds[:, 0])
    for column in unit.T:
        assert sorted(np.floor(column * 10).astype(int)) == list(range(10))
    assert training_design(10, 20, seed=3).shape == (20, 6)
    assert extension_design(10, 20, seed=3).shape == (0, 6)
