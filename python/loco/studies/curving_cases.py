"""The curves of the curving study and its sizes: each case's designed curve (straight, clothoid
transition with a linear cant run-off, circular curve with cant), the speed for a cant
deficiency, and the sizes of the ``curving`` stage per preset. Why these curves: the module
documentation of :mod:`loco.studies.curving`.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import loco
from loco.studies import fsd_comparison

__all__ = [
    "CANT_DEFICIENCIES_MM",
    "CURVES",
    "FULL_SIZES",
    "LEAD_IN",
    "MAX_SPEED_KMH",
    "RUN_IN",
    "TINY_SIZES",
    "CurveCase",
    "CurvingSizes",
    "speed_for_deficiency",
]


@dataclass(frozen=True)
class CurveCase:
    """A designed curve: radius (m), cant (mm), clothoid transition length (m), length of the
    circular curve (m, the assessed section) and its direction."""

    radius_m: float
    cant_mm: float
    transition_m: float
    curve_m: float = 200.0
    direction: str = "left"

    def sections(self, straight_m: float, run_m: float = 0.0) -> list[dict[str, float | str]]:
        """The design: ``straight_m`` of straight, the transition, the circular curve, which
        runs on beyond its assessed ``curve_m`` to cover a run whose leading wheelset travels
        ``run_m`` m (a run may not go beyond a design that ends in a curve)."""
        curve_m = max(self.curve_m, run_m - straight_m - self.transition_m)
        return [
            {"kind": "straight", "length_m": straight_m},
            {"kind": "transition", "length_m": self.transition_m},
            {
                "kind": "curve",
                "length_m": curve_m,
                "radius_m": self.radius_m,
                "cant_mm": self.cant_mm,
                "direction": self.direction,
            },
        ]


def _case(radius: float, cant: float) -> CurveCase:
    return CurveCase(radius_m=radius, cant_mm=cant, transition_m=max(60.0, cant * 1.0))


#: The study's curves (module docstring).
CURVES: tuple[CurveCase, ...] = (
    _case(600.0, 150.0),
    _case(1200.0, 120.0),
    _case(3000.0, 60.0),
    _case(7000.0, 30.0),
)
#: Cant deficiencies, mm.
CANT_DEFICIENCIES_MM: tuple[float, ...] = (0.0, 50.0, 100.0, 150.0)
#: Highest speed run, km/h (the top of the study's speed sweep, SPEC §6).
MAX_SPEED_KMH = 300.0
#: Straight run before the record, m: the damper comparison's, so that the FSD has left its start
#: state (valve closed) as it has there (:data:`loco.studies.fsd_comparison.LEAD_IN`).
LEAD_IN: float = fsd_comparison.LEAD_IN
#: Straight before the transition beyond the lead-in, m (the static equilibrium is found on it).
RUN_IN = 20.0


@dataclass(frozen=True)
class CurvingSizes:
    """How big the curving stage of ``loco reproduce`` is: the radii (m, of :data:`CURVES`), the
    cant deficiencies (mm), the lead-in (m) and the assessed circular curve's length (m)."""

    radii_m: tuple[float, ...]
    deficiencies_mm: tuple[float, ...]
    lead_in: float
    curve_m: float

    def curves(self) -> list[CurveCase]:
        """The study's curves of these radii, with this circular length."""
        return [
            dataclasses.replace(c, curve_m=self.curve_m)
            for c in CURVES
            if c.radius_m in self.radii_m
        ]


#: The whole study (``loco reproduce --full``): 4 curves × 4 deficiencies × 3 dampers, 45 runs
#: of 0.8–0.9 km (one deficiency on the 7000 m curve is above :data:`MAX_SPEED_KMH`).
FULL_SIZES = CurvingSizes(
    radii_m=tuple(c.radius_m for c in CURVES),
    deficiencies_mm=CANT_DEFICIENCIES_MM,
    lead_in=LEAD_IN,
    curve_m=200.0,
)
#: For tests: one curve, two deficiencies, no lead-in, a short circular curve (6 runs of 0.13 km).
TINY_SIZES = CurvingSizes(
    radii_m=(1200.0,), deficiencies_mm=(0.0, 100.0), lead_in=0.0, curve_m=40.0
)


def speed_for_deficiency(
    radius: float, cant_mm: float, deficiency_mm: float, vehicle: loco.Locomotive
) -> float:
    """Speed (m/s) giving cant deficiency ``deficiency_mm`` on a curve of ``radius`` (m) and
    ``cant_mm``: V = √(g·R·(c + d)/(2·b0))."""
    g = vehicle["track.gravity"]
    two_b0 = 2.0 * vehicle["track.contact_point_half_distance"]
    return math.sqrt(g * radius * (cant_mm + deficiency_mm) * 1e-3 / two_b0)
