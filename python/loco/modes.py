"""What moves in a mode: each body's share of the mode's kinetic energy, and its motions.

The shares come from the core (``loco_core::vehicle::analysis::modes``, through
``loco._loco.mode_energies``): for a mode shape ``q`` the mean kinetic energy of body ``b`` is
proportional to ``Σ_k D_b[k]·|(T_b q)_k|²``, with ``T_b`` the map from the coordinates to the
body's absolute motion (x, y, z; roll, pitch, yaw at its centre of gravity) and
``D_b = diag(m, m, m, Ixx, Iyy, Izz)``, the terms of the model's mass matrix
``M = Σ_b T_bᵀ D_b T_b``. Shares are independent of units and of how the coordinates are
chosen. This module groups them by kind of body and words them, and states the core's rules
that pick a mode by them (:func:`mode_rules`, used by ``loco.Eigen.carbody_mode`` and
``bogie_mode``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from loco import _loco

__all__ = [
    "MOTIONS",
    "Mode",
    "ModeEnergies",
    "ModeRule",
    "describe_rule",
    "mode_energies",
    "mode_rules",
]

#: The six motions of a body, in the order of the core's motion maps.
MOTIONS = tuple(_loco.body_motion_names())

#: Share (–) of a group's energy a motion needs to be named in :meth:`Mode.describe`.
_NAMED_MOTION = 0.2


@dataclass(frozen=True)
class ModeEnergies:
    """Kinetic-energy shares of several modes: body names and kinds (``wheelsets``, …), each
    body's share of each mode's energy (n_modes × n_bodies) and the share of each body's energy
    in each of :data:`MOTIONS` (n_modes × n_bodies × 6)."""

    names: list[str]
    kinds: list[str]
    shares: npt.NDArray[np.float64]
    motions: npt.NDArray[np.float64]

    def bodies(self, k: int) -> dict[str, float]:
        """Each body's share (–) of mode ``k``'s kinetic energy."""
        return dict(zip(self.names, self.shares[k].tolist(), strict=True))

    def body_motions(self, k: int) -> dict[str, dict[str, float]]:
        """Per body, the share (–) of its energy in mode ``k`` in each of :data:`MOTIONS`."""
        return {
            n: dict(zip(MOTIONS, row, strict=True))
            for n, row in zip(self.names, self.motions[k].tolist(), strict=True)
        }


def mode_energies(shapes: npt.NDArray[np.complex128], vehicle: _loco.Vehicle) -> ModeEnergies:
    """Energy shares of the mode shapes ``shapes`` (n_modes × n, first 90 columns: the
    coordinates) of a built vehicle (``Locomotive.native``), computed by the core."""
    shapes = np.atleast_2d(shapes)
    names, kinds, shares, motions = _loco.mode_energies(
        vehicle,
        np.ascontiguousarray(shapes.real, dtype=np.float64),
        np.ascontiguousarray(shapes.imag, dtype=np.float64),
    )
    return ModeEnergies(names=list(names), kinds=list(kinds), shares=shares, motions=motions)


@dataclass(frozen=True)
class Mode:
    """One oscillatory mode: frequency (Hz), damping ratio (–) and what moves.

    ``bodies``: each body's share (–) of the mode's kinetic energy; ``motions``: per body, the
    share (–) of its energy in each of :data:`MOTIONS`; ``kinds``: each body's kind
    (``carbody``, ``frames``, ``wheelsets``, …).
    """

    frequency: float
    damping_ratio: float
    eigenvalue: complex
    bodies: dict[str, float]
    motions: dict[str, dict[str, float]]
    kinds: dict[str, str]

    def __repr__(self) -> str:
        groups = self.groups()
        top = max(groups, key=groups.__getitem__) if groups else "?"
        share = f", {top} {100 * groups[top]:.0f} %" if groups else ""
        return f"Mode({self.frequency:.3f} Hz, ζ={self.damping_ratio:.4f}{share})"

    def groups(self) -> dict[str, float]:
        """Energy shares (–) by kind of body (``carbody``, ``frames``, ``wheelsets``, …)."""
        out: dict[str, float] = {}
        for body, share in self.bodies.items():
            out[self.kinds[body]] = out.get(self.kinds[body], 0.0) + share
        return out

    def group_motions(self, group: str) -> dict[str, float]:
        """Share (–) of a kind of body's energy in each motion."""
        out = dict.fromkeys(MOTIONS, 0.0)
        total = 0.0
        for body, share in self.bodies.items():
            if self.kinds[body] == group:
                total += share
                for m, v in self.motions[body].items():
                    out[m] += share * v
        return {m: v / (total or 1.0) for m, v in out.items()}

    def motion_shares(self) -> dict[str, float]:
        """Share (–) of the whole mode's kinetic energy in each motion, all bodies together."""
        out = dict.fromkeys(MOTIONS, 0.0)
        for body, share in self.bodies.items():
            for m, v in self.motions[body].items():
                out[m] += share * v
        return out

    def describe(self, top: int = 3) -> str:
        """``"1.23 Hz, ζ = 4.50 %: carbody 80 % (lateral 55 %, roll 40 %), frames 12 % (…)"``:
        the ``top`` kinds of body by energy share, each with its motions of at least 20 % (or
        its largest)."""
        parts = []
        for group, share in sorted(self.groups().items(), key=lambda kv: -kv[1])[:top]:
            motions = sorted(self.group_motions(group).items(), key=lambda kv: -kv[1])
            kept = [mv for mv in motions if mv[1] >= _NAMED_MOTION] or motions[:1]
            named = [f"{m} {100 * v:.0f} %" for m, v in kept]
            parts.append(f"{group} {100 * share:.0f} % ({', '.join(named)})")
        shares = ", ".join(parts)
        return f"{self.frequency:.3f} Hz, ζ = {100 * self.damping_ratio:.2f} %: {shares}"


@dataclass(frozen=True)
class ModeRule:
    """A rule of the core that picks one mode: frequency band (Hz), the least and largest share
    of the energy in the carbody, the least shares in the wheelsets, the frames and in lateral,
    roll and yaw motion (all –)."""

    name: str
    band: tuple[float, float]
    carbody_share: tuple[float, float]
    min_wheelset_share: float
    min_frame_share: float
    min_lateral_share: float


def mode_rules() -> dict[str, ModeRule]:
    """The core's mode rules by name (``carbody``, ``bogie``)."""
    return {r[0]: ModeRule(*r) for r in _loco.mode_rules()}


def describe_rule(name: str) -> str:
    """A rule in words: ``"0.3–3 Hz, carbody 30–100 %, wheelsets ≥ 2 %, …"``."""
    r = mode_rules()[name]
    pct = _percent
    return (
        f"{r.band[0]:g}–{r.band[1]:g} Hz, carbody {pct(r.carbody_share[0])}–"
        f"{pct(r.carbody_share[1])} %, wheelsets ≥ {pct(r.min_wheelset_share)} %, frames ≥ "
        f"{pct(r.min_frame_share)} %, lateral/roll/yaw ≥ {pct(r.min_lateral_share)} %"
    )


def _percent(share: float) -> str:
    """A share (–) as a number of percent."""
    return f"{100 * share:g}"
