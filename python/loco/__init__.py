"""loco: railway vehicle dynamics toolkit (Rust core, Python front end).

The native module ``loco._loco`` is private; use the submodules of this package:
``loco.profiles``, ``loco.contact``, ``loco.track``, ``loco.metrics``, ``loco.dampers``.
"""

from loco._loco import (
    ContactError,
    DerailmentError,
    DivergenceError,
    InternalError,
    LocoError,
    LocoIOError,
    ParameterError,
    ProfileFormatError,
    SimulationError,
    __version__,
)

__all__ = [
    "ContactError",
    "DerailmentError",
    "DivergenceError",
    "InternalError",
    "LocoError",
    "LocoIOError",
    "ParameterError",
    "ProfileFormatError",
    "SimulationError",
    "__version__",
]
