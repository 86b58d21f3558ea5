"""The study's wheel/rail pairs and the low-conicity pairs of its field problem, with their
contact parameters.

The study's three scenarios put the JM3 wheel states on CN60 inclined 1:40 (SPEC §2). The field
problem it names - carbody hunting with newly reprofiled wheels on rail ground at the gauge corner
and with a larger rail cant - adds the new and thin-flange JM3 on CN60 ground at the gauge corner
(the built-in ``cn60-gauge-ground``) and on rails inclined 1:20. :data:`PAIRS` lists them once;
:func:`pair_rows` gives per pair the EN 15302 equivalent conicity at 3 mm and the linear contact
parameters of :func:`loco.contact.linear_parameters` (λ, ε, σ, the gravitational stiffness under
the study locomotive's mean axle load). ``scripts/docs/contact_pairs_docs.py`` writes them to
``docs/contact_pairs.md``, ``loco contact-report`` to its ``contact_pairs.csv``/``.md``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from loco import conicity, contact, profiles
from loco._loco import LocoError

__all__ = ["AMPLITUDE", "PAIRS", "ContactPair", "markdown_table", "pair_rows"]

#: Wheelset amplitude of the equivalent conicity in the table, m (EN 15302's 3 mm).
AMPLITUDE = 0.003


@dataclass(frozen=True)
class ContactPair:
    """A wheel on a rail at a rail inclination ``1:cant`` (the built-in profiles' names)."""

    wheel: str
    rail: str
    cant: int

    @property
    def inclination(self) -> float:
        """The rail inclination, rad."""
        return math.atan(1.0 / self.cant)

    @property
    def label(self) -> str:
        """``"<wheel> on <rail> 1:<cant>"``."""
        return f"{self.wheel} on {self.rail} 1:{self.cant}"


#: The study's three pairs, then the low-conicity pairs of its field problem.
PAIRS: tuple[ContactPair, ...] = (
    ContactPair("jm3-thin-flange", "cn60", 40),
    ContactPair("jm3-new", "cn60", 40),
    ContactPair("jm3-worn", "cn60", 40),
    ContactPair("jm3-new", "cn60-gauge-ground", 40),
    ContactPair("jm3-thin-flange", "cn60-gauge-ground", 40),
    ContactPair("jm3-new", "cn60", 20),
    ContactPair("jm3-thin-flange", "cn60", 20),
    ContactPair("jm3-new", "cn60-gauge-ground", 20),
    ContactPair("jm3-thin-flange", "cn60-gauge-ground", 20),
)


def pair_rows(pairs: tuple[ContactPair, ...] = PAIRS) -> list[dict[str, Any]]:
    """Per pair: ``wheel``, ``rail``, ``cant`` (the 1:n), ``tan_gamma_e_3mm`` (EN 15302 at
    :data:`AMPLITUDE`; NaN with the reason in ``note`` when the standard's method has no value),
    ``contact_angle_rad`` δ0, ``lambda``, ``epsilon``, ``sigma`` (–),
    ``gravitational_stiffness_per_load`` (1/m) and ``gravitational_stiffness_kn_per_m`` under
    ``axle_load_n`` (the default locomotive's mean axle load, N)."""
    load = contact.axle_load()
    rows: list[dict[str, Any]] = []
    for pair in pairs:
        wheel, rail = profiles.builtin(pair.wheel), profiles.builtin(pair.rail)
        note = ""
        try:
            tan_ge = conicity.equivalent_conicity(
                pair.wheel, pair.rail, AMPLITUDE, rail_inclination=pair.inclination
            )
        except LocoError as err:
            tan_ge, note = math.nan, f"no EN 15302 value: {err}"
        p = contact.linear_parameters(
            wheel, rail, rail_inclination=pair.inclination, axle_load=load
        )
        rows.append(
            {
                "wheel": pair.wheel,
                "rail": pair.rail,
                "cant": pair.cant,
                "tan_gamma_e_3mm": tan_ge,
                "contact_angle_rad": p.contact_angle,
                "lambda": p.conicity,
                "epsilon": p.contact_angle_parameter,
                "sigma": p.roll_parameter,
                "gravitational_stiffness_per_load": p.gravitational_stiffness_per_load,
                "gravitational_stiffness_kn_per_m": p.gravitational_stiffness / 1e3,
                "axle_load_n": load,
                "note": note,
            }
        )
    return rows


def markdown_table(rows: list[dict[str, Any]]) -> list[str]:
    """The rows as a Markdown table (numbers rounded for reading)."""
    lines = [
        "| wheel | rail | cant | tan γe (3 mm) | δ0 [rad] | λ | ε | σ | K_g/W [1/m] | K_g [kN/m] |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        tan_ge = "n/a" if math.isnan(r["tan_gamma_e_3mm"]) else f"{r['tan_gamma_e_3mm']:.4f}"
        lines.append(
            f"| {r['wheel']} | {r['rail']} | 1:{r['cant']} | {tan_ge} "
            f"| {r['contact_angle_rad']:.4f} | {r['lambda']:.4f} | {r['epsilon']:.3f} "
            f"| {r['sigma']:.4f} | {r['gravitational_stiffness_per_load']:.3f} "
            f"| {r['gravitational_stiffness_kn_per_m']:.0f} |"
        )
    return lines
