"""The locomotive: the embedded default vehicle (an SS8-like B0-B0), parameter files, overrides.

Every parameter has a name ``section.name`` (e.g. ``secondary.yaw_damper_damping``), a value in
SI units, a unit and a source. The six study parameters of SPEC §6 may also be given by their
names there: ``K_px``, ``K_py``, ``C_sx``, ``C_sy``, ``K_ncsx``, ``K_ncsy``.
"""

from __future__ import annotations

import hashlib
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco.field_types import real, wrong_type

__all__ = ["STUDY_PARAMETERS", "Locomotive", "Parameter", "body_names", "dof_names"]

#: The origin of the embedded default vehicle, as its errors name it.
DEFAULT_ORIGIN = "<default vehicle>"
#: The origin errors name for a vehicle given as ``toml_text`` without an ``origin``.
TEXT_ORIGIN = "<toml_text>"

#: The six study parameters (SPEC §6): alias -> parameter file key.
STUDY_PARAMETERS: dict[str, str] = dict(_loco.study_parameters())


@dataclass(frozen=True)
class Parameter:
    """One vehicle parameter: value (SI), unit and source."""

    name: str
    value: float
    unit: str
    source: str


@dataclass(frozen=True)
class Locomotive:
    """A vehicle: a parameter file (None: the embedded default) and overrides by name.

    Instances are immutable; :meth:`replace` returns a new one. The file is parsed and the
    vehicle built once, when the object is created (a non-physical value raises
    :class:`loco.ParameterError` naming it): :attr:`native`, the built vehicle every simulation,
    linearisation and batch of it uses. Pickled as the file text and the overrides.
    """

    toml_text: str | None = None
    origin: str = DEFAULT_ORIGIN
    overrides: Mapping[str, float] = field(default_factory=dict)
    #: The built vehicle (``loco._loco.Vehicle``), shared by every call that takes this one.
    native: _loco.Vehicle = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if self.toml_text is not None and self.origin == DEFAULT_ORIGIN:
            # Errors in given text name the text, not the embedded file it replaces.
            object.__setattr__(self, "origin", TEXT_ORIGIN)
        overrides = _checked(self.overrides)
        object.__setattr__(self, "overrides", overrides)
        object.__setattr__(self, "native", _loco.Vehicle(self.toml_text, self.origin, overrides))

    @classmethod
    def _wrap(cls, native: _loco.Vehicle) -> Locomotive:
        """A Locomotive around an already built vehicle (no parsing, no build)."""
        self = object.__new__(cls)
        object.__setattr__(self, "toml_text", native.toml_text)
        object.__setattr__(self, "origin", native.origin)
        object.__setattr__(self, "overrides", dict(native.overrides))
        object.__setattr__(self, "native", native)
        return self

    def __reduce__(self) -> tuple[type[Locomotive], tuple[str | None, str, dict[str, float]]]:
        return (Locomotive, (self.toml_text, self.origin, dict(self.overrides)))

    def __repr__(self) -> str:
        source = "default vehicle" if self.toml_text is None else repr(self.origin)
        overrides = f", overrides={dict(self.overrides)}" if self.overrides else ""
        return f"Locomotive({source}{overrides})"

    @classmethod
    def default(cls) -> Locomotive:
        """The embedded default vehicle."""
        return cls()

    @classmethod
    def from_toml(cls, path: str | Path) -> Locomotive:
        """A vehicle from a parameter file in the format of the embedded one."""
        text = _loco.read_text_file(str(Path(path)), "vehicle")
        return cls(toml_text=text, origin=str(path))

    def replace(self, overrides: Mapping[str, float] | None = None, /, **kw: float) -> Locomotive:
        """A copy with parameters overridden, by key (``{"secondary.yaw_damper_damping": 2e5}``)
        or as keywords for names without dots (study aliases: ``replace(C_sx=2e5)``). The file
        is not parsed again; the new vehicle is built once."""
        given = _checked({**(overrides or {}), **kw})
        return Locomotive._wrap(self.native.replace(given))

    def parameters(self) -> dict[str, Parameter]:
        """All parameters after overrides, by key."""
        return {k: Parameter(k, v, u, s) for k, v, u, s in self.native.parameters_table()}

    def parameters_sha256(self) -> str:
        """SHA-256 of the resolved parameters: every key with its SI value after overrides, in
        key order. It is what a run of this vehicle depends on, and nothing of how the file is
        written: comments, sources, the units values are stated in, the order of keys and the
        ``allow_out_of_range`` list leave it unchanged. Stage and campaign hashes use it, so an
        edit that changes no value reruns nothing."""
        lines = [f"{k}={v!r}\n" for k, v, _unit, _source in self.native.parameters_table()]
        return hashlib.sha256("".join(lines).encode("utf-8")).hexdigest()

    def __getitem__(self, name: str) -> float:
        """The value (SI) of a parameter by key or study alias, read from the built vehicle."""
        return self.native[name]

    def total_mass(self) -> float:
        """Mass of the 25 bodies, kg."""
        return self.native.total_mass()

    def en14363_bogie_mass(self) -> float:
        """The bogie mass m⁺ of the EN 14363 stability limit ``(12 − m⁺/5)/2`` m/s², kg.

        ``assessment.bogie_mass`` when the vehicle file or an override states it; otherwise the
        heavier bogie's frame, wheelsets, axle boxes, frame-hung motors and hollow shafts (see
        ``docs/assessment.md``).
        """
        return self.native.en14363_bogie_mass()

    def mass_matrix(self) -> npt.NDArray[np.float64]:
        """The 90 × 90 mass matrix (kg, kg·m, kg·m²) in coordinate order (:func:`dof_names`)."""
        return self.native.mass_matrix()

    def default_toml(self) -> str:
        """The embedded default parameter file (a template for one's own)."""
        return _loco.default_vehicle_toml()


def _checked(overrides: Mapping[str, float]) -> dict[str, float]:
    """Overrides as floats by key; a key that is not a string or a value that is not a real number
    (a bool, a string, a complex number, None) is a :class:`loco.ParameterError` naming the key,
    not a raw ``TypeError`` or a silent conversion (``True`` read as 1, ``"2e5"`` as 2e5)."""
    if not isinstance(overrides, Mapping):
        raise wrong_type("overrides", "a mapping of parameter keys to values", overrides)
    out: dict[str, float] = {}
    for key, value in overrides.items():
        if not isinstance(key, str):
            raise wrong_type("overrides", "parameter keys (str)", key)
        out[key] = real(key, value)
    return out


def dof_names() -> list[str]:
    """Names of the 90 coordinates, ``body.coordinate``, in state order."""
    return _loco.dof_names()


def body_names() -> list[str]:
    """Names of the 25 bodies."""
    return _loco.body_names()
