"""The locomotive: the embedded default vehicle (an SS8-like B0-B0), parameter files, overrides.

Every parameter has a name ``section.name`` (e.g. ``secondary.yaw_damper_damping``), a value in
SI units, a unit and a source. The six study parameters of SPEC §6 may also be given by their
names there: ``K_px``, ``K_py``, ``C_sx``, ``C_sy``, ``K_ncsx``, ``K_ncsy``.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from loco import _loco

__all__ = ["STUDY_PARAMETERS", "Locomotive", "Parameter", "body_names", "dof_names"]

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

    Instances are immutable; :meth:`replace` returns a new one. The parameters are checked
    (the vehicle is built) when the object is created, so a non-physical value raises
    :class:`loco.ParameterError` naming it.
    """

    toml_text: str | None = None
    origin: str = "<default vehicle>"
    overrides: Mapping[str, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "overrides", {k: float(v) for k, v in self.overrides.items()})
        _loco.vehicle_parameters(self.toml_text, self.origin, dict(self.overrides))

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
        path = Path(path)
        try:
            text = path.read_text(encoding="utf-8")
        except OSError as e:
            raise _loco.LocoIOError(f"cannot access `{path}`: {e}") from e
        return cls(toml_text=text, origin=str(path))

    def replace(self, overrides: Mapping[str, float] | None = None, /, **kw: float) -> Locomotive:
        """A copy with parameters overridden, by key (``{"secondary.yaw_damper_damping": 2e5}``)
        or as keywords for names without dots (study aliases: ``replace(C_sx=2e5)``)."""
        merged = {**self.overrides, **(overrides or {}), **kw}
        return Locomotive(self.toml_text, self.origin, merged)

    def parameters(self) -> dict[str, Parameter]:
        """All parameters after overrides, by key."""
        rows = _loco.vehicle_parameters(self.toml_text, self.origin, dict(self.overrides))
        return {k: Parameter(k, v, u, s) for k, v, u, s in rows}

    def __getitem__(self, name: str) -> float:
        key = STUDY_PARAMETERS.get(name, name)
        params = self.parameters()
        if key not in params:
            raise _loco.ParameterError(f"invalid parameter `{name}`: unknown vehicle parameter")
        return params[key].value

    def total_mass(self) -> float:
        """Mass of the 25 bodies, kg."""
        return _loco.vehicle_total_mass(self.toml_text, self.origin, dict(self.overrides))

    def default_toml(self) -> str:
        """The embedded default parameter file (a template for one's own)."""
        return _loco.default_vehicle_toml()


def dof_names() -> list[str]:
    """Names of the 90 coordinates, ``body.coordinate``, in state order."""
    return _loco.dof_names()


def body_names() -> list[str]:
    """Names of the 25 bodies."""
    return _loco.body_names()
