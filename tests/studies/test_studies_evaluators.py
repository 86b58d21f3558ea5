"""The evaluator protocol helpers: shape checks and column-wise stacking."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt
import pytest

from loco.studies.evaluators import evaluate_checked, stack_evaluators

F64 = npt.NDArray[np.float64]


def total(x: F64, names: Sequence[str]) -> F64:
    return np.asarray(x.sum(axis=1), dtype=np.float64)


def product_and_first(x: F64, names: Sequence[str]) -> F64:
    return np.column_stack([x.prod(axis=1), x[:, 0]])


def test_evaluate_checked_shapes() -> None:
    x = np.arange(6.0).reshape(3, 2)
    np.testing.assert_array_equal(evaluate_checked(total, x, ["a", "b"], 1), [[1.0], [5.0], [9.0]])
    with pytest.raises(ValueError, match=r"expected \(3, 2\)"):
        evaluate_checked(total, x, ["a", "b"], 2)


def test_stack_evaluators_side_by_side() -> None:
    x = np.arange(6.0).reshape(3, 2)
    both = stack_evaluators((total, 1), (product_and_first, 2))
    np.testing.assert_array_equal(
        both(x, ["a", "b"]), [[1.0, 0.0, 0.0], [5.0, 6.0, 2.0], [9.0, 20.0, 4.0]]
    )
    with pytest.raises(ValueError, match="at least one"):
        stack_evaluators()
