"""Where a run is assessed: the zones of a designed alignment (each straight and each circular
curve) and how far each wheelset runs behind the leading one, so that each wheelset's channels
are read in the zone it is in (:func:`loco.assessment.assess`)."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd

from loco.vehicle import Locomotive

__all__ = ["Zone", "wheelset_offsets", "zones"]


@dataclass(frozen=True)
class Zone:
    """A stretch of track assessed on its own: ``name``, its start and end (m along the track,
    s = 0 where the leading wheelset starts the alignment) and radius (m; inf: straight)."""

    name: str
    start: float
    end: float
    radius: float

    @property
    def curved(self) -> bool:
        return math.isfinite(self.radius)


def wheelset_offsets(vehicle: Locomotive) -> list[float]:
    """How far each wheelset runs behind the leading one, m (0, 2·b, 2·a, 2·a + 2·b with a the
    half bogie distance and b the half wheelbase)."""
    a = vehicle["layout.bogie_half_distance"]
    b = vehicle["layout.half_wheelbase"]
    return [0.0, 2 * b, 2 * a, 2 * a + 2 * b]


def zones(curve: Sequence[Mapping[str, Any]] | str | Path | None, end: float) -> list[Zone]:
    """The zones of a designed alignment (its sections as ``loco.Scenario(curve=…)`` takes them,
    or a sections CSV): each straight and each circular curve, transitions left out. ``None``:
    one straight zone up to ``end`` (m)."""
    if curve is None:
        return [Zone("straight track", 0.0, end, math.inf)]
    rows: list[dict[str, Any]] = (
        [{str(k): v for k, v in r.items()} for r in pd.read_csv(curve).to_dict("records")]
        if isinstance(curve, (str, Path))
        else [dict(s) for s in curve]
    )
    out: list[Zone] = []
    start = 0.0
    for i, section in enumerate(rows):
        length = float(section["length_m"])
        kind = section["kind"]
        if kind == "straight":
            out.append(Zone(f"straight {i + 1}", start, start + length, math.inf))
        elif kind == "curve":
            radius = float(section["radius_m"])
            out.append(Zone(f"curve R = {radius:g} m", start, start + length, radius))
        start += length
    return out
