"""The GP kernel with its gradient formed in one array gives scikit-learn's composite kernel bit
for bit, so every Gaussian-process fit of the surrogate selection is unchanged by it."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from scipy.stats import qmc
from sklearn.exceptions import ConvergenceWarning
from sklearn.gaussian_process import GaussianProcessRegressor
from sklearn.gaussian_process.kernels import RBF, ConstantKernel, Kernel, Matern, WhiteKernel

from loco.studies.gp_kernel import ScaledKernelWithNoise, scaled_kernel_with_noise


def shapes(length: np.ndarray) -> list[Kernel]:
    return [Matern(length, (1e-2, 1e3), nu=2.5), RBF(length, (1e-2, 1e3))]


def plain(shape: Kernel, constant: float, noise: float) -> Kernel:
    return ConstantKernel(constant) * shape + WhiteKernel(noise, (1e-8, 1e1))


def fused_kernel(
    shape: Kernel, constant: float = 1.0, noise: float = 1e-2
) -> ScaledKernelWithNoise:
    return scaled_kernel_with_noise(shape, constant=constant, noise=noise, noise_bounds=(1e-8, 1e1))


@pytest.mark.parametrize(("n", "p"), [(1, 2), (2, 6), (37, 6), (120, 6), (64, 3), (30, 9)])
def test_the_fused_kernel_and_gradient_are_scikit_learns_bit_for_bit(n: int, p: int) -> None:
    rng = np.random.default_rng(n * 10 + p)
    x = rng.random((n, p))
    length = np.exp(rng.normal(size=p))
    constant, noise = 3 * rng.random(), 0.1 * rng.random()
    for reference, shape in zip(shapes(length), shapes(length), strict=True):
        fused = fused_kernel(shape, constant, noise)
        k0, g0 = plain(reference, constant, noise)(x, eval_gradient=True)
        k1, g1 = fused(x, eval_gradient=True)
        assert g1.shape == g0.shape == (n, n, p + 2)
        assert np.array_equal(k1, k0), type(shape).__name__
        assert np.array_equal(g1, g0), type(shape).__name__
        # Without the gradient, or between two sets of points, it is scikit-learn's own code.
        y = rng.random((5, p))
        assert np.array_equal(fused(x, y), plain(reference, constant, noise)(x, y))
        assert np.array_equal(fused(x), k0)


def test_other_compositions_and_fixed_hyperparameters_take_scikit_learns_path() -> None:
    x = np.random.default_rng(1).random((20, 4))
    length = np.full(4, 0.7)
    cases = [
        Matern(length, (1e-2, 1e3), nu=1.5),
        Matern(0.7, (1e-2, 1e3), nu=2.5),
        RBF(length, "fixed"),
    ]
    for shape in cases:
        fused = fused_kernel(shape)
        assert fused._fused_shape(x, None, True) is None
        k0, g0 = plain(shape, 1.0, 1e-2)(x, eval_gradient=True)
        k1, g1 = fused(x, eval_gradient=True)
        assert np.array_equal(k1, k0) and np.array_equal(g1, g0)


def test_a_fitted_process_is_the_same_with_either_kernel() -> None:
    # The optimiser sees the same likelihood and gradient, so it takes the same steps: the
    # same hyperparameters and predictions, bit for bit.
    x = qmc.LatinHypercube(d=6, seed=3).random(90)
    y = np.sin(3 * x[:, 0]) + x[:, 1] * x[:, 2] + 0.05 * np.cos(20 * x[:, 3])
    test = qmc.LatinHypercube(d=6, seed=4).random(40)
    for reference, shape in zip(shapes(np.full(6, 0.5)), shapes(np.full(6, 0.5)), strict=True):
        fits = []
        for kernel in (plain(reference, 1.0, 1e-2), fused_kernel(shape)):
            gp = GaussianProcessRegressor(kernel, normalize_y=True, random_state=0)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ConvergenceWarning)
                gp.fit(x, y)
            fits.append(gp)
        assert isinstance(fits[1].kernel_, ScaledKernelWithNoise)
        assert np.array_equal(fits[0].kernel_.theta, fits[1].kernel_.theta)
        assert np.array_equal(fits[0].predict(test), fits[1].predict(test))


def test_the_inputs_are_summed_in_numpys_order_or_by_numpy() -> None:
    # Up to 7 inputs this numpy adds a pair's terms in order (the fast sum); from 8 on it sums
    # pairwise, and numpy's own sum is taken. Either way the bits of `sum(-1)`.
    from loco.studies.gp_kernel import _sum_over_inputs

    rng = np.random.default_rng(5)
    for p in (2, 6, 8, 11):
        d = rng.random((p, 17, 17)) * np.exp(8 * rng.normal(size=(p, 17, 17)))
        expected = np.ascontiguousarray(d.transpose(1, 2, 0)).sum(-1)
        assert np.array_equal(_sum_over_inputs(d), expected), p
