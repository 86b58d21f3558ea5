"""The vehicle's parameter schema: for every key of a vehicle file its SI unit, kind, physical
range, what it affects and a description (the core's one list,
``vehicle/params/parameter_schema.toml``).

A vehicle file must give exactly these keys (an optional one it may leave to the model); a
value outside its range is refused with :class:`loco.ParameterRangeError` unless the file lists
the key in ``allow_out_of_range``::

    allow_out_of_range = ["carbody.mass"]
    [carbody]
    mass = { value = 150000.0, unit = "kg", source = "research: a heavier body" }

Values may be stated in another unit of the same quantity (``unit = "kN·s/m"``); they are
converted to SI on reading. Keys that are no parameters any more (:func:`retired_parameters`) are
refused with the reason.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, cast

from loco import _loco

__all__ = ["ParameterSpec", "parameter_schema", "retired_parameters"]

Kind = Literal["real", "count"]
Affects = Literal["structure", "contact", "metrics"]


@dataclass(frozen=True)
class ParameterSpec:
    """One vehicle parameter of the schema.

    Attributes
    ----------
    key : str
        ``section.name``, as in the vehicle file and overrides.
    unit : str
        The SI unit the model reads the value in.
    kind : {"real", "count"}
        A count is a whole number of identical elements.
    min, max : float
        The physical range (inclusive), in ``unit``.
    affects : tuple of {"structure", "contact", "metrics"}
        What a change rebuilds: the vehicle's bodies and suspension, the wheel-rail contact, or
        where the metrics' channels are measured.
    description : str
        One line.
    why : str
        The reasoning behind the range.
    optional : bool
        A vehicle file may leave it out; the model then computes it (the description says how).
    """

    key: str
    unit: str
    kind: Kind
    min: float
    max: float
    affects: tuple[Affects, ...]
    description: str
    why: str
    optional: bool = False

    def contains(self, value: float) -> bool:
        """True when ``value`` (SI) is inside the physical range."""
        return self.min <= value <= self.max


def parameter_schema() -> dict[str, ParameterSpec]:
    """Every vehicle parameter of the schema, by key (sorted)."""
    return {
        row[0]: ParameterSpec(
            key=row[0],
            unit=row[1],
            kind=cast(Kind, row[2]),
            min=row[3],
            max=row[4],
            affects=tuple(cast(Affects, a) for a in row[5]),
            description=row[6],
            why=row[7],
            optional=row[8],
        )
        for row in _loco.parameter_schema()
    }


def retired_parameters() -> dict[str, str]:
    """Keys that are not vehicle parameters (any more), with the reason."""
    return dict(_loco.retired_parameters())
