"""Sample designs over a box of :class:`~loco.studies.parameters.StudyParameter`: Latin hypercube
(Monte Carlo, surrogate training) and Saltelli's Sobol' design (direct Sobol estimation).

Every function returns an (n, k) array in SI, one column per parameter, and is deterministic for
a given ``seed``.
"""

from __future__ import annotations

import inspect
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt
from SALib.sample import sobol as _salib_sobol
from scipy.stats import qmc

from loco.studies.parameters import STUDY_PARAMETERS, StudyParameter, bounds_si, salib_problem

__all__ = [
    "latin_hypercube",
    "saltelli",
    "saltelli_block_size",
    "scale_unit",
]

FloatArray = npt.NDArray[np.float64]

# scipy renamed ``seed`` to ``rng`` in 1.15; pyproject allows scipy >= 1.10.
_LHS_SEED_KEYWORD = (
    "rng" if "rng" in inspect.signature(qmc.LatinHypercube.__init__).parameters else "seed"
)


def scale_unit(
    unit: npt.ArrayLike, parameters: Sequence[StudyParameter] = STUDY_PARAMETERS
) -> FloatArray:
    """Map points of the unit cube, shape (n, k), linearly onto the SI ranges."""
    bounds = bounds_si(parameters)
    u = np.asarray(unit, dtype=np.float64)
    return bounds[:, 0] + u * (bounds[:, 1] - bounds[:, 0])


def latin_hypercube(
    n: int,
    parameters: Sequence[StudyParameter] = STUDY_PARAMETERS,
    seed: int = 0,
    *,
    optimization: str | None = None,
) -> FloatArray:
    """``n`` Latin hypercube samples (McKay et al. 1979) over the SI ranges.

    Parameters
    ----------
    n : int
        Number of samples (the study uses 200).
    parameters : sequence of StudyParameter
        The box; one column per parameter, in order.
    seed : int
        Seed of :class:`scipy.stats.qmc.LatinHypercube` (scrambled: each point is uniform in its
        stratum).
    optimization : {None, "random-cd", "lloyd"}
        Passed to scipy: ``"random-cd"`` improves space filling (centred discrepancy) at some cost.

    Returns
    -------
    numpy.ndarray
        (n, k) samples in SI units.
    """
    if n < 1:
        raise ValueError(f"latin_hypercube: n must be >= 1, got {n}")
    kwargs: dict[str, object] = {_LHS_SEED_KEYWORD: seed, "optimization": optimization}
    engine = qmc.LatinHypercube(d=len(parameters), **kwargs)
    return scale_unit(engine.random(n), parameters)


def saltelli_block_size(n_params: int, calc_second_order: bool = False) -> int:
    """Rows per base sample in Saltelli's design: D + 2, or 2D + 2 with second order."""
    return 2 * n_params + 2 if calc_second_order else n_params + 2


def saltelli(
    n_base: int,
    parameters: Sequence[StudyParameter] = STUDY_PARAMETERS,
    seed: int = 0,
    *,
    calc_second_order: bool = False,
) -> FloatArray:
    """Saltelli's design (Saltelli 2002; Saltelli et al. 2010) by ``SALib.sample.sobol``.

    The design is ``n_base`` consecutive blocks of :func:`saltelli_block_size` rows: A, the D
    matrices A with column i from B, (with second order: the D matrices B with column i from A),
    and B, where A and B are the two halves of a scrambled Sobol' sequence of dimension 2D.
    Because the base points are a prefix of one Sobol' sequence, the first m blocks of a design
    of ``n_base`` are the design of ``m`` (same seed): :func:`loco.studies.sobol.
    sobol_convergence` relies on this.

    Parameters
    ----------
    n_base : int
        Number of base samples N; a power of 2 keeps the Sobol' sequence balanced.
    parameters : sequence of StudyParameter
        The box.
    seed : int
        Seed of the scrambling.
    calc_second_order : bool
        Add the rows that second-order indices need.

    Returns
    -------
    numpy.ndarray
        (n_base · block size, k) samples in SI units.
    """
    if n_base < 1:
        raise ValueError(f"saltelli: n_base must be >= 1, got {n_base}")
    if n_base & (n_base - 1):
        raise ValueError(f"saltelli: n_base must be a power of 2, got {n_base}")
    x = _salib_sobol.sample(
        salib_problem(parameters), n_base, calc_second_order=calc_second_order, seed=seed
    )
    return np.asarray(x, dtype=np.float64)
