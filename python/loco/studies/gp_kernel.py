"""The Gaussian processes' kernel, c·k(x, x') + noise, with its gradient formed in one array.

Why: fitting a GP of the surrogate selection maximises the marginal likelihood, and every
likelihood evaluation asks the kernel for K and its gradient with respect to the log
hyperparameters, an (n, n, p + 2) array. scikit-learn's composite kernel (``Sum`` of ``Product``
of ``ConstantKernel`` and ``Matern`` or ``RBF``, and ``WhiteKernel``) forms it from several
temporaries of that size, along the p inputs of each pair, and stacks them twice
(``np.dstack``): about half of a fit's time on the study's 400–500 samples.
:class:`ScaledKernelWithNoise` computes the same numbers, each with the same IEEE operations in
the same order as scikit-learn's code, input by input into one preallocated array, so the
optimiser follows the same path and every fitted model is the same bit for bit
(``tests/studies/test_gp_kernel.py`` compares both with ``np.array_equal``). Anything else (a cross
kernel ``k(X, Y)``, no gradient, fixed hyperparameters, another composition) is scikit-learn's
own code.
"""

from __future__ import annotations

import functools
from typing import Any

import numpy as np
import numpy.typing as npt
from sklearn.gaussian_process.kernels import (
    RBF,
    ConstantKernel,
    Kernel,
    Matern,
    Product,
    Sum,
    WhiteKernel,
)

__all__ = ["ScaledKernelWithNoise", "scaled_kernel_with_noise"]

FloatArray = npt.NDArray[np.float64]


class ScaledKernelWithNoise(Sum):
    """``ConstantKernel * shape + WhiteKernel`` (``shape`` an anisotropic ``Matern`` with
    ν = 5/2 or an anisotropic ``RBF``), whose gradient on the training inputs is formed in place.

    The hyperparameters, their order, bounds and every other method are ``Sum``'s; only
    ``__call__(X, eval_gradient=True)`` takes the fused path, when the kernel has that form.
    """

    def __call__(
        self, X: npt.ArrayLike, Y: npt.ArrayLike | None = None, eval_gradient: bool = False
    ) -> Any:
        shape = self._fused_shape(X, Y, eval_gradient)
        if shape is None:
            return super().__call__(X, Y, eval_gradient=eval_gradient)
        x = np.asarray(X, dtype=np.float64)
        c = self.k1.k1.constant_value
        noise = self.k2.noise_level
        n, p = x.shape
        k_shape = shape(x)
        gradient = np.empty((n, n, p + 2))
        # Product: the constant's gradient (c everywhere) times the shape's K. Every product
        # with c is one IEEE product per element whether c is broadcast from an array or not.
        np.multiply(c, k_shape, out=gradient[:, :, 0])
        # Worked on input by input, (p, n, n): numpy's loops then run along rows of n, not along
        # the p = 6 inputs of one pair. The elements are the same IEEE operations as
        # scikit-learn's (n, n, p) arrays, written into `gradient` once at the end.
        d = np.empty((p, n, n))
        xt = np.ascontiguousarray(x.T)
        length_scale = np.asarray(shape.length_scale, dtype=np.float64)
        # The dimension-wise squared distances over the squared length scales, as both shapes
        # form them: (x_i − x_j)² / l².
        np.subtract(xt[:, :, np.newaxis], xt[:, np.newaxis, :], out=d)
        np.square(d, out=d)
        np.divide(d, (length_scale**2)[:, np.newaxis, np.newaxis], out=d)
        if isinstance(shape, Matern):
            # 5/3 · D · (t + 1) · exp(−t), t = √(5 Σ D), left to right.
            t = np.sqrt(5 * _sum_over_inputs(d))
            np.multiply(5.0 / 3.0, d, out=d)
            np.multiply(d, t + 1, out=d)
            np.multiply(d, np.exp(-t), out=d)
        else:
            np.multiply(d, k_shape, out=d)
        # Product: the shape's gradient times the constant's K (c everywhere).
        np.multiply(d, c, out=gradient[:, :, 1 : p + 1].transpose(2, 0, 1))
        # WhiteKernel: noise · I, and its gradient the same.
        eye = noise * np.eye(n)
        gradient[:, :, p + 1] = eye
        return c * k_shape + eye, gradient

    def _fused_shape(self, X: npt.ArrayLike, Y: Any, eval_gradient: bool) -> Kernel | None:
        """The shape kernel when the fused path computes this call, else None."""
        if Y is not None or not eval_gradient:
            return None
        product, white = self.k1, self.k2
        # Exactly these classes: a subclass could compute something else.
        if not (type(product) is Product and type(white) is WhiteKernel):
            return None
        constant, shape = product.k1, product.k2
        if type(constant) is not ConstantKernel:
            return None
        if type(shape) is Matern:
            if shape.nu != 2.5:
                return None
        elif type(shape) is not RBF:
            return None
        x = np.asarray(X)
        length_scale = np.asarray(shape.length_scale)
        # One length scale per input, at least two: scikit-learn's isotropic path differs.
        if x.ndim != 2 or x.dtype != np.float64 or x.shape[1] < 2:
            return None
        if not shape.anisotropic or length_scale.shape != (x.shape[1],):
            return None
        if any(h.fixed for h in self.hyperparameters):
            return None
        if not np.isscalar(constant.constant_value) or not np.isscalar(white.noise_level):
            return None
        return shape


def _sum_over_inputs(d: FloatArray) -> FloatArray:
    """Σ_k d[k] for d of shape (p, n, n), with the bits of numpy's ``sum(-1)`` over the (n, n, p)
    layout that scikit-learn sums. That sum adds a pair's few inputs in order; added here one
    input's (n, n) array at a time, it is several times faster. Whether this numpy adds them in
    order is checked once per p on random numbers; if not, its own sum is taken."""
    if not _sums_in_order(d.shape[0]):
        return np.asarray(np.ascontiguousarray(d.transpose(1, 2, 0)).sum(-1), dtype=np.float64)
    return _add_in_order(d)


def _add_in_order(d: FloatArray) -> FloatArray:
    """((d[0] + d[1]) + d[2]) + … along the first axis."""
    total = d[0].copy()
    for term in d[1:]:
        total += term
    return total


@functools.cache
def _sums_in_order(p: int) -> bool:
    """Whether numpy's ``sum(-1)`` over a last axis of length p adds its terms in order."""
    rng = np.random.default_rng(p)
    sample = rng.random((64, 64, p)) * np.exp(rng.normal(size=(64, 64, p)) * 8)
    return bool(np.array_equal(sample.sum(-1), _add_in_order(sample.transpose(2, 0, 1))))


def scaled_kernel_with_noise(
    shape: Kernel, *, constant: float, noise: float, noise_bounds: Any
) -> ScaledKernelWithNoise:
    """``ConstantKernel(constant) * shape + WhiteKernel(noise, noise_bounds)`` as a
    :class:`ScaledKernelWithNoise`."""
    return ScaledKernelWithNoise(ConstantKernel(constant) * shape, WhiteKernel(noise, noise_bounds))
