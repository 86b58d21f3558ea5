"""Linear second-order systems M q̈ + C q̇ + K q = 0 as first-order state-space models, their
eigenvalues, the linear critical speed and the kinematic wavelength of a mode.

The state is x = [q, q̇]; A = [[0, I], [−M⁻¹K, −M⁻¹C]], so ẋ = A x. An eigenvalue s = σ + iω
(σ in 1/s, ω in rad/s) of a vehicle running at speed V (m/s) oscillates with the wavelength
2πV/ω (m). The linear critical speed is the lowest speed at which the largest real part of the
eigenvalues crosses zero; it is found here by a scan on a grid and a bisection inside the first
bracket (the largest real part is continuous in V, so a sign change brackets a crossing).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable

import numpy as np

#: A model at speed V (m/s): its mass, damping and stiffness matrices (SI).
Matrices = Callable[[float], tuple[np.ndarray, np.ndarray, np.ndarray]]


def state_matrix(m: np.ndarray, c: np.ndarray, k: np.ndarray) -> np.ndarray:
    """The first-order matrix A of M q̈ + C q̇ + K q = 0 (state [q, q̇])."""
    n = m.shape[0]
    minv = np.linalg.inv(m)
    return np.block([[np.zeros((n, n)), np.eye(n)], [-minv @ k, -minv @ c]])


def eigen(matrices: Matrices, speed: float) -> tuple[np.ndarray, np.ndarray]:
    """Eigenvalues (1/s) and eigenvectors (columns, state [q, q̇]) of the model at ``speed``."""
    return np.linalg.eig(state_matrix(*matrices(speed)))


def largest_real_part(matrices: Matrices, speed: float) -> float:
    """The largest real part (1/s) of the eigenvalues at ``speed`` (m/s)."""
    return float(np.max(eigen(matrices, speed)[0].real))


def critical_speed(
    matrices: Matrices,
    v_min: float = 1.0,
    v_max: float = 150.0,
    steps: int = 150,
    rel_tol: float = 1e-10,
) -> float:
    """The lowest speed (m/s) in [v_min, v_max] at which the largest real part crosses zero
    from below, by a scan of ``steps`` intervals and a bisection to ``rel_tol``; ``inf`` when the
    model is stable over the whole range. Refused when it is unstable already at ``v_min``."""
    speeds = np.linspace(v_min, v_max, steps + 1)
    previous = largest_real_part(matrices, speeds[0])
    if previous >= 0.0:
        raise ValueError(f"unstable at the lowest speed {v_min} m/s (largest real part {previous})")
    for lo, hi in itertools.pairwise(speeds):
        current = largest_real_part(matrices, hi)
        if current >= 0.0:
            while hi - lo > rel_tol * hi:
                mid = 0.5 * (lo + hi)
                if largest_real_part(matrices, mid) < 0.0:
                    lo = mid
                else:
                    hi = mid
            return 0.5 * (lo + hi)
    return float("inf")


def energy_shares(m: np.ndarray, vector: np.ndarray) -> np.ndarray:
    """Each coordinate's share (–) of a mode's kinetic energy, ½ q̇ᵀ M q̇ with M diagonal,
    from an eigenvector of the state [q, q̇]."""
    n = m.shape[0]
    energy = np.diag(m) * np.abs(vector[n:]) ** 2
    return energy / energy.sum()


def oscillatory_modes(
    matrices: Matrices, speed: float, dofs: list[int] | None = None, min_share: float = 0.0
) -> list[complex]:
    """Eigenvalues with ω > 0 (and ω > 1e-3 |σ|: not a real pair split by round-off), sorted
    by frequency; with ``dofs``, only those with at least ``min_share`` of their kinetic energy
    in these coordinates."""
    m = matrices(speed)[0]
    values, vectors = eigen(matrices, speed)
    chosen = []
    for s, vec in zip(values, vectors.T, strict=True):
        if s.imag <= max(1e-6, 1e-3 * abs(s.real)):
            continue
        if dofs is None or energy_shares(m, vec)[dofs].sum() >= min_share:
            chosen.append(complex(s))
    return sorted(chosen, key=lambda s: s.imag)


def kinematic_mode(matrices: Matrices, speed: float) -> complex:
    """The kinematic mode at a low ``speed``: the slowest oscillation, whose frequency grows
    in proportion to the speed (the suspension's modes keep theirs and the creep modes are
    overdamped). Refused when the slowest oscillation at twice the speed is not about twice as
    fast (then ``speed`` is not low enough for the kinematic mode to be the slowest)."""
    slow = oscillatory_modes(matrices, speed)[0]
    fast = oscillatory_modes(matrices, 2 * speed)[0]
    if abs(fast.imag / slow.imag - 2.0) > 0.05:
        raise ValueError(f"no kinematic mode at {speed} m/s: {slow} and {fast} at twice the speed")
    return slow


def wavelength(eigenvalue: complex, speed: float) -> float:
    """The wavelength (m) travelled per cycle of a mode at ``speed`` (m/s): 2πV/ω."""
    return 2.0 * np.pi * speed / eigenvalue.imag
