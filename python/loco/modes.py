"""What moves in a mode: each body's share of the mode's kinetic energy, and its motions.

The 90 coordinates mix metres, radians and motions relative to a parent body (hollow shafts,
traction rods, rotary arms), so their squared amplitudes say little about which bodies move.
The model's own mass matrix does: it is ``M = Σ_b T_bᵀ D_b T_b`` with ``T_b`` the map from the
coordinates to body ``b``'s absolute motion (x, y, z in m; roll, pitch, yaw in rad, at its
centre of gravity) and ``D_b = diag(m, m, m, Ixx, Iyy, Izz)`` (principal axes along the
vehicle's). For a mode shape ``q`` the velocity amplitude is ``λq``, so the mean kinetic energy
of body ``b`` is proportional to ``Σ_k D_b[k]·|(T_b q)_k|²``: its share of the total, split
into the six motions, is independent of units and of how the coordinates are chosen.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from loco import _loco

__all__ = ["MOTIONS", "BodyMasses", "Mode", "body_masses", "energy_shares"]

#: The six motions of a body, in the order of its motion map.
MOTIONS = ("longitudinal", "lateral", "vertical", "roll", "pitch", "yaw")

#: Share (–) of a group's energy a motion needs to be named in :meth:`Mode.describe`.
_NAMED_MOTION = 0.2


@dataclass(frozen=True)
class BodyMasses:
    """Motion maps (n_bodies × 6 × 90) and mass diagonals (n_bodies × 6, kg and kg·m²)."""

    names: list[str]
    maps: npt.NDArray[np.float64]
    masses: npt.NDArray[np.float64]

    def mass_matrix(self) -> npt.NDArray[np.float64]:
        """The 90 × 90 mass matrix ``Σ Tᵀ D T`` (kg, kg·m, kg·m²)."""
        return np.einsum("bki,bk,bkj->ij", self.maps, self.masses, self.maps)


def body_masses(toml_text: str | None, origin: str, overrides: dict[str, float]) -> BodyMasses:
    """The bodies of a vehicle file with overrides (see :class:`loco.Locomotive`)."""
    names, maps, masses = _loco.body_mass_maps(toml_text, origin, overrides)
    return BodyMasses(names=list(names), maps=maps, masses=masses)


def group_of(body: str) -> str:
    """The kind of a body: ``wheelset3`` → ``wheelsets``, ``rotary_arm2_left`` → ``rotary_arms``."""
    kind = re.sub(r"\d+(_(left|right))?$", "", body)
    return kind if kind == "carbody" else kind + "s"


def energy_shares(
    shape: npt.NDArray[np.complex128], bodies: BodyMasses
) -> tuple[dict[str, float], dict[str, dict[str, float]]]:
    """Each body's share of the mode's kinetic energy (summing to 1) and, per body, the share of
    its energy in each of :data:`MOTIONS`, for the mode shape ``shape`` (first 90 entries: the
    coordinates)."""
    motion = bodies.maps @ shape[: bodies.maps.shape[2]]  # (bodies, 6), complex amplitudes
    energy = bodies.masses * np.abs(motion) ** 2
    per_body = energy.sum(axis=1)
    total = float(per_body.sum()) or 1.0
    shares = {n: float(e) / total for n, e in zip(bodies.names, per_body, strict=True)}
    motions = {
        n: {m: float(v) / (float(e) or 1.0) for m, v in zip(MOTIONS, row, strict=True)}
        for n, e, row in zip(bodies.names, per_body, energy, strict=True)
    }
    return shares, motions


@dataclass(frozen=True)
class Mode:
    """One oscillatory mode: frequency (Hz), damping ratio (–) and what moves.

    ``bodies``: each body's share (–) of the mode's kinetic energy; ``motions``: per body, the
    share (–) of its energy in each of :data:`MOTIONS`.
    """

    frequency: float
    damping_ratio: float
    eigenvalue: complex
    bodies: dict[str, float]
    motions: dict[str, dict[str, float]]

    def groups(self) -> dict[str, float]:
        """Energy shares (–) by kind of body (``carbody``, ``frames``, ``wheelsets``, …)."""
        out: dict[str, float] = {}
        for body, share in self.bodies.items():
            out[group_of(body)] = out.get(group_of(body), 0.0) + share
        return out

    def group_motions(self, group: str) -> dict[str, float]:
        """Share (–) of a kind of body's energy in each motion."""
        out = dict.fromkeys(MOTIONS, 0.0)
        total = 0.0
        for body, share in self.bodies.items():
            if group_of(body) == group:
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
